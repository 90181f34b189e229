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
    out[0] = acc;
}
#endif
