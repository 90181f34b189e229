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
    appear_bsdf_record bs;
    appear_phase_record ps;
    appear_lambert lam = appear_lambert_make(appear_spectrum_splat(0.5f));
    appear_frame f = appear_frame_from_normal_tangent(wo, wi);
    float s, c, acc = 0.0f;
    appear_sincos_2pi(u, &s, &c);
    acc += s + c + appear__erfinv(u) + appear__exp(u) + appear__log(u) + appear__erf(u) + appear__atan2(u, s) + appear__pow(u, c);
    acc += appear_lambert_eval(&lam, wo, wi).v[0] + appear_lambert_pdf(&lam, wo, wi);
    acc += (float)appear_lambert_sample(&lam, wo, u, u, u, &bs) + bs.pdf;
    acc += appear_isotropic_eval(wo, wi) + appear_isotropic_pdf(wo, wi) + (float)appear_isotropic_sample(wo, u, u, &ps);
    acc += appear_hg_eval_g(u, wo, wi) + appear_hg_pdf_g(u, wo, wi) + (float)appear_hg_sample_g(u, wo, u, u, &ps) + ps.pdf;
    acc += appear_frame_to_world(f, appear_frame_to_local(f, wi)).x;
    {
        appear_ward wd = appear_ward_make(appear_spectrum_splat(0.2f), appear_spectrum_splat(0.5f), 0.1f, 0.2f, APPEAR_WARD_BALANCED);
        acc += appear_ward_eval(&wd, wo, wi).v[0] + appear_ward_pdf(&wd, wo, wi) + (float)appear_ward_sample(&wd, wo, u, u, u, &bs)
             + appear_ward_specular_pdf_h(0.1f, 0.2f, wi) + appear_ward_specular_sample_h(0.1f, 0.2f, u, u).z;
    }
    {
        appear_medium_sample ms;
        appear_majorant_segment seg = appear_majorant_make_constant(2.0f);
        appear_tracker tr;
        float t;
        appear_spectrum st = appear_spectrum_splat(u);
        acc += appear_homogeneous_transmittance(st, 2.0f).v[0] + appear_homogeneous_pdf(st, 2.0f, 1.0f, 1);
        acc += (float)appear_homogeneous_sample(st, 2.0f, u, u, &ms) + ms.t;
        appear_tracker_init(&tr, APPEAR_TRACK_URM, 3.0f, &seg, 1, 0);
        while (appear_tracker_next(&tr, u, u, &t)) appear_tracker_feed(&tr, 1.0f);
        acc += tr.T;
    }
    {
        appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.1f, APPEAR_SAMPLE_VISIBLE);
        appear_microfacet b = appear_microfacet_make(APPEAR_BECKMANN, 0.2f, 0.2f, APPEAR_SAMPLE_VISIBLE);
        appear_conductor c = appear_conductor_make(d, appear_spectrum_splat(0.2f), appear_spectrum_splat(3.0f));
        appear_conductor c2 = appear_conductor_make_f82(b, appear_spectrum_splat(0.9f), appear_spectrum_splat(0.8f));
        appear_dielectric g = appear_dielectric_make(d, 1.5f);
        appear_thin_dielectric th = appear_thin_dielectric_make(1.5f);
        acc += appear_ggx_D(0.3f, 0.1f, wi) + appear_ggx_lambda(0.3f, 0.1f, wo) + appear_ggx_G1(0.3f, 0.1f, wo, wi) + appear_ggx_G2(0.3f, 0.1f, wo, wi, wi);
        acc += appear_beckmann_D(0.3f, 0.1f, wi) + appear_beckmann_lambda(0.3f, 0.1f, wo) + appear_beckmann_lambda_fast(0.3f, 0.1f, wo)
             + appear_beckmann_G1(0.3f, 0.1f, wo, wi) + appear_beckmann_G2(0.3f, 0.1f, wo, wi, wi);
        acc += appear_ggx_sample_visible(0.3f, 0.1f, wo, u, u).z + appear_ggx_pdf_visible(0.3f, 0.1f, wo, wi)
             + appear_ggx_sample_bounded_normal(0.3f, 0.1f, wo, u, u).z + appear_ggx_pdf_bounded_reflect(0.3f, 0.1f, wo, wi)
             + appear_beckmann_sample_visible(0.3f, 0.1f, wo, u, u).z + appear_beckmann_pdf_visible(0.3f, 0.1f, wo, wi)
             + appear_ggx_sample_D(0.3f, 0.1f, u, u).z + appear_ggx_pdf_D(0.3f, 0.1f, wi)
             + appear_beckmann_sample_D(0.3f, 0.1f, u, u).z + appear_beckmann_pdf_D(0.3f, 0.1f, wi);
        acc += appear_fresnel_dielectric(u, 1.5f) + appear_fresnel_dielectric_spectrum(u, appear_spectrum_splat(1.5f)).v[0]
             + appear_fresnel_conductor(u, 0.2f, 3.0f) + appear_fresnel_conductor_spectrum(u, appear_spectrum_splat(0.2f), appear_spectrum_splat(3.0f)).v[0]
             + appear_fresnel_schlick(u, 0.04f) + appear_fresnel_schlick_spectrum(u, appear_spectrum_splat(0.04f)).v[0]
             + appear_fresnel_f82(u, 0.9f, appear_fresnel_f82_coef(0.9f, 0.8f)) + appear_fresnel_f82_spectrum(u, appear_spectrum_splat(0.9f), appear_spectrum_splat(0.8f)).v[0];
        acc += appear_conductor_eval(&c, wo, wi).v[0] + appear_conductor_pdf(&c2, wo, wi) + (float)appear_conductor_sample(&c, wo, u, u, u, &bs);
        acc += appear_dielectric_eval(&g, wo, wi).v[0] + appear_dielectric_pdf(&g, wo, wi) + (float)appear_dielectric_sample(&g, wo, u, u, u, &bs);
        acc += appear_thin_dielectric_eval(&th, wo, wi).v[0] + appear_thin_dielectric_pdf(&th, wo, wi) + (float)appear_thin_dielectric_sample(&th, wo, u, u, u, &bs);
    }
    {
        appear_sggx sg = appear_sggx_make(1.0f, 0.35f, 0.32f, 0.52f, 0.44f, 0.2f);
        appear_sggx sf = appear_sggx_make_fiber(wo, 0.3f), ss = appear_sggx_make_surface(wo, 0.2f);
        appear_sggx se = appear_sggx_make_eigen(f.x, f.y, f.z, 1.0f, 0.5f, 0.1f);
        appear_fiber fb = appear_fiber_make(wo, 8.0f);
        appear_dhg dh = appear_dhg_make(0.8f, -0.3f, 0.7f);
        appear_draine dr = appear_draine_make(0.5f, 1.0f);
        appear_mie mi = appear_mie_make(10.0f);
        appear_phase_table pt;
        float vals[3] = { 1.0f, 2.0f, 3.0f }, mat[6];
        appear_sggx_matrix(&sg, mat);
        acc += mat[0] + appear_sggx_sigma(&sf, wi) + appear_sggx_D(&ss, wi) + appear_sggx_sigma_t(&se, 2.0f, wi) + appear_sggx_majorant(&sg, 2.0f);
        acc += appear_sggx_sample_visible(&sg, wo, u, u).x + appear_sggx_specular_eval(&sg, wo, wi) + appear_sggx_specular_pdf(&sg, wo, wi)
             + (float)appear_sggx_specular_sample(&sg, wo, u, u, &ps) + appear_sggx_diffuse_eval(&sg, wo, wi, u, u)
             + (float)appear_sggx_diffuse_sample(&sg, wo, u, u, u, u, &ps);
        acc += appear_fiber_D(&fb, wi) + appear_fiber_sigma(&fb, wi) + appear_fiber_sigma_t(&fb, 1.0f, wi) + appear_fiber_majorant(&fb, 1.0f)
             + appear_fiber_eval(&fb, wo, wi) + appear_fiber_pdf(&fb, wo, wi) + (float)appear_fiber_sample(&fb, wo, u, u, &ps);
        acc += appear_dhg_eval(&dh, wo, wi) + appear_dhg_pdf(&dh, wo, wi) + (float)appear_dhg_sample(&dh, wo, u, u, &ps);
        acc += appear_rayleigh_eval(wo, wi) + appear_rayleigh_pdf(wo, wi) + (float)appear_rayleigh_sample(wo, u, u, &ps);
        acc += appear_draine_eval(&dr, wo, wi) + appear_draine_pdf(&dr, wo, wi) + (float)appear_draine_sample(&dr, wo, u, u, &ps);
        acc += appear_mie_eval(&mi, wo, wi) + appear_mie_pdf(&mi, wo, wi) + (float)appear_mie_sample(&mi, wo, u, u, &ps);
        acc += (float)appear_phase_table_make(&pt, vals, 0, 3) + appear_phase_table_eval(&pt, wo, wi) + appear_phase_table_pdf(&pt, wo, wi)
             + (float)appear_phase_table_sample(&pt, wo, u, u, &ps);
    }
    {
        appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        appear_conductor c = appear_conductor_make(d, appear_spectrum_splat(0.2f), appear_spectrum_splat(3.0f));
        appear_dielectric g = appear_dielectric_make(d, 1.5f);
        acc += appear_thinfilm_airy(u, 550.0f, 1.5f, 300.0f, 1.5f, 0.0f)
             + appear_thinfilm_rgb(u, 1.5f, 300.0f, appear_spectrum_splat(1.5f), appear_spectrum_splat(0.0f)).v[0];
        acc += appear_conductor_albedo(0, u, u) + appear_dielectric_albedo(1, u, 1.5f, u) +
               appear_conductor_albedo_aniso(u, 0.5f * u, wo);
        acc += appear_dielectric_reflect_albedo(1, u, 1.5f, u) + appear_dielectric_reflect_albedo_avg(0, u, 1.5f);
        acc += appear_conductor_comp_eval(&c, wo, wi).v[0] + appear_conductor_comp_pdf(&c, wo, wi) + (float)appear_conductor_comp_sample(&c, wo, u, u, u, &bs);
        acc += appear_dielectric_comp_eval(&g, wo, wi).v[0] + appear_dielectric_comp_pdf(&g, wo, wi) + (float)appear_dielectric_comp_sample(&g, wo, u, u, u, &bs);
        {
            appear_rng rng = appear_rng_make((unsigned)(u * 1000.0f));
            acc += appear_conductor_ms_eval(&c, wo, wi, &rng).v[0] + appear_conductor_ms_pdf(&c, wo, wi) + (float)appear_conductor_ms_sample(&c, wo, &rng, &bs);
            acc += appear_dielectric_ms_eval(&g, wo, wi, &rng).v[0] + appear_dielectric_ms_pdf(&g, wo, wi) + (float)appear_dielectric_ms_sample(&g, wo, &rng, &bs);
        }
    }
    out[0] = acc;
}
#endif
