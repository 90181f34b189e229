/* Compile check: the translation unit that defines APPEAR_IMPLEMENTATION. */
#define APPEAR_IMPLEMENTATION
#include "../../appear.h"
#include "../../appear.h" /* a second include must be harmless */
int appear_tu2_answer(void);
int main(void) { return appear_tu2_answer() == APPEAR_VERSION ? 0 : 1; }

#ifdef __CUDACC__
/* Device instantiation: nvcc checks a __host__ __device__ function's body for
   device use only when device code calls it, so this kernel calls the API. */
__global__ void appear_device_check(float *out, appear_vec3 wo, appear_vec3 wi, float u)
{
    appear_bsdf_sample bs;
    appear_phase_sample ps;
    appear_lambert lam = appear_lambert_make(appear_spectrum_splat(0.5f));
    appear_frame f = appear_frame_from_normal_tangent(wo, wi);
    float s, c, acc = 0.0f;
    appear_sincos_2pi(u, &s, &c);
    acc += s + c + appear__erfinv(u) + appear__exp(u) + appear__log(u) + appear__erf(u) + appear__atan2(u, s) + appear__pow(u, c);
    acc += appear_lambert_eval(&lam, wo, wi).v[0] + appear_lambert_pdf(&lam, wo, wi);
    acc += (float)appear_lambert_sample(&lam, wo, u, u, u, &bs) + bs.pdf;
    acc += appear_isotropic_eval(wo, wi) + appear_isotropic_pdf(wo, wi) + (float)appear_isotropic_sample(wo, u, u, &ps);
    acc += appear_hg_eval(u, wo, wi) + appear_hg_pdf(u, wo, wi) + (float)appear_hg_sample(u, wo, u, u, &ps) + ps.pdf;
    acc += appear_frame_to_world(f, appear_frame_to_local(f, wi)).x;
    {
        appear_ward wd = appear_ward_make(appear_spectrum_splat(0.2f), appear_spectrum_splat(0.5f), 0.1f, 0.2f, APPEAR_WARD_BALANCED);
        acc += appear_ward_eval(&wd, wo, wi).v[0] + appear_ward_pdf(&wd, wo, wi) + (float)appear_ward_sample(&wd, wo, u, u, u, &bs)
             + appear_ward_specular_pdf_h(0.1f, 0.2f, wi) + appear_ward_specular_sample_h(0.1f, 0.2f, u, u).z;
    }
    {
        appear_medium_sample ms;
        appear_majorant_segment seg = appear_majorant_constant(2.0f);
        appear_tracker tr;
        float t;
        appear_spectrum st = appear_spectrum_splat(u);
        acc += appear_homogeneous_transmittance(st, 2.0f).v[0] + appear_homogeneous_pdf(st, 2.0f, 1.0f, 1);
        acc += (float)appear_homogeneous_sample(st, 2.0f, u, u, &ms) + ms.t;
        appear_tracker_init(&tr, APPEAR_TRACK_URM, 3.0f, &seg, 1, 0);
        while (appear_tracker_next(&tr, u, u, &t)) appear_tracker_feed(&tr, 1.0f);
        acc += tr.T;
    }
    out[0] = acc;
}
#endif
