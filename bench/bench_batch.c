/* bench/bench_batch.c - the structure-of-arrays entry points (SECTION batch)
   against their scalar twins, in one run: for each batched function, ns per
   element of
     scalar  a loop calling the scalar function, one element at a time,
             writing its record to arrays (what a renderer's per-ray loop does);
     batch   the *_batch entry point on the same pre-drawn arrays,
   and "bit-identical" = how many output values differ between the two
   (must be 0 in every build; tests/test_batch.c asserts it in the test build).
   For GGX visible-normal sampling also the plain Heitz 2018 transcription
   (JCGT 7(4), listing 1) with libm sqrtf/sinf/cosf, the speed baseline,
   and the max error of the batch sampler against the same algorithm
   (Dupuy-Benyoub spherical caps) evaluated in double: max over elements of
   max |m_float - m_double| per component. */
#include "bench.h"
#include "../tests/listings.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

#define BB_N 16384
#define S_ APPEAR_SPECTRUM_SAMPLES
static float bb_wox[BB_N], bb_woy[BB_N], bb_woz[BB_N], bb_wix[BB_N], bb_wiy[BB_N], bb_wiz[BB_N];
static float bb_uc[BB_N], bb_u1[BB_N], bb_u2[BB_N], bb_d[BB_N];
static float bb_ox[BB_N], bb_oy[BB_N], bb_oz[BB_N], bb_op[BB_N], bb_ow[S_ * BB_N];
static float bb_sx[BB_N], bb_sy[BB_N], bb_sz[BB_N], bb_sp[BB_N], bb_sw[S_ * BB_N]; /* scalar loop outputs */
static unsigned bb_ofl[BB_N], bb_sfl[BB_N];
static int bb_osc[BB_N], bb_ssc[BB_N];

static const float bb_ax = 0.3f, bb_ay = 0.15f;

/* ---- the baseline: Heitz 2018, listing 1, transcribed plainly (float, libm): tests/listings.h ---- */

/* the spherical-caps sampler of appear_ggx_sample_visible, in double: p's
   azimuth is phi_v + pi - 2 pi u1 (phi_v: azimuth of the stretched wo), as
   in appear__ggx_caps_core; h = p + v plainly (double keeps the digits). */
static void bb_caps_double(double ax, double ay, double wx, double wy, double wz, double u1, double u2,
                           double *m)
{
    double vx = ax * wx, vy = ay * wy, vz = wz, l = sqrt(vx * vx + vy * vy + vz * vz), c, phi, z, st, hx, hy, hz;
    vx /= l; vy /= l; vz /= l; c = vz;
    phi = (vx != 0.0 || vy != 0.0 ? atan2(vy, vx) : 0.0) + 3.141592653589793 - 6.283185307179586 * u1;
    z = (1.0 - u2) * (1.0 + c) - c;
    st = sqrt(fmax(0.0, 1.0 - z * z));
    hx = ax * (st * cos(phi) + vx); hy = ay * (st * sin(phi) + vy); hz = fmax(z + c, 0.0);
    l = sqrt(hx * hx + hy * hy + hz * hz);
    m[0] = hx / l; m[1] = hy / l; m[2] = hz / l;
}

/* Heitz 2018 listing 1 in double (reference for the baseline's own error) */
static void bb_heitz_double(double ax, double ay, double wx, double wy, double wz, double U1, double U2, double *m)
{
    double vx = ax * wx, vy = ay * wy, vz = wz, l = sqrt(vx * vx + vy * vy + vz * vz), lensq, t1x, t1y, t2x, t2y, t2z;
    double r, phi, t1, t2, s, h, nx, ny, nz;
    vx /= l; vy /= l; vz /= l;
    lensq = vx * vx + vy * vy;
    t1x = lensq > 0 ? -vy / sqrt(lensq) : 1.0; t1y = lensq > 0 ? vx / sqrt(lensq) : 0.0;
    t2x = -vz * t1y; t2y = vz * t1x; t2z = vx * t1y - vy * t1x;          /* cross(Vh, T1), T1.z = 0 */
    r = sqrt(U1); phi = 2.0 * 3.14159265358979323846 * U2;
    t1 = r * cos(phi); t2 = r * sin(phi); s = 0.5 * (1.0 + vz);
    t2 = (1.0 - s) * sqrt(1.0 - t1 * t1) + s * t2;
    h = sqrt(fmax(0.0, 1.0 - t1 * t1 - t2 * t2));
    nx = ax * (t1 * t1x + t2 * t2x + h * vx); ny = ay * (t1 * t1y + t2 * t2y + h * vy); nz = fmax(0.0, t2 * t2z + h * vz);
    l = sqrt(nx * nx + ny * ny + nz * nz);
    m[0] = nx / l; m[1] = ny / l; m[2] = nz / l;
}

/* ---- loops ---- */
static void bb_sink3(void) { b_sink = bb_ox[BB_N / 2] + bb_sx[BB_N / 3] + bb_op[BB_N / 5] + bb_sp[BB_N / 7]; }
#define BB_WO(i) appear_vec3_make(bb_wox[i], bb_woy[i], bb_woz[i])
#define BB_WI(i) appear_vec3_make(bb_wix[i], bb_wiy[i], bb_wiz[i])

static void bb_heitz_loop(void *ctx) { int i; (void)ctx;
    for (i = 0; i < BB_N; ++i) { appear_vec3 m = lst_heitz18_vndf(BB_WO(i), bb_ax, bb_ay, bb_u1[i], bb_u2[i]);
        bb_sx[i] = m.x; bb_sy[i] = m.y; bb_sz[i] = m.z; } bb_sink3(); }
static void bb_ggx_s(void *ctx) { int i; (void)ctx;
    for (i = 0; i < BB_N; ++i) { appear_vec3 m = appear_ggx_sample_visible(bb_ax, bb_ay, BB_WO(i), bb_u1[i], bb_u2[i]);
        bb_sx[i] = m.x; bb_sy[i] = m.y; bb_sz[i] = m.z; } bb_sink3(); }
static void bb_ggx_b(void *ctx) { (void)ctx;
    appear_ggx_sample_visible_batch(bb_ax, bb_ay, bb_wox, bb_woy, bb_woz, bb_u1, bb_u2, bb_ox, bb_oy, bb_oz, BB_N); bb_sink3(); }
static void bb_sc_s(void *ctx) { int i; (void)ctx;
    for (i = 0; i < BB_N; ++i) { float s, c; appear_sincos_2pi(bb_u1[i], &s, &c); bb_sx[i] = s; bb_sy[i] = c; } bb_sink3(); }
static void bb_sc_b(void *ctx) { (void)ctx; appear_sincos_2pi_batch(bb_u1, bb_ox, bb_oy, BB_N); bb_sink3(); }
static void bb_hg_s(void *ctx) { int i; (void)ctx;
    for (i = 0; i < BB_N; ++i) { appear_phase_record s; appear_hg_sample_g(0.7f, BB_WO(i), bb_u1[i], bb_u2[i], &s);
        bb_sx[i] = s.wi.x; bb_sy[i] = s.wi.y; bb_sz[i] = s.wi.z; bb_sp[i] = s.pdf; } bb_sink3(); }
static void bb_hg_b(void *ctx) { (void)ctx;
    appear_hg_sample_batch_g(0.7f, bb_wox, bb_woy, bb_woz, bb_u1, bb_u2, bb_ox, bb_oy, bb_oz, bb_op, BB_N); bb_sink3(); }
static void bb_hge_s(void *ctx) { int i; (void)ctx;
    for (i = 0; i < BB_N; ++i) { bb_sp[i] = appear_hg_eval_g(0.7f, BB_WO(i), BB_WI(i)); } bb_sink3(); }
static void bb_hge_b(void *ctx) { (void)ctx;
    appear_hg_eval_batch_g(0.7f, bb_wox, bb_woy, bb_woz, bb_wix, bb_wiy, bb_wiz, bb_op, BB_N); bb_sink3(); }

/* BSDF samplers: one generic scalar loop through a function pointer would
   block inlining, so a macro writes each pair */
static void bb_put(int i, const appear_bsdf_record *s)
{ int k; bb_sx[i] = s->wi.x; bb_sy[i] = s->wi.y; bb_sz[i] = s->wi.z; bb_sp[i] = s->pdf;
  for (k = 0; k < S_; ++k) { bb_sw[k * BB_N + i] = s->weight.v[k]; } bb_sfl[i] = s->flags; }
#define BB_BSDF_PAIR(name, T, make_expr, scalar, batch) \
    static T name##_m; \
    static void name##_s(void *ctx) { int i; (void)ctx; for (i = 0; i < BB_N; ++i) { appear_bsdf_record s; \
        scalar(&name##_m, BB_WO(i), bb_uc[i], bb_u1[i], bb_u2[i], &s); bb_put(i, &s); } bb_sink3(); } \
    static void name##_b(void *ctx) { (void)ctx; batch(&name##_m, bb_wox, bb_woy, bb_woz, bb_uc, bb_u1, bb_u2, \
        bb_ox, bb_oy, bb_oz, bb_op, bb_ow, bb_ofl, BB_N); bb_sink3(); } \
    static void name##_init(void) { name##_m = make_expr; }

static void bb_lambert_sample(const appear_lambert *m, appear_vec3 wo, float uc, float u1, float u2, appear_bsdf_record *s)
{ appear_lambert_sample(m, wo, uc, u1, u2, s); }
static void bb_lambert_batch(const appear_lambert *m, const float *wx, const float *wy, const float *wz, const float *uc,
                             const float *u1, const float *u2, float *ox, float *oy, float *oz, float *op, float *ow,
                             unsigned *fl, int n)
{ (void)uc; appear_lambert_sample_batch(m, wx, wy, wz, u1, u2, ox, oy, oz, op, ow, fl, n); }
BB_BSDF_PAIR(bb_lam, appear_lambert, appear_lambert_make(appear_spectrum_rgb(0.2f, 0.5f, 0.8f)), bb_lambert_sample, bb_lambert_batch)
#ifndef APPEAR_NO_EON
static void bb_eon_sample(const appear_eon *m, appear_vec3 wo, float uc, float u1, float u2, appear_bsdf_record *s)
{ appear_eon_sample(m, wo, uc, u1, u2, s); }
static void bb_eon_batch(const appear_eon *m, const float *wx, const float *wy, const float *wz, const float *uc,
                         const float *u1, const float *u2, float *ox, float *oy, float *oz, float *op, float *ow,
                         unsigned *fl, int n)
{ (void)uc; appear_eon_sample_batch(m, wx, wy, wz, u1, u2, ox, oy, oz, op, ow, fl, n); }
BB_BSDF_PAIR(bb_eon, appear_eon, appear_eon_make(appear_spectrum_rgb(0.2f, 0.5f, 0.8f), 0.7f), bb_eon_sample, bb_eon_batch)
static void bb_eone_s(void *ctx) { int i, k; (void)ctx;
    for (i = 0; i < BB_N; ++i) { appear_spectrum f = appear_eon_eval(&bb_eon_m, BB_WO(i), BB_WI(i));
        for (k = 0; k < S_; ++k) bb_sw[k * BB_N + i] = f.v[k]; } bb_sink3(); }
static void bb_eone_b(void *ctx) { (void)ctx;
    appear_eon_eval_batch(&bb_eon_m, bb_wox, bb_woy, bb_woz, bb_wix, bb_wiy, bb_wiz, bb_ow, BB_N); bb_sink3(); }
static void bb_eonp_s(void *ctx) { int i; (void)ctx;
    for (i = 0; i < BB_N; ++i) { bb_sp[i] = appear_eon_pdf(&bb_eon_m, BB_WO(i), BB_WI(i)); } bb_sink3(); }
static void bb_eonp_b(void *ctx) { (void)ctx;
    appear_eon_pdf_batch(&bb_eon_m, bb_wox, bb_woy, bb_woz, bb_wix, bb_wiy, bb_wiz, bb_op, BB_N); bb_sink3(); }
#endif
#ifndef APPEAR_NO_SHEEN
static void bb_sheen_sample(const appear_sheen *m, appear_vec3 wo, float uc, float u1, float u2, appear_bsdf_record *s)
{ appear_sheen_sample(m, wo, uc, u1, u2, s); }
static void bb_sheen_batch(const appear_sheen *m, const float *wx, const float *wy, const float *wz, const float *uc,
                           const float *u1, const float *u2, float *ox, float *oy, float *oz, float *op, float *ow,
                           unsigned *fl, int n)
{ (void)uc; appear_sheen_sample_batch(m, wx, wy, wz, u1, u2, ox, oy, oz, op, ow, fl, n); }
BB_BSDF_PAIR(bb_sheen, appear_sheen, appear_sheen_make(appear_spectrum_rgb(0.9f, 0.6f, 0.3f), 0.5f), bb_sheen_sample,
             bb_sheen_batch)
static void bb_sheene_s(void *ctx) { int i, k; (void)ctx;
    for (i = 0; i < BB_N; ++i) { appear_spectrum f = appear_sheen_eval(&bb_sheen_m, BB_WO(i), BB_WI(i));
        for (k = 0; k < S_; ++k) bb_sw[k * BB_N + i] = f.v[k]; } bb_sink3(); }
static void bb_sheene_b(void *ctx) { (void)ctx;
    appear_sheen_eval_batch(&bb_sheen_m, bb_wox, bb_woy, bb_woz, bb_wix, bb_wiy, bb_wiz, bb_ow, BB_N); bb_sink3(); }
static void bb_sheenp_s(void *ctx) { int i; (void)ctx;
    for (i = 0; i < BB_N; ++i) { bb_sp[i] = appear_sheen_pdf(&bb_sheen_m, BB_WO(i), BB_WI(i)); } bb_sink3(); }
static void bb_sheenp_b(void *ctx) { (void)ctx;
    appear_sheen_pdf_batch(&bb_sheen_m, bb_wox, bb_woy, bb_woz, bb_wix, bb_wiy, bb_wiz, bb_op, BB_N); bb_sink3(); }
#endif
#ifndef APPEAR_NO_MICROFACET
BB_BSDF_PAIR(bb_cond, appear_conductor, appear_conductor_make(appear_microfacet_make(APPEAR_GGX, bb_ax, bb_ay, APPEAR_SAMPLE_VISIBLE),
             appear_spectrum_rgb(0.2f, 0.9f, 1.1f), appear_spectrum_rgb(3.9f, 2.4f, 2.2f)), appear_conductor_sample, appear_conductor_sample_batch)
BB_BSDF_PAIR(bb_diel, appear_dielectric, appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, bb_ax, bb_ay, APPEAR_SAMPLE_VISIBLE), 1.5f),
             appear_dielectric_sample, appear_dielectric_sample_batch)
static void bb_beck_s(void *ctx) { int i; (void)ctx;
    for (i = 0; i < BB_N; ++i) { appear_vec3 m = appear_beckmann_sample_visible(bb_ax, bb_ay, BB_WO(i), bb_u1[i], bb_u2[i]);
        bb_sx[i] = m.x; bb_sy[i] = m.y; bb_sz[i] = m.z; } bb_sink3(); }
static void bb_beck_b(void *ctx) { (void)ctx;
    appear_beckmann_sample_visible_batch(bb_ax, bb_ay, bb_wox, bb_woy, bb_woz, bb_u1, bb_u2, bb_ox, bb_oy, bb_oz, BB_N); bb_sink3(); }
static void bb_conde_s(void *ctx) { int i, k; (void)ctx;
    for (i = 0; i < BB_N; ++i) { appear_spectrum f = appear_conductor_eval(&bb_cond_m, BB_WO(i), BB_WI(i));
        for (k = 0; k < S_; ++k) bb_sw[k * BB_N + i] = f.v[k]; } bb_sink3(); }
static void bb_conde_b(void *ctx) { (void)ctx;
    appear_conductor_eval_batch(&bb_cond_m, bb_wox, bb_woy, bb_woz, bb_wix, bb_wiy, bb_wiz, bb_ow, BB_N); bb_sink3(); }
static void bb_condp_s(void *ctx) { int i; (void)ctx;
    for (i = 0; i < BB_N; ++i) { bb_sp[i] = appear_conductor_pdf(&bb_cond_m, BB_WO(i), BB_WI(i)); } bb_sink3(); }
static void bb_condp_b(void *ctx) { (void)ctx;
    appear_conductor_pdf_batch(&bb_cond_m, bb_wox, bb_woy, bb_woz, bb_wix, bb_wiy, bb_wiz, bb_op, BB_N); bb_sink3(); }
static void bb_diele_s(void *ctx) { int i, k; (void)ctx;
    for (i = 0; i < BB_N; ++i) { appear_spectrum f = appear_dielectric_eval(&bb_diel_m, BB_WO(i), BB_WI(i));
        for (k = 0; k < S_; ++k) bb_sw[k * BB_N + i] = f.v[k]; } bb_sink3(); }
static void bb_diele_b(void *ctx) { (void)ctx;
    appear_dielectric_eval_batch(&bb_diel_m, bb_wox, bb_woy, bb_woz, bb_wix, bb_wiy, bb_wiz, bb_ow, BB_N); bb_sink3(); }
static void bb_dielp_s(void *ctx) { int i; (void)ctx;
    for (i = 0; i < BB_N; ++i) { bb_sp[i] = appear_dielectric_pdf(&bb_diel_m, BB_WO(i), BB_WI(i)); } bb_sink3(); }
static void bb_dielp_b(void *ctx) { (void)ctx;
    appear_dielectric_pdf_batch(&bb_diel_m, bb_wox, bb_woy, bb_woz, bb_wix, bb_wiy, bb_wiz, bb_op, BB_N); bb_sink3(); }
#endif
#ifndef APPEAR_NO_WARD
BB_BSDF_PAIR(bb_ward, appear_ward, appear_ward_make(appear_spectrum_splat(0.2f), appear_spectrum_splat(0.5f), bb_ax, bb_ay, APPEAR_WARD_BALANCED),
             appear_ward_sample, appear_ward_sample_batch)
#endif
#ifndef APPEAR_NO_MEDIA
static appear_spectrum bb_sigma;
static void bb_hom_s(void *ctx) { int i, k; (void)ctx;
    for (i = 0; i < BB_N; ++i) { appear_medium_sample s; appear_homogeneous_sample(bb_sigma, bb_d[i], bb_uc[i], bb_u1[i], &s);
        bb_sx[i] = s.t; bb_ssc[i] = s.scattered; bb_sp[i] = s.pdf; for (k = 0; k < S_; ++k) bb_sw[k * BB_N + i] = s.weight.v[k]; }
    bb_sink3(); }
static void bb_hom_b(void *ctx) { (void)ctx;
    appear_homogeneous_sample_batch(bb_sigma, bb_d, bb_uc, bb_u1, bb_ox, bb_osc, bb_op, bb_ow, BB_N); bb_sink3(); }
#endif

/* number of output values that differ in their bits between the scalar
   loop's arrays and the batch's arrays (which = bit mask of outputs used) */
enum { BB_XYZ = 1, BB_P = 2, BB_W = 4, BB_FL = 8, BB_SC = 16, BB_X = 32, BB_XY = 64 };
static long bb_diff(int which)
{
    long bad = 0; int i, k;
    for (i = 0; i < BB_N; ++i) {
        if (which & (BB_XYZ | BB_X | BB_XY)) bad += memcmp(&bb_ox[i], &bb_sx[i], 4) != 0;
        if (which & (BB_XYZ | BB_XY)) bad += memcmp(&bb_oy[i], &bb_sy[i], 4) != 0;
        if (which & BB_XYZ) bad += memcmp(&bb_oz[i], &bb_sz[i], 4) != 0;
        if (which & BB_P) bad += memcmp(&bb_op[i], &bb_sp[i], 4) != 0;
        if (which & BB_W) for (k = 0; k < S_; ++k) bad += memcmp(&bb_ow[k * BB_N + i], &bb_sw[k * BB_N + i], 4) != 0;
        if (which & BB_FL) bad += bb_ofl[i] != bb_sfl[i];
        if (which & BB_SC) bad += bb_osc[i] != bb_ssc[i];
    }
    return bad;
}

static void bb_pair(const char *name, void (*s)(void *), void (*b)(void *), int which, double err, const char *extra)
{
    double ts, tb; long bad; char nm[96], note[260];
    s(0); b(0); bad = bb_diff(which);
    ts = b_time(s, 0, BB_N); tb = b_time(b, 0, BB_N);
    /* "vectorised" is read off the speed-up: >= 2x means the batch loop runs
       several elements per instruction and the scalar loop does not; below,
       both or neither vectorise (the report's vec column and the O2 vs
       O3native figures tell which); lanes = APPEAR_BATCH_LANES */
    snprintf(note, sizeof note, "batch %.1fx scalar; vectorised: %s; bit-identical: %s (%ld values differ); lanes=%d%s%s",
             ts / tb, ts / tb >= 2.0 ? "yes (batch only)" : "as the scalar loop (both or neither)", bad ? "NO" : "yes",
             bad, (int)APPEAR_BATCH_LANES,
             extra ? "; " : "", extra ? extra : "");
    snprintf(nm, sizeof nm, "%s scalar", name); b_row("batch", nm, ts, -1.0, "");
    snprintf(nm, sizeof nm, "%s batch", name);  b_row("batch", nm, tb, err, note);
}

void bench_batch(void)
{
    b_rng r = b_rng_make(9);
    int i;
    double err = 0.0, th, tb, ratio;
    char note[200];
    for (i = 0; i < BB_N; ++i) {
        appear_vec3 wo = b_rand_hemi(&r), wi = b_rand_hemi(&r);
        bb_wox[i] = wo.x; bb_woy[i] = wo.y; bb_woz[i] = wo.z; bb_wix[i] = wi.x; bb_wiy[i] = wi.y; bb_wiz[i] = wi.z;
        bb_uc[i] = b_randf(&r); bb_u1[i] = b_randf(&r); bb_u2[i] = b_randf(&r); bb_d[i] = (float)(4.0 * b_rand(&r));
    }
    b_note("batch (SoA) entry points vs a loop over the scalar function, %d elements drawn before timing; "
           "ns per element; wo, wi uniform on the upper hemisphere, GGX/Ward alpha = (%.2f, %.2f)", BB_N, bb_ax, bb_ay);

    /* GGX: the listing baseline against the batch sampler */
    bb_ggx_b(0);
    for (i = 0; i < BB_N; ++i) {
        double m[3]; int k; float o[3];
        o[0] = bb_ox[i]; o[1] = bb_oy[i]; o[2] = bb_oz[i];
        bb_caps_double(bb_ax, bb_ay, bb_wox[i], bb_woy[i], bb_woz[i], bb_u1[i], bb_u2[i], m);
        for (k = 0; k < 3; ++k) err = fabs(o[k] - m[k]) > err ? fabs(o[k] - m[k]) : err;
    }
    {   /* the baseline's own float error against its double twin */
        double eh = 0.0;
        bb_heitz_loop(0);
        for (i = 0; i < BB_N; ++i) {
            double m[3]; int k; float o[3];
            o[0] = bb_sx[i]; o[1] = bb_sy[i]; o[2] = bb_sz[i];
            bb_heitz_double(bb_ax, bb_ay, bb_wox[i], bb_woy[i], bb_woz[i], bb_u1[i], bb_u2[i], m);
            for (k = 0; k < 3; ++k) eh = fabs(o[k] - m[k]) > eh ? fabs(o[k] - m[k]) : eh;
        }
        ratio = b_time_pair(bb_heitz_loop, 0, bb_ggx_b, 0, BB_N, &th, &tb); /* alternating runs */
        b_row("batch", "ggx_sample_visible: Heitz 2018 listing, libm", th, eh, "baseline; err vs the listing in double");
    }
    snprintf(note, sizeof note, "%.1fx faster than Heitz 2018 + libm (median of paired runs; target >= 10x); max err vs double %.2g (target <= 1e-5)",
             ratio, err);
    b_row("batch", "ggx_sample_visible: batch vs Heitz 2018", tb, err, note);
    bb_pair("ggx_sample_visible", bb_ggx_s, bb_ggx_b, BB_XYZ, err, "err: max |m - m_double| per component");

    bb_pair("sincos_2pi", bb_sc_s, bb_sc_b, BB_XY, -1.0, "err: see special");
    bb_pair("hg_sample g=0.7", bb_hg_s, bb_hg_b, BB_XYZ | BB_P, -1.0, 0);
    bb_pair("hg_eval g=0.7", bb_hge_s, bb_hge_b, BB_P, -1.0, 0);
    bb_lam_init();
    bb_pair("lambert_sample", bb_lam_s, bb_lam_b, BB_XYZ | BB_P | BB_W | BB_FL, -1.0, 0);
#ifndef APPEAR_NO_EON
    bb_eon_init();
    bb_pair("eon_sample (sigma 0.7)", bb_eon_s, bb_eon_b, BB_XYZ | BB_P | BB_W | BB_FL, -1.0, 0);
    bb_pair("eon_eval (sigma 0.7)", bb_eone_s, bb_eone_b, BB_W, -1.0, 0);
    bb_pair("eon_pdf (sigma 0.7)", bb_eonp_s, bb_eonp_b, BB_P, -1.0, 0);
#endif
#ifndef APPEAR_NO_SHEEN
    bb_sheen_init();
    bb_pair("sheen_sample (r 0.5)", bb_sheen_s, bb_sheen_b, BB_XYZ | BB_P | BB_W | BB_FL, -1.0, 0);
    bb_pair("sheen_eval (r 0.5)", bb_sheene_s, bb_sheene_b, BB_W, -1.0, 0);
    bb_pair("sheen_pdf (r 0.5)", bb_sheenp_s, bb_sheenp_b, BB_P, -1.0, 0);
#endif
#ifndef APPEAR_NO_MICROFACET
    bb_cond_init(); bb_diel_init();
    bb_pair("beckmann_sample_visible", bb_beck_s, bb_beck_b, BB_XYZ, -1.0, 0);
    bb_pair("conductor_sample (GGX)", bb_cond_s, bb_cond_b, BB_XYZ | BB_P | BB_W | BB_FL, -1.0, 0);
    bb_pair("conductor_eval (GGX)", bb_conde_s, bb_conde_b, BB_W, -1.0, 0);
    bb_pair("conductor_pdf (GGX)", bb_condp_s, bb_condp_b, BB_P, -1.0, 0);
    bb_pair("dielectric_sample (GGX, 1.5)", bb_diel_s, bb_diel_b, BB_XYZ | BB_P | BB_W | BB_FL, -1.0, 0);
    bb_pair("dielectric_eval (GGX, 1.5)", bb_diele_s, bb_diele_b, BB_W, -1.0, 0);
    bb_pair("dielectric_pdf (GGX, 1.5)", bb_dielp_s, bb_dielp_b, BB_P, -1.0, 0);
#endif
#ifndef APPEAR_NO_WARD
    bb_ward_init();
    bb_pair("ward_sample (balanced)", bb_ward_s, bb_ward_b, BB_XYZ | BB_P | BB_W | BB_FL, -1.0, 0);
#endif
#ifndef APPEAR_NO_MEDIA
    bb_sigma = appear_spectrum_rgb(0.5f, 1.0f, 2.0f);
    bb_pair("homogeneous_sample", bb_hom_s, bb_hom_b, BB_X | BB_P | BB_W | BB_SC, -1.0, 0);
#endif
}
