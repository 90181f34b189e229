/* Compile check: a second translation unit that includes the header (without
   APPEAR_IMPLEMENTATION) and uses it, to catch duplicate definitions. */
#include "../../appear.h"
int appear_tu2_answer(void);
int appear_tu2_answer(void)
{
    appear_vec3 n = appear_vec3_make(0.0f, 0.0f, 1.0f);
    appear_frame f = appear_frame_from_normal(n);
    return appear_dot(f.z, n) > 0.5f ? appear_version() : -1;
}

/* That APPEAR_HAS_<PART> follows APPEAR_NO_<PART> (every part on, all off, each alone off)
   is tests/compile/parts.sh's check in make check-compile, on the parts it reads from the
   header, so no list of parts is kept here. */

/* The deprecated names (SECTION deprecated of the header) still compile, as
   macros for the new ones, until the next release. */
float appear_tu2_deprecated(appear_vec3 wo, appear_vec3 wi);
float appear_tu2_deprecated(appear_vec3 wo, appear_vec3 wi)
{
    float acc = 0.0f;
#if !defined(APPEAR_NO_DEPRECATED) && defined(APPEAR_HAS_MICROFACET)
    acc += appear_f82_coef(0.9f, 0.8f) + appear_ggx_pdf_reflect_bounded(0.3f, 0.3f, wo, wi)
         + appear_ggx_sample_visible_bounded(0.3f, 0.3f, wo, 0.5f, 0.5f).z;
#endif
#if !defined(APPEAR_NO_DEPRECATED) && defined(APPEAR_HAS_MULTISCATTER)
    {
        appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        appear_spectrum one = appear_spectrum_splat(1.0f);
        appear_conductor c = appear_conductor_make(d, one, one);
        appear_dielectric g = appear_dielectric_make(d, 1.5f);
        acc += appear_ms_albedo_conductor(APPEAR_GGX, 0.3f, 0.5f)
             + appear_ms_albedo_dielectric(APPEAR_GGX, 0.3f, 1.5f, 0.5f)
             + appear_conductor_ms_scale(&c, wo).v[0] + appear_dielectric_ms_scale(&g, wo);
    }
#endif
#if !defined(APPEAR_NO_DEPRECATED) && defined(APPEAR_HAS_THINFILM)
    {
        appear_spectrum e = appear_spectrum_splat(1.5f), k = appear_spectrum_splat(0.0f);
        appear_thinfilm tf = appear_thinfilm_make_rgb(1.4f, 400.0f, e, k);
        acc += appear_thinfilm_F(&tf, 0.5f).v[0];
    }
#endif
#if !defined(APPEAR_NO_DEPRECATED) && defined(APPEAR_HAS_MEDIA)
    acc += appear_majorant_constant(1.0f).sigma_maj
         + appear_cmajorant_constant(appear_spectrum_splat(1.0f)).sigma_maj.v[0];
#endif
    (void)wo; (void)wi;
    return acc;
}
