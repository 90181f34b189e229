/* tests/test_tracer.c - the example path tracer's scenes checked numerically
   on small renders, with tolerances taken from the measured noise.

   furnace   every object alone in a uniform white environment (radiance 1):
             lossless ones (expect = 1) must have, per channel, an object
             mean within 5 standard errors of 1 and every pixel within 6
             pixel standard deviations of 1; lossy ones (expect <= 1) the
             same bounds from above only. The environment pixels are exactly
             1 (the pixel's sigma: the larger of its own estimate and the
             object's pooled one). No sample may be NaN or Inf.
   absorber  a purely absorbing procedural cloud (albedo 0) against the
             white environment: each pixel is the transmittance along its
             camera rays, which a deterministic quadrature of the density
             reproduces independently (double, 2000 midpoint steps along
             each pixel-centre ray; the render uses pixel-centre rays too).
   nee/mis   a lit scene with the scattering cloud, a chromatic HG sphere and
             a Lambert floor rendered twice: with next-event estimation + MIS
             (ratio-tracked shadow rays) and with phase/BSDF sampling alone.
             Both are unbiased, so per object the means must agree within 5
             combined standard errors.
   spectral  the spectral mode's colour: D65 x CIE 1931 integrates to RGB 1
             and the metals' normal reflectance to appear_metal_to_rgb's F0;
             a spectral white furnace (Lambert 1 and a smooth dispersive SF11
             sphere, whose refractions terminate the secondary wavelengths,
             render 1) with metal spheres, whose spectral and RGB renders must
             agree within the RGB forms' error.
   openpbr   the "openpbr_furnace" scene (the spec's white-furnace list: 1
             within 5 standard errors plus the model's stated error; coat
             and fuzz over glass in [0.84, 1]); emission exact; opacity as
             a cutout; a glass around an absorbing interior medium against
             its closed form along the diameter; the presets (the "openpbr"
             scene) with NEE + MIS against BSDF sampling alone. */
#include "harness.h"
#include "../examples/tracer.h"
#include <math.h>
#include <string.h>

/* maxdev_*: the largest pixel deviation from 1 in units of that pixel's
   standard deviation, taken as the larger of its own estimate and the
   object's pooled one (a pixel whose rare event did happen, e.g. Russian
   roulette inside glass, has its own variance far above the pooled one) */
typedef struct { double mean, se, sigma_pix, maxdev_hi, maxdev_abs, z_hi, z_abs; long n; } obj_stats;

/* statistics of channel c over the pixels of shape s (id == s) against 1 */
static obj_stats stats_of(const tracer_image *img, int s, int c, int spp)
{
    obj_stats st;
    double sum = 0, var = 0;
    long i;
    memset(&st, 0, sizeof st);
    for (i = 0; i < (long)img->w * img->h; ++i) {
        double v;
        if (img->id[i] != s) continue;
        v = img->rgb[3 * i + c];
        sum += v; var += img->var[3 * i + c]; st.n++;
        if (v - 1.0 > st.maxdev_hi) st.maxdev_hi = v - 1.0;
        if (fabs(v - 1.0) > st.maxdev_abs) st.maxdev_abs = fabs(v - 1.0);
    }
    if (!st.n) return st;
    st.mean = sum / st.n;
    st.sigma_pix = sqrt(var / st.n / spp);     /* pooled std. dev. of a pixel mean */
    st.se = st.sigma_pix / sqrt((double)st.n); /* standard error of the object mean */
    for (i = 0; i < (long)img->w * img->h; ++i) {
        double v, sg;
        if (img->id[i] != s) continue;
        v = img->rgb[3 * i + c] - 1.0;
        sg = sqrt(img->var[3 * i + c] / spp);
        sg = (sg > st.sigma_pix ? sg : st.sigma_pix) + 2e-4 / 6; /* 2e-4: float rounding */
        if (v / sg > st.z_hi) st.z_hi = v / sg;
        if (fabs(v) / sg > st.z_abs) st.z_abs = fabs(v) / sg;
    }
    return st;
}

static void furnace_case(void)
{
    static tracer_scene sc;
    tracer_image img;
    tracer_options opt;
    int s, c;
    long i, env_bad = 0;
    h_case("tracer furnace: lossless objects render 1, lossy ones <= 1 (per channel, tolerances from noise)");
    if (tracer_scene_build(&sc, "furnace")) { h_fail("no furnace scene"); return; }
    memset(&opt, 0, sizeof opt);
    opt.w = h_quick() ? 64 : 160; opt.h = h_quick() ? 40 : 100;
    opt.spp = h_quick() ? 8 : 32; opt.threads = 2; opt.seed = 7;
    if (tracer_render(&sc, &opt, &img)) { h_fail("render failed"); return; }
    H_CHECK(img.nonfinite == 0, "%ld non-finite samples", img.nonfinite);
    /* environment pixels away from silhouettes (pixel jitter reaches the
       neighbours) are exactly 1 */
    for (i = 0; i < (long)img.w * img.h; ++i) {
        int x = (int)(i % img.w), y = (int)(i / img.w), dx, dy, interior = 1;
        for (dy = -1; dy <= 1; ++dy)
            for (dx = -1; dx <= 1; ++dx) {
                int xx = x + dx, yy = y + dy;
                if (xx >= 0 && yy >= 0 && xx < img.w && yy < img.h && img.id[(long)yy * img.w + xx] >= 0) interior = 0;
            }
        if (interior && !(img.rgb[3 * i] == 1.0f && img.rgb[3 * i + 1] == 1.0f && img.rgb[3 * i + 2] == 1.0f)) ++env_bad;
    }
    H_CHECK(env_bad == 0, "%ld environment pixels differ from 1", env_bad);
    for (s = 0; s < sc.n_shapes; ++s) {
        const char *lab = sc.shapes[s].label ? sc.shapes[s].label : "?";
        int ex = sc.shapes[s].expect;
        double worst_z = 0;
        if (ex == TRACER_EXPECT_NONE) continue;
        for (c = 0; c < 3; ++c) {
            obj_stats st = stats_of(&img, s, c, opt.spp);
            /* 2e-4: float rounding of a long product of weights */
            double tol_mean = 5.0 * st.se + 2e-4;
            double z = st.se > 0 ? fabs(st.mean - 1.0) / st.se : 0;
            if (z > worst_z) worst_z = z;
            if (st.n < 20) { h_fail("%s: only %ld pixels", lab, st.n); continue; }
            if (ex == TRACER_EXPECT_ONE) {
                H_CHECK(fabs(st.mean - 1.0) <= tol_mean, "%s ch%d: mean %.5f, expected 1 +- %.5f", lab, c, st.mean, tol_mean);
                H_CHECK(st.z_abs <= 6.0, "%s ch%d: a pixel is %.1f sigma from 1 (max |pixel - 1| %.4f)", lab, c, st.z_abs, st.maxdev_abs);
            } else {
                H_CHECK(st.mean <= 1.0 + tol_mean, "%s ch%d: mean %.5f above 1 + %.5f", lab, c, st.mean, tol_mean);
                H_CHECK(st.z_hi <= 6.0, "%s ch%d: a pixel is %.1f sigma above 1 (max pixel - 1 = %.4f)", lab, c, st.z_hi, st.maxdev_hi);
            }
            if (c == 1)
                h_measure("tracer furnace", "%-34s mean %.5f  se %.2e  max|v-1| %.4f  pixel sigma %.4f  (expect %s)", lab, st.mean,
                          st.se, st.maxdev_abs, st.sigma_pix, ex == TRACER_EXPECT_ONE ? "1" : "<= 1");
        }
    }
    tracer_image_free(&img);
}

/* ---- absorbing cloud vs quadrature ---- */
static double quad_T(const tracer_medium *m, appear_vec3 lo, appear_vec3 hi, appear_vec3 o, appear_vec3 d, int steps)
{
    double t0 = -1e30, t1 = 1e30, tau = 0, dt;
    int i;
    for (i = 0; i < 3; ++i) {
        double oi = i == 0 ? o.x : (i == 1 ? o.y : o.z), di = i == 0 ? d.x : (i == 1 ? d.y : d.z);
        double l = i == 0 ? lo.x : (i == 1 ? lo.y : lo.z), h = i == 0 ? hi.x : (i == 1 ? hi.y : hi.z);
        double a = (l - oi) / di, b = (h - oi) / di;
        if (a > b) { double x = a; a = b; b = x; }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
    }
    if (t0 >= t1) return -1; /* missed */
    dt = (t1 - t0) / steps;
    for (i = 0; i < steps; ++i) {
        double t = t0 + (i + 0.5) * dt;
        appear_vec3 p = appear_vec3_make((float)(o.x + t * d.x), (float)(o.y + t * d.y), (float)(o.z + t * d.z));
        tau += m->sigma_max * tracer_cloud_density(m, p) * dt;
    }
    return exp(-tau);
}

static void absorber_case(void)
{
    static tracer_scene sc;
    tracer_medium m;
    tracer_image img;
    tracer_options opt;
    appear_vec3 lo = appear_vec3_make(-1.2f, -0.8f, -1.0f), hi = appear_vec3_make(1.2f, 0.8f, 1.0f);
    appear_vec3 fw, rt, up;
    double ty, tx, sum_d = 0, sum_se2 = 0, maxz = 0, mean_T = 0, wref = 0, wgot = 0;
    int wx = 0, wy = 0;
    long i, n = 0;
    int x, y;
    h_case("tracer absorber: delta tracking through a procedural cloud matches the quadrature transmittance");
    tracer_scene_init(&sc, "absorber");
    memset(&m, 0, sizeof m);
    m.kind = MED_CLOUD; m.lo = lo; m.hi = hi; m.sigma_max = 6.0f; m.albedo = appear_spectrum_splat(0.0f);
#if !TRACER_HAS_TRACKERS
    h_measure("tracer absorber", "skipped: appear.h without the media trackers");
    return;
#endif
    tracer_add_box(&sc, lo, hi, tracer_add_material(&sc, tracer_mat_none()), tracer_add_medium(&sc, m));
    sc.eye = appear_vec3_make(0.3f, 0.5f, 4.0f); sc.look = appear_vec3_make(0, 0, 0); sc.fov = 0.7f;
    memset(&opt, 0, sizeof opt);
    opt.w = h_quick() ? 24 : 64; opt.h = h_quick() ? 18 : 48;
    opt.spp = h_quick() ? 16 : 64; opt.threads = 2; opt.seed = 11; opt.pixel_centre = 1;
    if (tracer_render(&sc, &opt, &img)) { h_fail("render failed"); return; }
    H_CHECK(img.nonfinite == 0, "%ld non-finite samples", img.nonfinite);
    /* the tracer's pinhole camera, rebuilt here in double */
    fw = appear_normalize(appear_sub(sc.look, sc.eye));
    rt = appear_normalize(appear_cross(fw, sc.up));
    up = appear_cross(rt, fw);
    ty = tan(0.5 * sc.fov); tx = ty * opt.w / opt.h;
    for (y = 0; y < opt.h; ++y)
        for (x = 0; x < opt.w; ++x) {
            double ref, var, d, sx = (2.0 * (x + 0.5) / opt.w - 1.0) * tx, sy = (1.0 - 2.0 * (y + 0.5) / opt.h) * ty;
            appear_vec3 dir = appear_normalize(appear_add(fw, appear_add(appear_scale(rt, (float)sx), appear_scale(up, (float)sy))));
            int all;
            i = (long)y * opt.w + x;
            ref = quad_T(&m, lo, hi, sc.eye, dir, 2000);
            all = ref >= 0 && img.id[i] >= 0;
            if (!all) continue; /* pixels on the silhouette */
            /* the estimate is Bernoulli(T): its variance is T (1 - T) */
            var = ref * (1 - ref) / opt.spp;
            d = img.rgb[3 * i] - ref;
            sum_d += d; sum_se2 += var; mean_T += ref; ++n;
            if (var > 0 && fabs(d) / sqrt(var) > maxz) { maxz = fabs(d) / sqrt(var); wx = x; wy = y; wref = ref; wgot = img.rgb[3 * i]; }
        }
    H_CHECK(n > 50, "only %ld interior pixels", n);
    if (n > 0) {
        double mean_d = sum_d / n, se = sqrt(sum_se2) / n;
        /* 2e-4: float rounding of the ray and the midpoint rule */
        H_CHECK(fabs(mean_d) <= 5 * se + 2e-4, "mean(render - quadrature) %.5f, tolerance %.5f", mean_d, 5 * se + 2e-4);
        /* max over n pixels of a binomial z-score: 6 sigma plus the discreteness of few samples */
        H_CHECK(maxz <= 6.0 + 2.0, "max pixel z-score %.2f at (%d, %d): render %.4f, quadrature %.4f", maxz, wx, wy, wgot, wref);
        h_measure("tracer absorber", "%ld pixels, mean T %.3f, mean(render - quadrature) %.2e (se %.1e), max |z| %.2f at %d spp",
                  n, mean_T / n, mean_d, se, maxz, opt.spp);
    }
    tracer_image_free(&img);
}

/* ---- NEE + MIS vs BSDF/phase sampling alone ---- */
/* chromatic: the cloud is a chromatic heterogeneous medium (per-channel
   extinction 1 : 4 : 12, the spectral-MIS tracker of appear_ctracker) */
static void nee_case(int chromatic)
{
    static tracer_scene sc;
    tracer_medium m;
    tracer_image a, b;
    tracer_options opt;
    appear_vec3 lo = appear_vec3_make(-1.5f, -0.6f, -0.8f), hi = appear_vec3_make(0.3f, 0.8f, 0.8f);
    int s, c, shapes[3];
    h_case("tracer NEE+MIS vs phase/BSDF sampling alone: equal means per object (%s cloud, chromatic HG sphere, floor)",
           chromatic ? "chromatic heterogeneous" : "grey heterogeneous");
    tracer_scene_init(&sc, "mis");
    sc.env_top = appear_spectrum_rgb(0.2f, 0.25f, 0.3f); sc.env_bottom = appear_spectrum_splat(0.05f);
    shapes[2] = tracer_add_box(&sc, appear_vec3_make(-10, -2.0f, -10), appear_vec3_make(10, -1.0f, 10),
                               tracer_add_material(&sc, tracer_mat_lambert(appear_spectrum_splat(0.5f))), -1);
    tracer_add_sphere_light(&sc, appear_vec3_make(1.0f, 3.0f, 1.0f), 1.2f, appear_spectrum_rgb(6.0f, 5.0f, 4.0f));
    memset(&m, 0, sizeof m);
#if TRACER_HAS_TRACKERS
    m.kind = MED_CLOUD; m.lo = lo; m.hi = hi; m.sigma_max = 6.0f; m.albedo = appear_spectrum_splat(0.9f);
    if (chromatic) {
        m.kind = MED_CLOUD_CHROMATIC; m.sigma_t = appear_spectrum_rgb(1.0f, 4.0f, 12.0f);
        m.albedo = appear_spectrum_rgb(0.95f, 0.7f, 0.3f);
    }
#else
    (void)chromatic;
    m.kind = MED_HOMOGENEOUS; m.sigma_t = appear_spectrum_splat(2.0f); m.albedo = appear_spectrum_splat(0.9f);
#endif
    m.phase = appear_phase_hg(appear_hg_make(0.5f));
    shapes[0] = tracer_add_box(&sc, lo, hi, tracer_add_material(&sc, tracer_mat_none()), tracer_add_medium(&sc, m));
    memset(&m, 0, sizeof m);
    m.kind = MED_HOMOGENEOUS; m.sigma_t = appear_spectrum_rgb(1.0f, 3.0f, 6.0f); m.albedo = appear_spectrum_rgb(0.95f, 0.8f, 0.6f);
    m.phase = appear_phase_hg(appear_hg_make(-0.3f));
    shapes[1] = tracer_add_sphere(&sc, appear_vec3_make(1.2f, 0.0f, 0.0f), 0.7f, tracer_add_material(&sc, tracer_mat_none()),
                                  tracer_add_medium(&sc, m));
    sc.eye = appear_vec3_make(0, 0.8f, 4.5f); sc.look = appear_vec3_make(0, -0.2f, 0); sc.fov = 0.8f;
    memset(&opt, 0, sizeof opt);
    opt.w = h_quick() ? 24 : 48; opt.h = h_quick() ? 18 : 36;
    opt.spp = h_quick() ? 32 : 128; opt.threads = 2; opt.seed = 3;
    if (tracer_render(&sc, &opt, &a)) { h_fail("render failed"); return; }
    opt.no_nee = 1; opt.seed = 4;
    if (tracer_render(&sc, &opt, &b)) { h_fail("render failed"); tracer_image_free(&a); return; }
    H_CHECK(a.nonfinite == 0 && b.nonfinite == 0, "non-finite samples: %ld with NEE, %ld without", a.nonfinite, b.nonfinite);
    for (s = 0; s < 3; ++s)
        for (c = 0; c < 3; ++c) {
            obj_stats sa = stats_of(&a, shapes[s], c, opt.spp), sb = stats_of(&b, shapes[s], c, opt.spp);
            double se = sqrt(sa.se * sa.se + sb.se * sb.se), d = sa.mean - sb.mean;
            if (sa.n < 10) { h_fail("object %d: only %ld pixels", s, sa.n); continue; }
            H_CHECK(fabs(d) <= 5 * se + 1e-4, "object %d ch%d: NEE %.5f vs no NEE %.5f, difference %.2f se", s, c, sa.mean, sb.mean,
                    se > 0 ? d / se : 0.0);
            if (c == 0)
                h_measure("tracer nee/mis", "object %d (%s): NEE %.4f (se %.1e) vs phase/BSDF only %.4f (se %.1e): %.2f se; variance ratio %.1f",
                          s, s == 0 ? "cloud" : s == 1 ? "HG sphere" : "floor", sa.mean, sa.se, sb.mean, sb.se, se > 0 ? d / se : 0.0,
                          sa.se > 0 ? (sb.se * sb.se) / (sa.se * sa.se) : 0.0);
        }
    tracer_image_free(&a);
    tracer_image_free(&b);
}

/* ---- every demo scene builds, with valid materials ---- */
static void scenes_case(void)
{
    static tracer_scene sc;
    int k, i, n = 0;
    h_case("tracer scenes: every listed scene (and layered_ref) builds, states its expectation, "
           "has valid materials");
    while (tracer_scene_names[n]) ++n;
    for (k = 0; k < n + TRACER_HAS_LAYERED; ++k) { /* the list, then the unlisted layered_ref */
        const char *name = k < n ? tracer_scene_names[k] : "layered_ref";
        if (tracer_scene_build(&sc, name)) { h_fail("scene %s does not build", name); continue; }
        H_CHECK(tracer_scene_expectation(name)[0] != '\0', "scene %s: no expectation stated", name);
        H_CHECK(sc.n_shapes > 0, "scene %s: no shapes", name);
        for (i = 0; i < sc.n_mats; ++i) {
            const tracer_material *m = &sc.mats[i];
            unsigned f = 1u;
            if (m->kind == MAT_BSDF) f = appear_bsdf_flags(&m->bsdf);
#if TRACER_HAS_MATERIALS
            if (m->kind == MAT_METAL)
                f = (unsigned)appear_conductor_make_metal(m->d, m->named, NULL).valid;
            if (m->kind == MAT_GLASS) {
                float lambda[APPEAR_SPECTRUM_SAMPLES];
                int j;
                for (j = 0; j < APPEAR_SPECTRUM_SAMPLES; ++j)
                    lambda[j] = 400.0f + 100.0f * (float)j;
                f = (unsigned)appear_dielectric_make_dispersive(
                        m->d, appear_dielectric_ior_spectrum(m->named, lambda)).valid;
            }
#endif
#if TRACER_HAS_OPENPBR
            if (m->kind == MAT_OPENPBR) f = appear_openpbr_flags(&m->openpbr);
#endif
#if TRACER_HAS_LAYERED
            if (m->kind == MAT_COATED) f = appear_coated_flags(&m->coated);
            if (m->kind == MAT_LAYERED) {
                appear_rng r = appear_rng_make(1u);
                appear_layered l = tracer_layered_make(&m->layered, &r);
                f = appear_layered_flags(&l);
            }
#endif
            H_CHECK(f != 0u, "scene %s: material %d (kind %d) is invalid (flags 0)", name, i,
                    m->kind);
        }
    }
}

#if TRACER_HAS_LAYERED || TRACER_HAS_OPENPBR
/* ---- layered materials and OpenPBR: light samples vs BSDF sampling alone ---- */
/* "layered_ref": the reference walk, a stochastic model (noisy eval and pdf): the tracer joins no
   MIS at its vertices (light samples alone, weight 1; a BSDF-sampled path that hits the light
   after a non-delta event adds nothing). "layered": appear_coated, exact pdf, NEE + MIS.
   "openpbr": the presets (appear_openpbr's mixture pdf), NEE + MIS, 64 spp (the 256 of the
   layered pair at twice the height would take 2.5 s). Either way the image must equal the one by
   BSDF sampling alone (no NEE): per sphere and channel the means within 5 combined standard
   errors. */
static void nee_vs_bsdf_case(const char *name)
{
    static tracer_scene sc;
    tracer_image a, b;
    tracer_options opt;
    int s, c, pbr = !strcmp(name, "openpbr");
    h_case("tracer %s: NEE (%s) vs BSDF sampling alone: equal means per sphere", name,
           strcmp(name, "layered_ref") ? "MIS" : "light samples alone at the stochastic walk");
    if (tracer_scene_build(&sc, name)) { h_fail("no %s scene", name); return; }
    /* the light wider (radius 2: clear of the floor and the view), as bright in all: BSDF
       sampling alone finds it more often */
    {
        tracer_shape *l = &sc.shapes[sc.light];
        float k = l->r / 2.0f;
        l->r = 2.0f;
        sc.mats[l->material].emission = appear_spectrum_scale(sc.mats[l->material].emission, k * k);
    }
    memset(&opt, 0, sizeof opt);
    opt.w = h_quick() ? 60 : 120; opt.h = (h_quick() ? 18 : 36) * (pbr ? 2 : 1);
    opt.spp = h_quick() ? 32 : pbr ? 64 : 256; opt.threads = 2; opt.seed = 5;
    if (tracer_render(&sc, &opt, &a)) { h_fail("render failed"); return; }
    opt.no_nee = 1; opt.seed = 6;
    if (tracer_render(&sc, &opt, &b)) { h_fail("render failed"); tracer_image_free(&a); return; }
    H_CHECK(a.nonfinite == 0 && b.nonfinite == 0, "non-finite samples: %ld with NEE, %ld without",
            a.nonfinite, b.nonfinite);
    for (s = 0; s < sc.n_shapes; ++s) {
        const char *lab = sc.shapes[s].label;
        if (!lab) continue; /* the floor, the light */
        for (c = 0; c < 3; ++c) {
            obj_stats sa = stats_of(&a, s, c, opt.spp), sb = stats_of(&b, s, c, opt.spp);
            double se = sqrt(sa.se * sa.se + sb.se * sb.se), d = sa.mean - sb.mean;
            if (sa.n < 10) { h_fail("%s: only %ld pixels", lab, sa.n); continue; }
            H_CHECK(fabs(d) <= 5 * se + 1e-4, "%s ch%d: NEE %.5f vs no NEE %.5f, %.2f se", lab, c,
                    sa.mean, sb.mean, se > 0 ? d / se : 0.0);
            if (c == 0)
                h_measure(pbr ? "tracer openpbr" : "tracer layered",
                          "%s %-22s: NEE %.4f (se %.1e) vs BSDF only %.4f (se %.1e): %.2f se",
                          name, lab, sa.mean, sa.se, sb.mean, sb.se, se > 0 ? d / se : 0.0);
        }
    }
    tracer_image_free(&a);
    tracer_image_free(&b);
}
#endif

#if TRACER_HAS_MATERIALS
/* ---- spectral mode ---- */
/* The tracer's colour integrals (midpoint rule, 0.1 nm: the integrands are smooth within each
   5 nm row) against the white and against appear_metal_to_rgb's F0, which tests/gen/
   gen_materials.c integrates at 1 nm from the 1 nm observer: the difference is the 5 nm rows'
   (and D65 as the light: any other illuminant would show here). */
static const int spectral_metals[6] = { APPEAR_METAL_AU, APPEAR_METAL_CU, APPEAR_METAL_AL,
                                        APPEAR_METAL_AG, APPEAR_METAL_CR, APPEAR_METAL_TI };
static const char *const spectral_metal_names[6] = { "Au", "Cu", "Al", "Ag", "Cr", "Ti" };
static void spectral_colour_case(void)
{
    const double step = 0.1;
    double white[3] = { 0, 0, 0 }, f0[6][3], worst = 0;
    int i, m, c, n = (int)((TRACER_LAMBDA_MAX - TRACER_LAMBDA_MIN) / step + 0.5);
    h_case("tracer spectral colour: D65 x CIE 1931 gives RGB 1; metals' F0 as appear_metal_to_rgb");
    memset(f0, 0, sizeof f0);
    for (i = 0; i < n; ++i) {
        float lambda = TRACER_LAMBDA_MIN + (float)((i + 0.5) * step), illum, bar[3];
        tracer_spectral_colour(lambda, &illum, bar);
        for (c = 0; c < 3; ++c) white[c] += step * illum * bar[c];
        for (m = 0; m < 6; ++m) {
            float eta, k, f;
            appear_metal_eta_k(spectral_metals[m], lambda, &eta, &k);
            f = appear_fresnel_conductor(1.0f, eta, k);
            for (c = 0; c < 3; ++c) f0[m][c] += step * f * illum * bar[c];
        }
    }
    for (c = 0; c < 3; ++c)
        H_CHECK(fabs(white[c] - 1.0) <= 1e-4, "white ch%d: %.6f, expected 1", c, white[c]);
    for (m = 0; m < 6; ++m) {
        appear_metal_rgb r = appear_metal_to_rgb(spectral_metals[m]);
        for (c = 0; c < 3; ++c) { /* the stored F0 is clipped into [0, 1] (gold's red) */
            double got = f0[m][c] < 1.0 ? f0[m][c] : 1.0, d = fabs(got - r.f0[c]);
            worst = d > worst ? d : worst;
            H_CHECK(d <= 1e-3, "%s ch%d: F0 %.5f, appear_metal_to_rgb %.5f",
                    spectral_metal_names[m], c, got, r.f0[c]);
        }
    }
    h_measure("tracer spectral", "white (%.6f, %.6f, %.6f); six metals' F0 within %.2e of "
              "appear_metal_to_rgb's", white[0], white[1], white[2], worst);
}

/* A white furnace in spectral mode (each object alone in an environment of radiance 1, D65):
   Lambert R = 1 and a smooth SF11 sphere (dispersive: every refraction terminates the secondary
   wavelengths, so 1 only if the hero then counts n times) render 1 per channel; then the six
   metals (GGX alpha 0.25), once spectral and once RGB (appear_metal_to_rgb's eta, k): one bounce
   or a few off one sphere, so the two differ only by the RGB form's error, the clip of gold's red
   F0 (1.0375 to 1) above all. Bound per channel: 5 standard errors plus 0.5% (4% for gold's
   red). */
static void spectral_furnace_case(void)
{
    static tracer_scene sc;
    tracer_image spec, rgb;
    tracer_options opt;
    const int vis = APPEAR_SAMPLE_VISIBLE;
    appear_microfacet smooth = appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f, vis);
    appear_microfacet rough = appear_microfacet_make(APPEAR_GGX, 0.25f, 0.25f, vis);
    tracer_material lambert = tracer_mat_lambert(appear_spectrum_splat(1.0f));
    int s, c, m, shapes[8];
    h_case("tracer spectral furnace: Lambert 1 and dispersive SF11 glass render 1; metals' "
           "spectral and RGB renders agree");
    tracer_scene_init(&sc, "spectral furnace");
    shapes[0] = tracer_add_sphere(&sc, appear_vec3_make(-3.5f, 0, 0), 0.48f,
                                  tracer_add_material(&sc, lambert), -1);
    shapes[1] = tracer_add_sphere(
        &sc, appear_vec3_make(-2.5f, 0, 0), 0.48f,
        tracer_add_material(&sc, tracer_mat_glass(smooth, APPEAR_DIELECTRIC_SF11)), -1);
    for (m = 0; m < 6; ++m)
        shapes[2 + m] = tracer_add_sphere(
            &sc, appear_vec3_make(-1.5f + (float)m, 0, 0), 0.48f,
            tracer_add_material(&sc, tracer_mat_metal(rough, spectral_metals[m])), -1);
    sc.isolate = 1;
    sc.eye = appear_vec3_make(0, 0, 14.0f); sc.look = appear_vec3_make(0, 0, 0); sc.fov = 0.09f;
    memset(&opt, 0, sizeof opt);
    opt.w = h_quick() ? 160 : 320; opt.h = h_quick() ? 20 : 40;
    opt.spp = h_quick() ? 32 : 128; opt.threads = 2; opt.seed = 11; opt.spectral = 1;
    if (tracer_render(&sc, &opt, &spec)) { h_fail("spectral render failed"); return; }
    opt.spectral = 0; opt.seed = 12;
    if (tracer_render(&sc, &opt, &rgb)) {
        h_fail("RGB render failed");
        tracer_image_free(&spec);
        return;
    }
    H_CHECK(spec.nonfinite == 0 && rgb.nonfinite == 0, "non-finite samples: %ld spectral, %ld RGB",
            spec.nonfinite, rgb.nonfinite);
    for (s = 0; s < 8; ++s)
        for (c = 0; c < 3; ++c) {
            obj_stats a = stats_of(&spec, shapes[s], c, opt.spp);
            obj_stats b = stats_of(&rgb, shapes[s], c, opt.spp);
            if (a.n < 20) { h_fail("object %d: only %ld pixels", s, a.n); continue; }
            if (s < 2) {
                H_CHECK(fabs(a.mean - 1.0) <= 5.0 * a.se + 2e-4,
                        "%s ch%d: spectral mean %.5f, expected 1 +- %.5f",
                        s ? "SF11 glass" : "Lambert 1", c, a.mean, 5.0 * a.se + 2e-4);
                if (c == 1)
                    h_measure("tracer spectral", "furnace %-10s mean %.5f se %.1e (expect 1)",
                              s ? "SF11 glass" : "Lambert 1", a.mean, a.se);
            } else {
                double se = sqrt(a.se * a.se + b.se * b.se), d = a.mean - b.mean;
                double tol = 5.0 * se + (s == 2 && c == 0 ? 0.04 : 0.005) * b.mean;
                H_CHECK(fabs(d) <= tol, "%s ch%d: spectral %.5f vs RGB %.5f (bound %.5f)",
                        spectral_metal_names[s - 2], c, a.mean, b.mean, tol);
                h_measure("tracer spectral",
                          "furnace %s ch%d: spectral %.4f RGB %.4f: %+.2f%% (se %.2f%%)",
                          spectral_metal_names[s - 2], c, a.mean, b.mean, 100.0 * d / b.mean,
                          100.0 * se / b.mean);
            }
        }
    tracer_image_free(&spec);
    tracer_image_free(&rgb);
}
#endif

#if TRACER_HAS_OPENPBR
/* ---- OpenPBR: the white-furnace scene, emission and opacity ---- */
/* "openpbr_furnace" at a small size: every sphere alone in a white environment. Per sphere and
   channel: expected 1 within 5 standard errors plus the sphere's stated model error (tol: 3e-3
   opaque isotropic, 0.02 anisotropic, 1e-2 translucent; scenes.c); the coat and fuzz over a rough
   glass lose their reflection back inside (appear.h SECTION openpbr): at most 1 + 5 SE, and not
   below 0.84 (measured 0.865 +- 0.002 at the demo's size). */
static void openpbr_furnace_case(void)
{
    static tracer_scene sc;
    tracer_image img;
    tracer_options opt;
    int s, c;
    h_case("tracer openpbr_furnace: the spec's white-furnace configurations render 1 (5 se + the "
           "model's stated error), coat and fuzz over glass in [0.84, 1]");
    if (tracer_scene_build(&sc, "openpbr_furnace")) { h_fail("no openpbr_furnace scene"); return; }
    memset(&opt, 0, sizeof opt);
    opt.w = h_quick() ? 96 : 160; opt.h = h_quick() ? 60 : 100;
    opt.spp = h_quick() ? 16 : 32; opt.threads = 2; opt.seed = 9;
    if (tracer_render(&sc, &opt, &img)) { h_fail("render failed"); return; }
    H_CHECK(img.nonfinite == 0, "%ld non-finite samples", img.nonfinite);
    for (s = 0; s < sc.n_shapes; ++s) {
        const char *lab = sc.shapes[s].label ? sc.shapes[s].label : "?";
        int ex = sc.shapes[s].expect;
        if (ex == TRACER_EXPECT_NONE) continue;
        for (c = 0; c < 3; ++c) {
            obj_stats st = stats_of(&img, s, c, opt.spp);
            double tol = 5.0 * st.se + sc.shapes[s].tol + 2e-4; /* 2e-4: float rounding */
            if (st.n < 20) { h_fail("%s: only %ld pixels", lab, st.n); continue; }
            if (ex == TRACER_EXPECT_ONE)
                H_CHECK(fabs(st.mean - 1.0) <= tol, "%s ch%d: mean %.5f, expected 1 +- %.5f", lab,
                        c, st.mean, tol);
            else
                H_CHECK(st.mean <= 1.0 + tol && st.mean >= 0.84, "%s ch%d: mean %.5f, expected "
                        "in [0.84, 1 + %.5f]", lab, c, st.mean, tol);
            if (c == 1)
                h_measure("tracer openpbr furnace", "%-34s mean %.5f  se %.1e  (expect %s, tol %g)",
                          lab, st.mean, st.se, ex == TRACER_EXPECT_ONE ? "1" : "<= 1",
                          (double)sc.shapes[s].tol);
        }
    }
    tracer_image_free(&img);
}

/* Emission and opacity through the tracer (pixel-centre rays, each sphere alone):
   - an emitter (luminance 2, colour (1, 0.5, 0.25); no coat or fuzz, so the layers pass all of
     it; specular weight 0 and an all but black base) in a black environment: every pixel of the
     sphere is its emission, 2 (1, 0.5, 0.25), to float rounding;
   - the same surface, not emitting, at geometry_opacity 0.25 in a white environment: a camera ray
     crosses the sphere's two surfaces, each passed with probability 0.75 (then it sees 1), else
     it scatters off a base of albedo 1e-6: the sphere's mean is 0.75^2 = 0.5625 within 5
     standard errors (a Bernoulli pixel). */
static void openpbr_emission_opacity_case(void)
{
    static tracer_scene sc;
    appear_openpbr_params p = appear_openpbr_params_default();
    tracer_image img;
    tracer_options opt;
    long i, bad = 0, n = 0;
    int k, s;
    h_case("tracer openpbr: emission renders luminance x colour; opacity 0.25 passes 0.75 of "
           "the light at a surface");
    p.base_color = appear_spectrum_splat(1e-6f);
    p.specular_weight = 0.0f;
    p.emission_luminance = 2.0f;
    p.emission_color = appear_spectrum_rgb(1.0f, 0.5f, 0.25f);
    memset(&opt, 0, sizeof opt);
    opt.w = 32; opt.h = 32; opt.spp = 4; opt.threads = 2; opt.seed = 13; opt.pixel_centre = 1;
    for (k = 0; k < 2; ++k) {
        tracer_scene_init(&sc, k ? "openpbr opacity" : "openpbr emission");
        sc.env_top = sc.env_bottom = appear_spectrum_splat(k ? 1.0f : 0.0f);
        if (k) {
            p.emission_luminance = 0.0f;
            p.geometry_opacity = 0.25f;
            opt.spp = 64;
        }
        s = tracer_add_openpbr_sphere(&sc, appear_vec3_make(0, 0, 0), 1.0f, &p);
        sc.isolate = 1;
        if (tracer_render(&sc, &opt, &img)) { h_fail("render failed"); return; }
        H_CHECK(img.nonfinite == 0, "%ld non-finite samples", img.nonfinite);
        if (!k) {
            for (i = 0, n = 0, bad = 0; i < (long)img.w * img.h; ++i) {
                const float want[3] = { 2.0f, 1.0f, 0.5f };
                int c;
                if (img.id[i] != s) continue;
                ++n;
                for (c = 0; c < 3; ++c) bad += fabsf(img.rgb[3 * i + c] - want[c]) > 1e-5f;
            }
            H_CHECK(n > 100 && bad == 0, "emission: %ld of %ld pixels' channels off 2 (1, 0.5, "
                    "0.25)", bad, n);
        } else {
            obj_stats st = stats_of(&img, s, 1, opt.spp);
            double tol = 5.0 * st.se + 1e-5;
            H_CHECK(st.n > 100 && fabs(st.mean - 0.5625) <= tol, "opacity 0.25: mean %.5f, "
                    "expected 0.5625 +- %.5f", st.mean, tol);
            h_measure("tracer openpbr", "emission: %ld pixels exact; opacity 0.25: mean %.5f "
                      "(se %.1e, expect 0.75^2 = 0.5625)", n, st.mean, st.se);
        }
        tracer_image_free(&img);
    }
}

/* The interior medium through the tracer: a smooth glass sphere (n 1.5, F0 0.04) of radius 1
   around an absorbing medium (transmission_color (0.5, 0.25, 1) at depth 1: T = colour^2 across
   the diameter) in a white environment, one pixel-centre ray through its centre. Along the
   diameter every event is at normal incidence: R0 + (1 - R0)^2 T / (1 - R0 T) (the reflection,
   then the light that enters and leaves after k - 1 internal reflections). Per channel within 5
   standard errors: a refraction must carry the path into and out of the medium. */
static void openpbr_medium_case(void)
{
    static tracer_scene sc;
    appear_openpbr_params p = appear_openpbr_params_default();
    const double col[3] = { 0.5, 0.25, 1.0 }, r0 = 0.04;
    tracer_image img;
    tracer_options opt;
    int c, s;
    h_case("tracer openpbr: a glass around an absorbing medium, along its diameter: "
           "R0 + (1 - R0)^2 T / (1 - R0 T)");
    p.specular_roughness = 0.0f;
    p.specular_ior = 1.5f;
    p.transmission_weight = 1.0f;
    p.transmission_color = appear_spectrum_rgb(0.5f, 0.25f, 1.0f);
    p.transmission_depth = 1.0f;
    tracer_scene_init(&sc, "openpbr medium");
    s = tracer_add_openpbr_sphere(&sc, appear_vec3_make(0, 0, 0), 1.0f, &p);
    H_CHECK(s >= 0 && sc.shapes[s].medium >= 0, "the sphere has no interior medium");
    sc.isolate = 1;
    memset(&opt, 0, sizeof opt);
    opt.w = 1; opt.h = 1; opt.spp = h_quick() ? 20000 : 100000; opt.threads = 1; opt.seed = 17;
    opt.pixel_centre = 1;
    if (tracer_render(&sc, &opt, &img)) { h_fail("render failed"); return; }
    H_CHECK(img.nonfinite == 0 && img.id[0] == s, "%ld non-finite samples; hit %d", img.nonfinite,
            img.id[0]);
    for (c = 0; c < 3; ++c) {
        double t = col[c] * col[c], want = r0 + (1 - r0) * (1 - r0) * t / (1 - r0 * t);
        double se = sqrt(img.var[c] / opt.spp);
        H_CHECK(fabs(img.rgb[c] - want) <= 5.0 * se + 1e-4, "ch%d: %.5f, expected %.5f (se %.1e)",
                c, img.rgb[c], want, se);
        h_measure("tracer openpbr", "medium ch%d: %.5f (se %.1e), expected %.5f", c, img.rgb[c],
                  se, want);
    }
    tracer_image_free(&img);
}
#endif

void suite_tracer(void)
{
    scenes_case();
#if TRACER_HAS_LAYERED
    nee_vs_bsdf_case("layered");
    nee_vs_bsdf_case("layered_ref");
#endif
    furnace_case();
    absorber_case();
    nee_case(0);
#if TRACER_HAS_TRACKERS
    nee_case(1);
#endif
#if TRACER_HAS_MATERIALS
    spectral_colour_case();
    spectral_furnace_case();
#endif
#if TRACER_HAS_OPENPBR
    openpbr_furnace_case();
    openpbr_emission_opacity_case();
    openpbr_medium_case();
    nee_vs_bsdf_case("openpbr");
#endif
}
