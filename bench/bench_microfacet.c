/* bench/bench_microfacet.c - distributions, visible-normal samplers, Fresnel,
   rough conductor and dielectric. Baselines written plainly from the papers,
   measured in the same run: the Heitz 2018 listing (libm sqrtf/sinf/cosf) and
   a Walter 2007 textbook GGX conductor eval (tan-based D, separable Smith G,
   libm). Last, the variance of a reflected-radiance estimate with each
   sampling strategy, at equal time (efficiency = 1 / (variance x ns)). */
#include "bench.h"
#include "../tests/listings.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { N = 1 << 16 };
typedef struct {
    float u1[N], u2[N], uc[N], cs[N];
    appear_vec3 wo[N], wi[N], m[N];
} inputs;
static inputs *g_in;
static float g_ax = 0.3f, g_ay = 0.3f;
static appear_conductor g_cond;
static appear_dielectric g_diel;

/* ---- baselines ---- */

/* The Heitz 2018 listing and the Walter 2007 textbook conductor: tests/listings.h
   (lst_heitz18_vndf, lst_walter_eval). */

/* The Beckmann visible-normal sampler as it was before the fitted initial
   guess (the earlier appear.h): safeguarded Newton in the erf domain
   started from the linear guess b = lo + (hi - lo) u; the speed baseline of
   the current appear_beckmann_sample_visible. Same distribution. */
static appear_vec3 beck_vis_linear_guess(float ax, float ay, appear_vec3 wo, float u1, float u2)
{
    appear_vec3 v = appear_normalize(appear_vec3_make(ax * wo.x, ay * wo.y, wo.z));
    float r = sqrtf(v.x * v.x + v.y * v.y);
    float cphi = r > 0.0f ? v.x / r : 1.0f, sphi = r > 0.0f ? v.y / r : 0.0f;
    int big = v.z >= r;
    float cot = big ? (r > 0.0f ? appear__min(v.z / r, 10.0f) : 10.0f) : v.z / r;
    float tn = big ? r / v.z : 1.0f, p = big ? 1.0f : cot;
    float lo = -1.0f, hi = appear__erf(cot);
    float norm = p * (1.0f + hi) + tn * appear__exp(-cot * cot) * 0.564189584f;
    float u = appear__clamp(u1, 0.0f, 1.0f), target = u * norm;
    float b = lo + (hi - lo) * u, x = 0.0f, sx, sy, y;
    int it;
    for (it = 0; it < 16; ++it) {
        float val, der;
        if (!(b > lo && b < hi)) b = 0.5f * (lo + hi);
        x = appear__erfinv(b);
        val = p * (1.0f + b) + tn * appear__exp(-x * x) * 0.564189584f - target;
        der = p - tn * x;
        if (val > 0.0f) hi = b; else lo = b;
        if (fabsf(val) <= 2e-7f * norm || hi - lo <= 1.2e-7f) break;
        b -= der > 0.0f ? val / der : 0.0f;
    }
    x = appear__erfinv(appear__clamp(b, -0.99999994f, 0.99999994f));
    y = appear__erfinv(appear__clamp(2.0f * u2 - 1.0f, -0.99999994f, 0.99999994f));
    sx = ax * (cphi * x - sphi * y);
    sy = ay * (sphi * x + cphi * y);
    return appear_normalize(appear_vec3_make(-sx, -sy, 1.0f));
}

/* ---- loops ---- */
#define LOOP(name, body)                                                          \
    static void name(void *c)                                                     \
    {                                                                             \
        float acc = 0; int i; (void)c;                                            \
        for (i = 0; i < N; ++i) { body; }                                         \
        b_sink = acc;                                                             \
    }
LOOP(run_ggx_D, acc += appear_ggx_D(g_ax, g_ay, g_in->m[i]))
LOOP(run_ggx_G1, acc += appear_ggx_G1(g_ax, g_ay, g_in->wo[i], g_in->m[i]))
LOOP(run_beck_D, acc += appear_beckmann_D(g_ax, g_ay, g_in->m[i]))
LOOP(run_beck_L, acc += appear_beckmann_lambda(g_ax, g_ay, g_in->wo[i]))
LOOP(run_beck_Lf, acc += appear_beckmann_lambda_fast(g_ax, g_ay, g_in->wo[i]))
LOOP(run_ggx_vis, { appear_vec3 m = appear_ggx_sample_visible(g_ax, g_ay, g_in->wo[i], g_in->u1[i], g_in->u2[i]); acc += m.x + m.z; })
LOOP(run_ggx_vis_raw, { appear_vec3 m = appear__ggx_sample_caps(g_ax, g_ay, g_in->wo[i], g_in->u1[i], g_in->u2[i]); acc += m.x + m.z; })
LOOP(run_heitz18, { appear_vec3 m = lst_heitz18_vndf(g_in->wo[i], g_ax, g_ay, g_in->u1[i], g_in->u2[i]); acc += m.x + m.z; })
LOOP(run_ggx_bnd, { appear_vec3 m = appear_ggx_sample_bounded_normal(g_ax, g_ay, g_in->wo[i], g_in->u1[i], g_in->u2[i]); acc += m.x + m.z; })
LOOP(run_beck_vis, { appear_vec3 m = appear_beckmann_sample_visible(g_ax, g_ay, g_in->wo[i], g_in->u1[i], g_in->u2[i]); acc += m.x + m.z; })
LOOP(run_beck_vis_old, { appear_vec3 m = beck_vis_linear_guess(g_ax, g_ay, g_in->wo[i], g_in->u1[i], g_in->u2[i]); acc += m.x + m.z; })
LOOP(run_ggx_full, { appear_vec3 m = appear_ggx_sample_D(g_ax, g_ay, g_in->u1[i], g_in->u2[i]); acc += m.x + m.z; })
LOOP(run_ggx_pdfv, acc += appear_ggx_pdf_visible(g_ax, g_ay, g_in->wo[i], g_in->m[i]))
LOOP(run_fr_diel, acc += appear_fresnel_dielectric(g_in->cs[i], 1.5f))
LOOP(run_fr_cond, acc += appear_fresnel_conductor(g_in->cs[i], 0.143f, 3.983f))
LOOP(run_fr_schlick, acc += appear_fresnel_schlick(g_in->cs[i], 0.04f))
LOOP(run_fr_f82, acc += appear_fresnel_f82(g_in->cs[i], 0.9f, 0.3f))
LOOP(run_cond_eval, acc += appear_conductor_eval(&g_cond, g_in->wo[i], g_in->wi[i]).v[0])
LOOP(run_walter_eval, acc += lst_walter_eval(g_ax, g_in->wo[i], g_in->wi[i]))
LOOP(run_cond_pdf, acc += appear_conductor_pdf(&g_cond, g_in->wo[i], g_in->wi[i]))
LOOP(run_cond_sample, { appear_bsdf_record s; appear_conductor_sample(&g_cond, g_in->wo[i], g_in->uc[i], g_in->u1[i], g_in->u2[i], &s); acc += s.weight.v[0] + s.wi.x; })
LOOP(run_diel_eval, acc += appear_dielectric_eval(&g_diel, g_in->wo[i], g_in->wi[i]).v[0])
LOOP(run_diel_pdf, acc += appear_dielectric_pdf(&g_diel, g_in->wo[i], g_in->wi[i]))
LOOP(run_diel_sample, { appear_bsdf_record s; appear_dielectric_sample(&g_diel, g_in->wo[i], g_in->uc[i], g_in->u1[i], g_in->u2[i], &s); acc += s.weight.v[0] + s.wi.x; })

/* ---- variance at equal time ---- */
static appear_vec3 g_sun;
static float env(appear_vec3 w)
{   /* a sky with a soft sun: smooth but peaked */
    float c = appear_dot(w, g_sun), p = c > 0 ? c : 0;
    p = p * p; p = p * p; p = p * p; p = p * p; /* ^16 */
    return 0.2f + 0.8f * (w.z > 0 ? w.z : 0) + 20.0f * p;
}
static appear_vec3 g_wo;
static void run_estimate(void *c)
{
    const appear_conductor *m = (const appear_conductor *)c;
    float acc = 0; int i;
    for (i = 0; i < N; ++i) {
        appear_bsdf_record s;
        if (appear_conductor_sample(m, g_wo, g_in->uc[i], g_in->u1[i], g_in->u2[i], &s)) acc += s.weight.v[0] * env(s.wi);
    }
    b_sink = acc;
}
static void variance(const appear_conductor *m, double *mean, double *var)
{
    double s = 0, s2 = 0;
    int i;
    for (i = 0; i < N; ++i) {
        appear_bsdf_record bs;
        double v = 0;
        if (appear_conductor_sample(m, g_wo, g_in->uc[i], g_in->u1[i], g_in->u2[i], &bs)) v = bs.weight.v[0] * env(bs.wi);
        s += v; s2 += v * v;
    }
    *mean = s / N;
    *var = s2 / N - *mean * *mean;
}

static void run_ggx_L(void *c)
{ float acc = 0; int i; (void)c; for (i = 0; i < N; ++i) acc += appear_ggx_lambda(g_ax, g_ay, g_in->wo[i]); b_sink = acc; }
static void run_beck_pdfv(void *c)
{ float acc = 0; int i; (void)c; for (i = 0; i < N; ++i) acc += appear_beckmann_pdf_visible(g_ax, g_ay, g_in->wo[i], g_in->m[i]); b_sink = acc; }
static void run_ggx_pdfb(void *c)
{ float acc = 0; int i; (void)c; for (i = 0; i < N; ++i) acc += appear_ggx_pdf_bounded_reflect(g_ax, g_ay, g_in->wo[i], g_in->wi[i]); b_sink = acc; }
static const appear_spectrum *g_eta3, *g_k3;
static void run_fr_diel_s(void *c)
{ float acc = 0; int i; (void)c; for (i = 0; i < N; ++i) acc += appear_fresnel_dielectric_spectrum(g_in->cs[i], *g_eta3).v[1]; b_sink = acc; }
static void run_fr_cond_s(void *c)
{ float acc = 0; int i; (void)c; for (i = 0; i < N; ++i) acc += appear_fresnel_conductor_spectrum(g_in->wo[i].z, *g_eta3, *g_k3).v[1]; b_sink = acc; }
static void run_fr_schlick_s(void *c)
{ float acc = 0; int i; (void)c; for (i = 0; i < N; ++i) acc += appear_fresnel_schlick_spectrum(g_in->wo[i].z, *g_k3).v[1]; b_sink = acc; }
static void run_fr_f82_s(void *c)
{ float acc = 0; int i; (void)c; for (i = 0; i < N; ++i) acc += appear_fresnel_f82_spectrum(g_in->wo[i].z, *g_k3, *g_eta3).v[1]; b_sink = acc; }

void bench_microfacet(void)
{
    b_rng r = b_rng_make(17);
    int i, k;
    double err;
    char name[160];
    g_in = (inputs *)malloc(sizeof(inputs));
    for (i = 0; i < N; ++i) {
        appear_vec3 h;
        g_in->u1[i] = b_randf(&r); g_in->u2[i] = b_randf(&r); g_in->uc[i] = b_randf(&r);
        g_in->cs[i] = (float)(2 * b_rand(&r) - 1);
        g_in->wo[i] = b_rand_hemi(&r); g_in->wi[i] = b_rand_hemi(&r);
        h = appear_normalize(appear_add(g_in->wo[i], g_in->wi[i]));
        g_in->m[i] = h;
    }
    g_cond = appear_conductor_make(appear_microfacet_make(APPEAR_GGX, g_ax, g_ay, APPEAR_SAMPLE_VISIBLE),
                                   appear_spectrum_rgb(0.143f, 0.374f, 1.442f), appear_spectrum_rgb(3.983f, 2.386f, 1.603f));
    g_diel = appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, g_ax, g_ay, APPEAR_SAMPLE_VISIBLE), 1.5f);
    b_note("microfacet: alpha = 0.3 isotropic, wo and wi uniform on the upper hemisphere, %d inputs", N);

    b_row("microfacet", "ggx_D", b_time(run_ggx_D, 0, N), -1, "");
    b_row("microfacet", "ggx_G1", b_time(run_ggx_G1, 0, N), -1, "");
    b_row("microfacet", "beckmann_D", b_time(run_beck_D, 0, N), -1, "");
    b_row("microfacet", "beckmann_lambda (exact)", b_time(run_beck_L, 0, N), 0.0, "the reference of the fast fit");
    err = 0;
    for (i = 0; i < N; ++i) {
        float a = 1.0f / (1.0f + appear_beckmann_lambda(g_ax, g_ay, g_in->wo[i])), b = 1.0f / (1.0f + appear_beckmann_lambda_fast(g_ax, g_ay, g_in->wo[i]));
        err = fmax(err, fabs(a - b));
    }
    b_row("microfacet", "beckmann_lambda_fast (Walter07 fit)", b_time(run_beck_Lf, 0, N), err, "err = max |G1 - G1 exact|");
    /* the caps sampler and the Heitz 2018 transcription draw the same
       distribution (tests/test_microfacet.c checks the caps one by chi2) */
    {   /* the public (validating) caps sampler against the listing, timed in alternation */
        double tc, th, q = b_time_pair(run_heitz18, 0, run_ggx_vis, 0, N, &th, &tc);
        char note[128];
        snprintf(note, sizeof note, "Dupuy-Benyoub 2023; %.2fx faster than the Heitz 2018 listing (median of paired runs)", q);
        b_row("microfacet", "ggx_sample_visible (caps, public: validates)", tc, -1, note);
        b_row("microfacet", "ggx caps sampler core (no validation)", b_time(run_ggx_vis_raw, 0, N), -1, "");
        b_row("microfacet", "ggx VNDF Heitz 2018 listing (libm)", th, -1, "baseline");
    }
    b_row("microfacet", "ggx_sample_visible_bounded", b_time(run_ggx_bnd, 0, N), -1, "Eto-Tokuyoshi 2023");
    b_row("microfacet", "ggx_sample_D (full D)", b_time(run_ggx_full, 0, N), -1, "");
    {
        double tn = b_time(run_beck_vis, 0, N), to = b_time(run_beck_vis_old, 0, N);
        char note[96];
        snprintf(note, sizeof note, "fitted guess: %.1fx faster than the linear-guess baseline", to / tn);
        b_row("microfacet", "beckmann_sample_visible (erf Newton, fitted guess)", tn, -1, note);
        b_row("microfacet", "beckmann vis. baseline: linear initial guess", to, -1, "baseline (the previous version)");
    }
    b_row("microfacet", "ggx_pdf_visible", b_time(run_ggx_pdfv, 0, N), -1, "");
    b_row("microfacet", "ggx_lambda", b_time(run_ggx_L, 0, N), -1, "");
    b_row("microfacet", "beckmann_pdf_visible", b_time(run_beck_pdfv, 0, N), -1, "");
    b_row("microfacet", "ggx_pdf_reflect_bounded", b_time(run_ggx_pdfb, 0, N), -1, "");
    err = 0;
    for (i = 0; i < N; ++i) {
        double c = g_in->cs[i], e = 1.5, ct, rs, rp, ref;
        if (c < 0) { c = -c; e = 1 / 1.5; }
        ct = 1 - (1 - c * c) / (e * e);
        if (ct <= 0) ref = 1; else { ct = sqrt(ct); rs = (c - e * ct) / (c + e * ct); rp = (e * c - ct) / (e * c + ct); ref = 0.5 * (rs * rs + rp * rp); }
        err = fmax(err, fabs(appear_fresnel_dielectric(g_in->cs[i], 1.5f) - ref));
    }
    b_row("fresnel", "dielectric (exact)", b_time(run_fr_diel, 0, N), err, "abs err vs double");
    b_row("fresnel", "conductor (exact, complex IOR)", b_time(run_fr_cond, 0, N), -1, "");
    b_row("fresnel", "schlick", b_time(run_fr_schlick, 0, N), -1, "");
    b_row("fresnel", "f82-tint", b_time(run_fr_f82, 0, N), -1, "");
    {
        appear_spectrum eta3 = appear_spectrum_rgb(1.45f, 1.5f, 1.55f), k3 = appear_spectrum_rgb(0.9f, 0.6f, 0.3f);
        g_eta3 = &eta3; g_k3 = &k3;
        b_row("fresnel", "dielectric_spectrum (3 channels)", b_time(run_fr_diel_s, 0, N), -1, "");
        b_row("fresnel", "conductor_spectrum (3 channels)", b_time(run_fr_cond_s, 0, N), -1, "");
        b_row("fresnel", "schlick_spectrum (3 channels)", b_time(run_fr_schlick_s, 0, N), -1, "");
        b_row("fresnel", "f82_spectrum (3 channels)", b_time(run_fr_f82_s, 0, N), -1, "");
    }
    b_row("conductor", "ggx eval (appear, height-correlated G2)", b_time(run_cond_eval, 0, N), -1, "");
    b_row("conductor", "ggx eval (Walter07 textbook, separable G, libm)", b_time(run_walter_eval, 0, N), -1, "baseline");
    b_row("conductor", "ggx pdf", b_time(run_cond_pdf, 0, N), -1, "");
    b_row("conductor", "ggx sample (caps)", b_time(run_cond_sample, &g_cond, N), -1, "");
    b_row("dielectric", "ggx eval", b_time(run_diel_eval, 0, N), -1, "");
    b_row("dielectric", "ggx pdf", b_time(run_diel_pdf, 0, N), -1, "");
    b_row("dielectric", "ggx sample", b_time(run_diel_sample, 0, N), -1, "");

    /* variance of a reflected-radiance estimate at equal time */
    for (k = 0; k < 2; ++k) {
        static const float al[2] = { 0.5f, 0.1f };
        static const int sm[3] = { APPEAR_SAMPLE_VISIBLE, APPEAR_SAMPLE_BOUNDED, APPEAR_SAMPLE_FULL_D };
        static const char *smn[3] = { "VNDF caps", "bounded VNDF", "full D" };
        int j;
        g_wo = appear_normalize(appear_vec3_make(0.95f, 0.0f, 0.2f)); /* grazing-ish view */
        g_sun = appear_normalize(appear_vec3_make(-0.8f, 0.1f, 0.4f));
        for (j = 0; j < 3; ++j) {
            appear_conductor c = appear_conductor_make(appear_microfacet_make(APPEAR_GGX, al[k], al[k], sm[j]), appear_spectrum_splat(0.2f),
                                                       appear_spectrum_splat(3.0f));
            double mean, var, ns = b_time(run_estimate, &c, N);
            variance(&c, &mean, &var);
            snprintf(name, sizeof name, "estimate alpha %g cos_o 0.2, %s", al[k], smn[j]);
            b_row("variance", name, ns, -1, "");
            b_note("  %s: mean %.5f variance %.5f ns/sample %.2f efficiency 1e6/(var*ns) %.1f", name, mean, var, ns, 1e6 / (var * ns));
        }
    }
    free(g_in);
}
