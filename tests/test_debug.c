/* tests/test_debug.c - APPEAR_DEBUG: invalid input to the public entry points
 * is reported through APPEAR_DEBUG_REPORT (here: counted and recorded), once
 * per mistake, with the function's name; valid input reports nothing; the
 * result is the same zero / failed one as without APPEAR_DEBUG.
 * This translation unit is built with APPEAR_DEBUG (the functions are
 * static inline, so the other test files keep the default, no checks; the
 * default report, once per site with counts, is tests/test_debug_once.c).
 * A user-defined APPEAR_DEBUG_REPORT, as here, gets every call. */
#include <string.h>
static int dbg_count;
static const char *dbg_func = "", *dbg_what = "";
#define APPEAR_DEBUG
#define APPEAR_DEBUG_REPORT(func, what) (++dbg_count, dbg_func = (func), dbg_what = (what))
#include "harness.h"

static void dbg_reset(void)
{
    dbg_count = 0;
    dbg_func = dbg_what = "";
}
/* exactly one report, from func, whose message contains word */
static void dbg_expect(const char *call, const char *func, const char *word)
{
    H_CHECK(dbg_count == 1 && strcmp(dbg_func, func) == 0 && strstr(dbg_what, word) != NULL,
            "%s: %d reports, last %s: \"%s\" (expected one from %s about \"%s\")", call, dbg_count,
            dbg_func, dbg_what, func, word);
    dbg_reset();
}
static void dbg_none(const char *call)
{
    H_CHECK(dbg_count == 0, "%s: valid input reported %d times (%s: %s)", call, dbg_count, dbg_func,
            dbg_what);
    dbg_reset();
}
#define DBG_ONE(call, func, word) \
    do { \
        dbg_reset(); \
        (void)(call); \
        dbg_expect(#call, func, word); \
    } while (0)
#define DBG_NONE(call) \
    do { \
        dbg_reset(); \
        (void)(call); \
        dbg_none(#call); \
    } while (0)

void suite_debug(void)
{
    appear_vec3 up = appear_vec3_make(0.0f, 0.0f, 1.0f), wi = appear_vec3_make(0.6f, 0.0f, 0.8f);
    appear_vec3 nan3 = appear_vec3_make(NAN, 0.0f, 1.0f),
                longv = appear_vec3_make(0.0f, 0.0f, 2.0f);
    appear_vec3 tang = appear_vec3_make(1.0f, 0.0f, 0.0f);
    appear_bsdf_record bs;
    appear_phase_record ps;
    (void)longv;

    h_case("APPEAR_DEBUG: valid input reports nothing");
    {
        appear_spectrum half = appear_spectrum_splat(0.5f);
        appear_lambert l = appear_lambert_make(half);
        appear_ward w =
            appear_ward_make(appear_spectrum_splat(0.3f), half, 0.2f, 0.3f, APPEAR_WARD_DUER);
        appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        appear_conductor c = appear_conductor_make(d, half, appear_spectrum_splat(3.0f));
        appear_conductor cr = appear_conductor_make_reflectance(d, half);
        appear_dielectric de = appear_dielectric_make(d, 1.5f);
        appear_medium_sample ms;
        appear_medium_sample1 ms1;
        dbg_none("the make() calls");
        DBG_NONE(appear_lambert_eval(&l, up, wi));
        DBG_NONE(appear_lambert_pdf(&l, up, wi));
        DBG_NONE(appear_lambert_sample(&l, up, 0.5f, 0.3f, 0.7f, &bs));
        DBG_NONE(appear_lambert_eval(
            &l, up, appear_vec3_make(0.0f, 0.0f, -1.0f))); /* wrong side: legit 0 */
        DBG_NONE(appear_ward_eval(&w, up, wi));
        DBG_NONE(appear_ward_pdf(&w, up, wi));
        DBG_NONE(appear_ward_sample(&w, up, 0.5f, 0.3f, 0.7f, &bs));
        DBG_NONE(appear_conductor_eval(&c, up, wi));
        DBG_NONE(appear_conductor_pdf(&c, up, wi));
        DBG_NONE(appear_conductor_sample(&c, up, 0.5f, 0.3f, 0.7f, &bs));
        DBG_NONE(appear_conductor_eval(&cr, up, wi));
        DBG_NONE(appear_dielectric_eval(&de, up, wi));
        DBG_NONE(appear_dielectric_pdf(&de, up, wi));
        DBG_NONE(appear_dielectric_sample(&de, up, 0.5f, 0.3f, 0.7f, &bs));
        DBG_NONE(
            appear_dielectric_sample(&de, up, 1.0f, 0.0f, 1.0f, &bs)); /* u = 0 and 1 are allowed */
        DBG_NONE(appear_hg_eval_g(0.7f, up, wi));
        DBG_NONE(appear_hg_pdf_g(-1.0f, up, wi));
        DBG_NONE(appear_hg_sample_g(0.7f, up, 0.3f, 0.7f, &ps));
        DBG_NONE(appear_hg_eval_g(0.7f, up, tang)); /* phase functions have no tangent plane */
        DBG_NONE(appear_homogeneous_sample(half, 1.0f, 0.5f, 0.5f, &ms));
        DBG_NONE(appear_homogeneous_sample(half, HUGE_VALF, 0.5f, 1.0f, &ms));
        DBG_NONE(appear_homogeneous_sample1(0.5f, 0.0f, 0.0f, &ms1));
    }

    h_case("APPEAR_DEBUG: each invalid direction / random number trips once, result unchanged");
    {
        appear_lambert l = appear_lambert_make(appear_spectrum_splat(0.5f));
        appear_microfacet d =
            appear_microfacet_make(APPEAR_BECKMANN, 0.3f, 0.2f, APPEAR_SAMPLE_VISIBLE);
        appear_conductor c =
            appear_conductor_make_f82(d, appear_spectrum_splat(0.9f), appear_spectrum_splat(0.8f));
        appear_dielectric de = appear_dielectric_make(d, 1.33f);
        appear_ward w = appear_ward_make(appear_spectrum_splat(0.3f), appear_spectrum_splat(0.5f),
                                         0.2f, 0.2f, APPEAR_WARD_BALANCED);
        appear_spectrum e;
        int r;
        DBG_ONE(appear_lambert_eval(&l, nan3, wi), "appear_lambert_eval", "wo is NaN");
        DBG_ONE(appear_lambert_eval(&l, up, longv), "appear_lambert_eval", "wi is not unit");
        DBG_ONE(appear_lambert_pdf(&l, tang, wi), "appear_lambert_pdf",
                "wo is in the tangent plane");
        DBG_ONE(appear_lambert_pdf(&l, up, nan3), "appear_lambert_pdf", "wi is NaN");
        dbg_reset();
        r = appear_lambert_sample(&l, up, 0.5f, NAN, 0.5f, &bs);
        dbg_expect("lambert_sample(u1 NaN)", "appear_lambert_sample", "u1");
        H_CHECK(r == 0 && bs.pdf == 0 && bs.weight.v[0] == 0, "lambert u1 NaN: %d %g", r, bs.pdf);
        DBG_ONE(appear_lambert_sample(&l, longv, 0.5f, 0.5f, 0.5f, &bs), "appear_lambert_sample",
                "wo is not unit");
        DBG_ONE(appear_lambert_sample(&l, up, 0.5f, 0.5f, 1.5f, &bs), "appear_lambert_sample",
                "u2");

        DBG_ONE(appear_ward_eval(&w, longv, wi), "appear_ward_eval", "wo is not unit");
        DBG_ONE(appear_ward_pdf(&w, up, nan3), "appear_ward_pdf", "wi is NaN");
        DBG_ONE(appear_ward_sample(&w, tang, 0.5f, 0.5f, 0.5f, &bs), "appear_ward_sample",
                "tangent");
        DBG_ONE(appear_ward_sample(&w, up, -0.5f, 0.5f, 0.5f, &bs), "appear_ward_sample", "uc");

        dbg_reset();
        e = appear_conductor_eval(&c, up, longv);
        dbg_expect("conductor_eval(wi long)", "appear_conductor_eval", "wi is not unit");
        H_CHECK(e.v[0] == 0 && e.v[1] == 0 && e.v[2] == 0, "conductor eval of a bad wi: %g",
                e.v[0]);
        DBG_ONE(appear_conductor_pdf(&c, nan3, wi), "appear_conductor_pdf", "wo is NaN");
        DBG_ONE(appear_conductor_sample(&c, tang, 0.5f, 0.5f, 0.5f, &bs), "appear_conductor_sample",
                "tangent");
        DBG_ONE(appear_conductor_sample(&c, up, 0.5f, 0.5f, NAN, &bs), "appear_conductor_sample",
                "u2");

        DBG_ONE(appear_dielectric_eval(&de, tang, wi), "appear_dielectric_eval", "tangent");
        DBG_ONE(appear_dielectric_pdf(&de, up, longv), "appear_dielectric_pdf", "wi is not unit");
        dbg_reset();
        r = appear_dielectric_sample(&de, nan3, 0.5f, 0.5f, 0.5f, &bs);
        dbg_expect("dielectric_sample(wo NaN)", "appear_dielectric_sample", "wo is NaN");
        H_CHECK(r == 0 && bs.flags == 0 && bs.pdf == 0, "dielectric wo NaN: %d", r);
        DBG_ONE(appear_dielectric_sample(&de, up, NAN, 0.5f, 0.5f, &bs), "appear_dielectric_sample",
                "uc");

        DBG_ONE(appear_hg_eval_g(1.5f, up, wi), "appear_hg_eval_g", "g is NaN");
        DBG_ONE(appear_hg_eval_g(0.5f, up, longv), "appear_hg_eval_g", "wi is not unit");
        DBG_ONE(appear_hg_pdf_g(NAN, up, wi), "appear_hg_pdf_g", "g is NaN");
        DBG_ONE(appear_hg_sample_g(0.5f, nan3, 0.5f, 0.5f, &ps), "appear_hg_sample_g", "wo is NaN");
        DBG_ONE(appear_hg_sample_g(0.5f, up, 2.0f, 0.5f, &ps), "appear_hg_sample_g", "u1");
    }

    h_case(
        "APPEAR_DEBUG: invalid parameters trip at make time (and an invalid model at each call)");
    {
        appear_microfacet good =
                              appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE),
                          d;
        appear_lambert l;
        appear_conductor c;
        appear_dielectric de;
        appear_medium_sample ms;
        appear_medium_sample1 ms1;
        float v;
        int r;
        dbg_reset();
        d = appear_microfacet_make(APPEAR_GGX, -0.1f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        dbg_expect("microfacet_make(ax < 0)", "appear_microfacet_make", "ax or ay");
        H_CHECK(!d.valid, "ax < 0 accepted");
        DBG_ONE(appear_microfacet_make(APPEAR_GGX, 0.3f, 1e9f, APPEAR_SAMPLE_VISIBLE),
                "appear_microfacet_make", "ax or ay");
        DBG_ONE(appear_microfacet_make(APPEAR_BECKMANN, 0.3f, 0.3f, APPEAR_SAMPLE_BOUNDED),
                "appear_microfacet_make", "sampling");
        DBG_ONE(appear_lambert_make(appear_spectrum_splat(1.5f)), "appear_lambert_make", "albedo");
        DBG_ONE(appear_eon_make(appear_spectrum_splat(1.5f), 0.5f), "appear_eon_make", "rho");
        DBG_ONE(appear_eon_make(appear_spectrum_splat(0.5f), NAN), "appear_eon_make", "sigma");
        DBG_ONE(appear_eon_make_sampled(appear_spectrum_splat(0.5f), 0.5f, 7), "appear_eon_make",
                "sampling");
        DBG_ONE(appear_sheen_make(appear_spectrum_splat(0.5f), 0.0f), "appear_sheen_make", "roughness");
        DBG_ONE(appear_sheen_make(appear_spectrum_splat(NAN), 0.5f), "appear_sheen_make", "color");
        DBG_ONE(appear_ward_make(appear_spectrum_splat(0.5f), appear_spectrum_splat(0.3f), 0.0f,
                                 0.2f, APPEAR_WARD_DUER),
                "appear_ward_make", "alpha_x or alpha_y");
        DBG_ONE(
            appear_conductor_make(good, appear_spectrum_splat(NAN), appear_spectrum_splat(1.0f)),
            "appear_conductor_make", "eta or k");
        DBG_ONE(appear_conductor_make_f82(good, appear_spectrum_splat(0.5f),
                                          appear_spectrum_splat(2.0f)),
                "appear_conductor_make_f82", "f0 or tint");
        DBG_ONE(appear_conductor_make_reflectance(good, appear_spectrum_splat(-0.5f)),
                "appear_conductor_make_reflectance", "F0");
        DBG_ONE(appear_conductor_make(d, appear_spectrum_splat(0.5f), appear_spectrum_splat(1.0f)),
                "appear_conductor_make", "d is invalid");
        DBG_ONE(appear_dielectric_make(good, 0.0f), "appear_dielectric_make", "eta");
        dbg_reset();
        l = appear_lambert_make(appear_spectrum_splat(NAN));
        dbg_reset();
        dbg_reset();
        v = appear_lambert_pdf(&l, up, wi);
        dbg_expect("lambert_pdf(invalid model)", "appear_lambert_pdf", "model invalid");
        H_CHECK(v == 0.0f, "invalid lambert pdf %g", v);
        dbg_reset();
        c = appear_conductor_make_reflectance(good, appear_spectrum_splat(NAN));
        dbg_reset();
        DBG_ONE(appear_conductor_sample(&c, up, 0.5f, 0.5f, 0.5f, &bs), "appear_conductor_sample",
                "model invalid");
        dbg_reset();
        de = appear_dielectric_make(good, NAN);
        dbg_reset();
        DBG_ONE(appear_dielectric_eval(&de, up, wi), "appear_dielectric_eval", "model invalid");

        dbg_reset();
        r = appear_homogeneous_sample(appear_spectrum_splat(-1.0f), 1.0f, 0.5f, 0.5f, &ms);
        dbg_expect("homogeneous_sample(sigma < 0)", "appear_homogeneous_sample", "sigma_t");
        H_CHECK(r == APPEAR_MEDIUM_FAILED && ms.pdf == 0, "homogeneous sigma < 0: %d", r);
        DBG_ONE(appear_homogeneous_sample(appear_spectrum_splat(1.0f), NAN, 0.5f, 0.5f, &ms),
                "appear_homogeneous_sample", "d is NaN");
        DBG_ONE(appear_homogeneous_sample(appear_spectrum_splat(1.0f), 1.0f, 0.5f, NAN, &ms),
                "appear_homogeneous_sample", "u is NaN");
        DBG_ONE(appear_homogeneous_sample(appear_spectrum_splat(1.0f), 1.0f, 1.5f, 0.5f, &ms),
                "appear_homogeneous_sample", "uc");
        DBG_ONE(appear_homogeneous_sample1(HUGE_VALF, 1.0f, 0.5f, &ms1),
                "appear_homogeneous_sample1", "sigma_t");
        DBG_ONE(appear_homogeneous_sample1(1.0f, -1.0f, 0.5f, &ms1), "appear_homogeneous_sample1",
                "d is NaN");
    }

    /* issue 30: the isotropic phase function and the frames were not
       checked (a non-unit wi gave 0 silently, a normal of length 3 a frame
       that is not orthonormal) */
    h_case("APPEAR_DEBUG: isotropic phase function and frames check their input");
    {
        appear_vec3 n3 = appear_vec3_make(0.0f, 0.0f, 3.0f),
                    tilt = appear_vec3_make(0.6f, 0.0f, 0.8f);
        appear_frame f;
        float v;
        int r;
        DBG_NONE(appear_isotropic_eval(up, wi));
        DBG_NONE(appear_isotropic_pdf(up, tang));
        DBG_NONE(appear_isotropic_sample(up, 0.0f, 1.0f, &ps));
        dbg_reset();
        v = appear_isotropic_eval(up, longv);
        dbg_expect("isotropic_eval(wi long)", "appear_isotropic_eval", "wi is not unit");
        H_CHECK(v == 0.0f, "isotropic eval of a bad wi: %g", v);
        DBG_ONE(appear_isotropic_eval(nan3, wi), "appear_isotropic_eval", "wo is NaN");
        DBG_ONE(appear_isotropic_pdf(up, longv), "appear_isotropic_pdf", "wi is not unit");
        dbg_reset();
        r = appear_isotropic_sample(longv, 0.5f, 0.5f, &ps);
        dbg_expect("isotropic_sample(wo long)", "appear_isotropic_sample", "wo is not unit");
        H_CHECK(r == 0 && ps.pdf == 0.0f, "isotropic sample of a bad wo: %d %g", r, ps.pdf);
        DBG_ONE(appear_isotropic_sample(up, 1.5f, 0.5f, &ps), "appear_isotropic_sample", "u1");
        DBG_ONE(appear_isotropic_sample(up, 0.5f, NAN, &ps), "appear_isotropic_sample", "u2");

        DBG_NONE(appear_frame_from_normal(up));
        DBG_NONE(appear_frame_from_normal(appear_vec3_make(0.0f, 0.0f, -1.0f)));
        DBG_NONE(appear_frame_from_normal_tangent(tilt, tang));
        DBG_NONE(appear_frame_from_normal_tangent(up, longv)); /* t of any length */
        dbg_reset();
        f = appear_frame_from_normal(n3);
        dbg_expect("frame_from_normal(length 3)", "appear_frame_from_normal", "n is not unit");
        H_CHECK(f.z.z == 3.0f, "frame of a length-3 normal: z = %g (documented: n as given)",
                f.z.z);
        DBG_ONE(appear_frame_from_normal(nan3), "appear_frame_from_normal", "n is NaN");
        DBG_ONE(appear_frame_from_normal(appear_vec3_make(0.0f, 0.0f, 0.0f)),
                "appear_frame_from_normal", "n is not unit");
        DBG_ONE(appear_frame_from_normal_tangent(n3, tang), "appear_frame_from_normal_tangent",
                "n is not unit");
        /* the fallback for a tangent parallel to n reports once, as the tangent form */
        DBG_ONE(appear_frame_from_normal_tangent(n3, n3), "appear_frame_from_normal_tangent",
                "n is not unit");
        DBG_ONE(appear_frame_from_normal_tangent(nan3, tang), "appear_frame_from_normal_tangent",
                "n is NaN");
    }

    h_case("APPEAR_DEBUG: the further phase functions check their input");
    {
        appear_dhg dh = appear_dhg_make(0.7f, -0.3f, 0.6f);
        appear_draine dr = appear_draine_make(0.5f, 1.0f);
        appear_mie mi = appear_mie_make(5.0f);
        static const float vals[3] = {1.0f, 2.0f, 3.0f};
        static appear_phase_table tab; /* 3 KB: not on the stack */
        appear_sggx sg = appear_sggx_make_surface(up, 0.3f);
        appear_fiber fb = appear_fiber_make(up, 4.0f);
        (void)appear_phase_table_make(&tab, vals, NULL, 3);
        dbg_none("the phase make() calls");
        DBG_NONE(appear_dhg_eval(&dh, up, wi));
        DBG_NONE(appear_dhg_pdf(&dh, up, wi));
        DBG_NONE(appear_dhg_sample(&dh, up, 0.3f, 0.7f, &ps));
        DBG_NONE(appear_rayleigh_eval(up, wi));
        DBG_NONE(appear_rayleigh_pdf(up, wi));
        DBG_NONE(appear_rayleigh_sample(up, 0.3f, 0.7f, &ps));
        DBG_NONE(appear_draine_eval(&dr, up, wi));
        DBG_NONE(appear_draine_pdf(&dr, up, wi));
        DBG_NONE(appear_draine_sample(&dr, up, 0.3f, 0.7f, &ps));
        DBG_NONE(appear_mie_eval(&mi, up, wi));
        DBG_NONE(appear_mie_pdf(&mi, up, wi));
        DBG_NONE(appear_mie_sample(&mi, up, 0.3f, 0.7f, &ps));
        DBG_NONE(appear_mie_sample(&mi, up, 0.9f, 0.7f, &ps));
        DBG_NONE(appear_phase_table_eval(&tab, up, wi));
        DBG_NONE(appear_phase_table_pdf(&tab, up, wi));
        DBG_NONE(appear_phase_table_sample(&tab, up, 0.3f, 0.7f, &ps));
        DBG_NONE(appear_sggx_specular_eval(&sg, up, wi));
        DBG_NONE(appear_sggx_specular_pdf(&sg, up, wi));
        DBG_NONE(appear_sggx_specular_sample(&sg, up, 0.3f, 0.7f, &ps));
        DBG_NONE(appear_sggx_diffuse_eval(&sg, up, wi, 0.3f, 0.7f));
        DBG_NONE(appear_sggx_diffuse_sample(&sg, up, 0.3f, 0.7f, 0.2f, 0.9f, &ps));
        DBG_NONE(appear_fiber_eval(&fb, tang, wi));
        DBG_NONE(appear_fiber_pdf(&fb, tang, wi));
        DBG_NONE(appear_fiber_sample(&fb, tang, 0.3f, 0.7f, &ps));

        DBG_ONE(appear_dhg_eval(&dh, up, longv), "appear_dhg_eval", "wi is not unit");
        DBG_ONE(appear_dhg_pdf(&dh, nan3, wi), "appear_dhg_pdf", "wo is NaN");
        DBG_ONE(appear_dhg_sample(&dh, longv, 0.3f, 0.7f, &ps), "appear_dhg_sample",
                "wo is not unit");
        DBG_ONE(appear_dhg_sample(&dh, up, 0.3f, -0.5f, &ps), "appear_dhg_sample", "u2");
        DBG_ONE(appear_rayleigh_eval(up, longv), "appear_rayleigh_eval", "wi is not unit");
        DBG_ONE(appear_rayleigh_pdf(longv, wi), "appear_rayleigh_pdf", "wo is not unit");
        DBG_ONE(appear_rayleigh_sample(up, NAN, 0.7f, &ps), "appear_rayleigh_sample", "u1");
        DBG_ONE(appear_draine_eval(&dr, up, longv), "appear_draine_eval", "wi is not unit");
        DBG_ONE(appear_draine_pdf(&dr, up, nan3), "appear_draine_pdf", "wi is NaN");
        DBG_ONE(appear_draine_sample(&dr, longv, 0.3f, 0.7f, &ps), "appear_draine_sample",
                "wo is not unit");
        DBG_ONE(appear_mie_eval(&mi, up, longv), "appear_mie_eval", "wi is not unit");
        DBG_ONE(appear_mie_pdf(&mi, longv, wi), "appear_mie_pdf", "wo is not unit");
        DBG_ONE(appear_mie_sample(&mi, longv, 0.3f, 0.7f, &ps), "appear_mie_sample",
                "wo is not unit");
        DBG_ONE(appear_mie_sample(&mi, longv, 0.9f, 0.7f, &ps), "appear_mie_sample",
                "wo is not unit");
        DBG_ONE(appear_phase_table_eval(&tab, up, longv), "appear_phase_table_eval",
                "wi is not unit");
        DBG_ONE(appear_phase_table_pdf(&tab, nan3, wi), "appear_phase_table_pdf", "wo is NaN");
        DBG_ONE(appear_phase_table_sample(&tab, up, 2.0f, 0.7f, &ps), "appear_phase_table_sample",
                "u1");
        DBG_ONE(appear_sggx_specular_eval(&sg, up, longv), "appear_sggx_specular_eval",
                "wi is not unit");
        DBG_ONE(appear_sggx_specular_pdf(&sg, longv, wi), "appear_sggx_specular_pdf",
                "wo is not unit");
        DBG_ONE(appear_sggx_specular_sample(&sg, nan3, 0.3f, 0.7f, &ps),
                "appear_sggx_specular_sample", "wo is NaN");
        DBG_ONE(appear_sggx_diffuse_eval(&sg, up, wi, 0.3f, 1.5f), "appear_sggx_diffuse_eval",
                "u2");
        DBG_ONE(appear_sggx_diffuse_sample(&sg, longv, 0.3f, 0.7f, 0.2f, 0.9f, &ps),
                "appear_sggx_diffuse_sample", "wo is not unit");
        DBG_ONE(appear_sggx_diffuse_sample(&sg, up, 0.3f, 0.7f, 0.2f, NAN, &ps),
                "appear_sggx_diffuse_sample", "u4");
        DBG_ONE(appear_fiber_eval(&fb, tang, longv), "appear_fiber_eval", "wi is not unit");
        DBG_ONE(appear_fiber_pdf(&fb, longv, wi), "appear_fiber_pdf", "wo is not unit");
        DBG_ONE(appear_fiber_sample(&fb, tang, 0.3f, NAN, &ps), "appear_fiber_sample", "u2");

        DBG_ONE(appear_dhg_make(0.5f, 1.5f, 0.5f), "appear_dhg_make", "g1 or g2");
        DBG_ONE(appear_draine_make(0.5f, -2.0f), "appear_draine_make", "alpha");
        DBG_ONE(appear_mie_make(60.0f), "appear_mie_make", "d is NaN or outside");
        DBG_ONE(appear_phase_table_make(&tab, vals, NULL, 1), "appear_phase_table_make",
                "n outside");
        DBG_ONE(appear_sggx_make_surface(longv, 0.3f), "appear_sggx_make_surface", "n is not unit");
        DBG_ONE(appear_sggx_make_fiber(up, 2.0f), "appear_sggx_make_fiber", "alpha");
        DBG_ONE(appear_sggx_make(-1.0f, 1.0f, 1.0f, 0.0f, 0.0f, 0.0f), "appear_sggx_make",
                "positive semi-definite");
        DBG_ONE(appear_sggx_make_eigen(up, up, tang, 1.0f, 1.0f, 1.0f), "appear_sggx_make_eigen",
                "not orthogonal");
        DBG_ONE(appear_fiber_make(longv, 4.0f), "appear_fiber_make", "t is not unit");
        dbg_reset();
        dh = appear_dhg_make(NAN, 0.0f, 0.5f);
        dbg_reset();
        DBG_ONE(appear_dhg_eval(&dh, up, wi), "appear_dhg_eval", "model invalid");
    }

    /* issue 30: a report named the internal function a public one forwards
       to (appear_hg_pdf reported as appear_hg_pdf_g; double HG reported
       twice as appear_hg_eval_g; the compensated conductor as
       appear_conductor_eval) */
    h_case("APPEAR_DEBUG: a report names the function the caller called, once");
    {
        appear_hg h = appear_hg_make(0.5f), bad;
        appear_dhg dh = appear_dhg_make(0.7f, -0.3f, 0.6f);
        appear_draine dr = appear_draine_make(0.5f, 1.0f);
        appear_mie mi = appear_mie_make(5.0f);
        appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE),
                          dbad;
        appear_conductor c =
            appear_conductor_make(d, appear_spectrum_splat(0.2f), appear_spectrum_splat(3.0f));
        appear_dielectric de = appear_dielectric_make(d, 1.5f);
        appear_thinfilm tf = appear_thinfilm_make_rgb(1.4f, 300.0f, appear_spectrum_splat(0.2f),
                                                      appear_spectrum_splat(3.0f));
        appear_thinfilm_conductor tc = appear_thinfilm_conductor_make(d, tf);
        dbg_none("the make() calls");
        DBG_NONE(appear_hg_eval(&h, up, wi));
        DBG_NONE(appear_hg_pdf(&h, up, wi));
        DBG_NONE(appear_hg_sample(&h, up, 0.3f, 0.7f, &ps));
        DBG_NONE(appear_conductor_comp_eval(&c, up, wi));
        DBG_NONE(appear_conductor_comp_pdf(&c, up, wi));
        DBG_NONE(appear_conductor_comp_sample(&c, up, 0.5f, 0.3f, 0.7f, &bs));
        DBG_NONE(appear_dielectric_comp_eval(&de, up, wi));
        DBG_NONE(appear_dielectric_comp_pdf(&de, up, wi));
        DBG_NONE(appear_dielectric_comp_sample(&de, up, 0.5f, 0.3f, 0.7f, &bs));
        DBG_NONE(appear_thinfilm_conductor_eval(&tc, up, wi));
        DBG_NONE(appear_thinfilm_conductor_pdf(&tc, up, wi));
        DBG_NONE(appear_thinfilm_conductor_sample(&tc, up, 0.5f, 0.3f, 0.7f, &bs));

        DBG_ONE(appear_hg_pdf(&h, up, longv), "appear_hg_pdf", "wi is not unit");
        DBG_ONE(appear_hg_eval(&h, nan3, wi), "appear_hg_eval", "wo is NaN");
        DBG_ONE(appear_hg_sample(&h, up, 0.5f, 2.0f, &ps), "appear_hg_sample", "u2");
        dbg_reset();
        bad = appear_hg_make(2.0f);
        dbg_expect("hg_make(2)", "appear_hg_make", "g is NaN");
        DBG_ONE(appear_hg_pdf(&bad, up, wi), "appear_hg_pdf", "model invalid");
        /* the mixtures once, as themselves (not twice as appear_hg_eval_g) */
        DBG_ONE(appear_dhg_eval(&dh, longv, wi), "appear_dhg_eval", "wo is not unit");
        DBG_ONE(appear_draine_eval(&dr, longv, wi), "appear_draine_eval", "wo is not unit");
        DBG_ONE(appear_mie_pdf(&mi, up, nan3), "appear_mie_pdf", "wi is NaN");
        DBG_ONE(appear_conductor_comp_eval(&c, up, longv), "appear_conductor_comp_eval",
                "wi is not unit");
        DBG_ONE(appear_conductor_comp_pdf(&c, tang, wi), "appear_conductor_comp_pdf", "tangent");
        DBG_ONE(appear_conductor_comp_sample(&c, up, 0.5f, NAN, 0.7f, &bs),
                "appear_conductor_comp_sample", "u1");
        DBG_ONE(appear_dielectric_comp_eval(&de, nan3, wi), "appear_dielectric_comp_eval",
                "wo is NaN");
        DBG_ONE(appear_dielectric_comp_pdf(&de, up, longv), "appear_dielectric_comp_pdf",
                "wi is not unit");
        DBG_ONE(appear_dielectric_comp_sample(&de, up, 2.0f, 0.3f, 0.7f, &bs),
                "appear_dielectric_comp_sample", "uc");
        DBG_ONE(appear_thinfilm_conductor_eval(&tc, up, longv), "appear_thinfilm_conductor_eval",
                "wi is not unit");
        DBG_ONE(appear_thinfilm_conductor_pdf(&tc, longv, wi), "appear_thinfilm_conductor_pdf",
                "wo is not unit");
        DBG_ONE(appear_thinfilm_conductor_sample(&tc, tang, 0.5f, 0.3f, 0.7f, &bs),
                "appear_thinfilm_conductor_sample", "tangent");
        dbg_reset();
        dbad = appear_microfacet_make(APPEAR_GGX, -1.0f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        dbg_reset();
        DBG_ONE(appear_thinfilm_conductor_make(dbad, tf), "appear_thinfilm_conductor_make",
                "d is invalid");
    }
#ifdef APPEAR_HAS_MATERIALS
    h_case("APPEAR_DEBUG: the materials' lookups name the argument, once, from the function called");
    {
        const float lam[APPEAR_SPECTRUM_SAMPLES] = { 0 }; /* 0 nm: outside [360, 830] */
        appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        appear_spectrum e, k;
        float fe, fk;
        dbg_reset();
        (void)appear_metal_eta_k(APPEAR_METAL_AU, 550.0f, &fe, &fk);
        (void)appear_dielectric_ior(APPEAR_DIELECTRIC_WATER, 360.0f);
        (void)appear_ior_cauchy_abbe(1.5f, INFINITY, 830.0f);
        (void)appear_conductor_make_metal(d, APPEAR_METAL_CU, APPEAR__NULL);
        dbg_none("valid material lookups");
        DBG_ONE(appear_metal_eta_k(-1, 550.0f, &fe, &fk), "appear_metal_eta_k", "metal");
        DBG_ONE(appear_metal_eta_k(APPEAR_METAL_AU, NAN, &fe, &fk), "appear_metal_eta_k", "lambda_nm");
        DBG_ONE(appear_metal_eta_k(APPEAR_METAL_AU, 900.0f, &fe, &fk), "appear_metal_eta_k", "outside");
        DBG_ONE(appear_metal_to_rgb(APPEAR_METAL_COUNT), "appear_metal_to_rgb", "metal");
        DBG_ONE(appear_dielectric_ior(99, 500.0f), "appear_dielectric_ior", "material");
        DBG_ONE(appear_dielectric_ior(APPEAR_DIELECTRIC_ICE, 100.0f), "appear_dielectric_ior", "lambda_nm");
        DBG_ONE(appear_dielectric_ior_spectrum(-3, APPEAR__NULL), "appear_dielectric_ior_spectrum", "material");
        DBG_ONE(appear_ior_cauchy_abbe(NAN, 20.0f, 500.0f), "appear_ior_cauchy_abbe", "n_d");
        DBG_ONE(appear_ior_cauchy_abbe(1.5f, -1.0f, 500.0f), "appear_ior_cauchy_abbe", "V_d");
        DBG_ONE(appear_conductor_make_metal(d, 77, APPEAR__NULL),
                "appear_conductor_make_metal", "metal");
        {
            appear_spectrum et = appear_spectrum_splat(1.5f);
            appear_dielectric_dispersive dm;
            appear_bsdf_record rec;
            et.v[0] = NAN;
            DBG_ONE(appear_dielectric_make_dispersive(d, et), "appear_dielectric_make_dispersive", "eta");
            dm = appear_dielectric_make_dispersive(d, appear_spectrum_splat(1.5f));
            dbg_none("valid dispersive make");
            DBG_ONE(appear_dielectric_dispersive_eval(&dm, appear_vec3_make(0, 0, 2), appear_vec3_make(0, 0, 1)),
                    "appear_dielectric_dispersive_eval", "wo is not unit");
            DBG_ONE(appear_dielectric_dispersive_sample(&dm, appear_vec3_make(0, 0, 1), 0.5f, NAN, 0.5f, &rec),
                    "appear_dielectric_dispersive_sample", "u1");
        }
        (void)appear_metal_spectrum(APPEAR_METAL_AG, lam, &e, &k);
        H_CHECK(dbg_count == APPEAR_SPECTRUM_SAMPLES && strcmp(dbg_func, "appear_metal_spectrum") == 0,
                "metal_spectrum at 0 nm: %d reports from %s", dbg_count, dbg_func);
        dbg_reset();
    }
#endif
}
