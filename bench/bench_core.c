/* bench/bench_core.c - sincos, Lambert, isotropic and Henyey-Greenstein,
   with the textbook HG inverse CDF (libm, float; tests/listings.h) as the baseline. */
#include "bench.h"
#include "../tests/listings.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { N = 1 << 16 };
typedef struct {
    float u1[N], u2[N], g[N];
    appear_vec3 wo[N], wi[N];
} inputs;

static inputs *make_inputs(float gfix)
{
    inputs *in = (inputs *)malloc(sizeof(inputs));
    b_rng r = b_rng_make(9);
    int i;
    for (i = 0; i < N; ++i) {
        in->u1[i] = b_randf(&r); in->u2[i] = b_randf(&r);
        in->g[i] = gfix;
        in->wo[i] = b_rand_hemi(&r); in->wi[i] = b_rand_hemi(&r);
    }
    return in;
}

static inputs *g_in;

static void run_sincos(void *c)
{
    float acc = 0; int i; (void)c;
    for (i = 0; i < N; ++i) { float s, co; appear_sincos_2pi(g_in->u1[i], &s, &co); acc += s + co; }
    b_sink = acc;
}
static void run_sincos_libm(void *c)
{
    float acc = 0; int i; (void)c;
    for (i = 0; i < N; ++i) { float a = 6.2831853f * g_in->u1[i]; acc += sinf(a) + cosf(a); }
    b_sink = acc;
}
static void run_lambert_eval(void *c)
{
    const appear_lambert *m = (const appear_lambert *)c; float acc = 0; int i;
    for (i = 0; i < N; ++i) acc += appear_lambert_eval(m, g_in->wo[i], g_in->wi[i]).v[0];
    b_sink = acc;
}
static void run_lambert_pdf(void *c)
{
    const appear_lambert *m = (const appear_lambert *)c; float acc = 0; int i;
    for (i = 0; i < N; ++i) acc += appear_lambert_pdf(m, g_in->wo[i], g_in->wi[i]);
    b_sink = acc;
}
static void run_lambert_sample(void *c)
{
    const appear_lambert *m = (const appear_lambert *)c; float acc = 0; int i;
    for (i = 0; i < N; ++i) {
        appear_bsdf_record s;
        appear_lambert_sample(m, g_in->wo[i], 0.5f, g_in->u1[i], g_in->u2[i], &s);
        acc += s.wi.x + s.pdf;
    }
    b_sink = acc;
}
static void run_hg_eval(void *c)
{
    float acc = 0; int i; (void)c;
    for (i = 0; i < N; ++i) acc += appear_hg_eval_g(g_in->g[i], g_in->wo[i], g_in->wi[i]);
    b_sink = acc;
}
static void run_hg_sample(void *c)
{
    float acc = 0; int i; (void)c;
    for (i = 0; i < N; ++i) {
        appear_phase_record s;
        appear_hg_sample_g(g_in->g[i], g_in->wo[i], g_in->u1[i], g_in->u2[i], &s);
        acc += s.wi.x + s.pdf;
    }
    b_sink = acc;
}

static void run_hg_pdf(void *c)
{
    float acc = 0; int i; (void)c;
    for (i = 0; i < N; ++i) acc += appear_hg_pdf_g(g_in->g[i], g_in->wo[i], g_in->wi[i]);
    b_sink = acc;
}
static void run_iso_eval(void *c)
{
    float acc = 0; int i; (void)c;
    for (i = 0; i < N; ++i) acc += appear_isotropic_eval(g_in->wo[i], g_in->wi[i]);
    b_sink = acc;
}
static void run_iso_pdf(void *c)
{
    float acc = 0; int i; (void)c;
    for (i = 0; i < N; ++i) acc += appear_isotropic_pdf(g_in->wo[i], g_in->wi[i]);
    b_sink = acc;
}
static void run_iso_sample(void *c)
{
    float acc = 0; int i; (void)c;
    for (i = 0; i < N; ++i) {
        appear_phase_record s;
        appear_isotropic_sample(g_in->wo[i], g_in->u1[i], g_in->u2[i], &s);
        acc += s.wi.x + s.pdf;
    }
    b_sink = acc;
}

/* Baseline: the textbook inverse CDF (tests/listings.h lst_hg_sample_textbook). */
static void run_hg_textbook(void *c)
{
    float acc = 0; int i; (void)c;
    for (i = 0; i < N; ++i) {
        float pdf;
        appear_vec3 w = lst_hg_sample_textbook(g_in->g[i], g_in->wo[i], g_in->u1[i], g_in->u2[i], &pdf);
        acc += w.x + pdf;
    }
    b_sink = acc;
}

/* error of the sampled cos theta against the exact inverse CDF in long double */
static long double mu_exact(long double g, long double u)
{
    long double t;
    if (g == 0) return 2.0L * u - 1.0L;
    t = (1.0L - g * g) / (1.0L - g + 2.0L * g * u);
    return (1.0L + g * g - t * t) / (2.0L * g);
}
static double hg_err(float g, int textbook)
{
    double worst = 0;
    int i;
    for (i = 0; i < N; ++i) {
        appear_vec3 wo = g_in->wo[i], w;
        float u = g_in->u1[i], pdf;
        double mu;
        if (textbook) {
            w = lst_hg_sample_textbook(g, wo, u, g_in->u2[i], &pdf);
            mu = -((double)wo.x * w.x + (double)wo.y * w.y + (double)wo.z * w.z);
            worst = fmax(worst, fabs(mu - (double)mu_exact(g, u)));
        } else {
            appear_phase_record s;
            appear_hg_sample_g(g, wo, u, g_in->u2[i], &s);
            mu = -((double)wo.x * s.wi.x + (double)wo.y * s.wi.y + (double)wo.z * s.wi.z);
            worst = fmax(worst, fabs(mu - (double)mu_exact(g, u)));
        }
    }
    return worst;
}

/* EON: the variance of a reflected-radiance estimate (sample, weight x environment) per
   sampling strategy, at equal inputs: the paper's CLTC mixture against cosine sampling */
static appear_vec3 g_eon_wo;
static int g_eon_env; /* 0: white furnace (the weight's variance), 1: a sky with a soft sun */
static float eon_env(appear_vec3 w)
{   /* the sun behind the viewer, on wo's side, where rough diffuse retro-reflects */
    appear_vec3 sun = appear_normalize(appear_vec3_make(-0.7f, 0.1f, 0.5f));
    float c = appear_dot(w, sun), p = c > 0 ? c : 0;
    if (!g_eon_env) return 1.0f;
    p = p * p; p = p * p; p = p * p;
    return 0.2f + 0.8f * (w.z > 0 ? w.z : 0) + 10.0f * p;
}
static void run_eon_estimate(void *c)
{
    const appear_eon *m = (const appear_eon *)c;
    float acc = 0; int i;
    for (i = 0; i < N; ++i) {
        appear_bsdf_record s;
        if (appear_eon_sample(m, g_eon_wo, 0.5f, g_in->u1[i], g_in->u2[i], &s)) acc += s.weight.v[0] * eon_env(s.wi);
    }
    b_sink = acc;
}
static void eon_variance(const appear_eon *m, double *mean, double *var)
{
    double s = 0, s2 = 0;
    int i;
    for (i = 0; i < N; ++i) {
        appear_bsdf_record bs;
        double v = 0;
        if (appear_eon_sample(m, g_eon_wo, 0.5f, g_in->u1[i], g_in->u2[i], &bs)) v = bs.weight.v[0] * eon_env(bs.wi);
        s += v; s2 += v * v;
    }
    *mean = s / N;
    *var = s2 / N - *mean * *mean;
}

void bench_core(void)
{
    appear_lambert lam = appear_lambert_make(appear_spectrum_rgb(0.8f, 0.5f, 0.2f));
    static const float gs[] = { 1e-4f, 0.3f, 0.99f };
    char name[128];
    double err;
    int k, i;
    g_in = make_inputs(0.3f);
    {
        double e = 0;
        for (i = 0; i < N; ++i) {
            float s, c;
            appear_sincos_2pi(g_in->u1[i], &s, &c);
            e = fmax(e, fabs(s - sin(6.283185307179586 * g_in->u1[i])));
            e = fmax(e, fabs(c - cos(6.283185307179586 * g_in->u1[i])));
        }
        b_row("core", "sincos_2pi (appear polynomial)", b_time(run_sincos, 0, N), e, "");
        e = 0;
        for (i = 0; i < N; ++i) {
            float a = 6.2831853f * g_in->u1[i];
            e = fmax(e, fabs(sinf(a) - sin(6.283185307179586 * g_in->u1[i])));
            e = fmax(e, fabs(cosf(a) - cos(6.283185307179586 * g_in->u1[i])));
        }
        b_row("core", "sinf+cosf of 2 pi u (libm baseline)", b_time(run_sincos_libm, 0, N), e, "");
    }
    b_row("lambert", "eval", b_time(run_lambert_eval, &lam, N), 0.0, "");
    b_row("lambert", "pdf", b_time(run_lambert_pdf, &lam, N), 0.0, "");
    b_row("lambert", "sample", b_time(run_lambert_sample, &lam, N), -1.0, "");
    {
        static const float sig[2] = { 0.5f, 1.0f }, cos_o[2] = { 0.9f, 0.2f };
        int a, b, st;
        for (g_eon_env = 0; g_eon_env < 2; ++g_eon_env)
        for (a = 0; a < 2; ++a)
            for (b = 0; b < 2; ++b)
                for (st = 0; st < 2; ++st) {
                    appear_eon m = appear_eon_make_sampled(appear_spectrum_splat(0.8f), sig[a],
                                                           st ? APPEAR_EON_SAMPLE_COSINE : APPEAR_EON_SAMPLE_CLTC);
                    double mean, var, ns;
                    g_eon_wo = appear_vec3_make(-sqrtf(1.0f - cos_o[b] * cos_o[b]), 0.0f, cos_o[b]);
                    ns = b_time(run_eon_estimate, &m, N);
                    eon_variance(&m, &mean, &var);
                    snprintf(name, sizeof name, "estimate eon sigma %g cos_o %g %s, %s", sig[a], cos_o[b],
                             g_eon_env ? "sky + sun" : "white", st ? "cosine" : "CLTC mixture");
                    b_row("variance", name, ns, -1, "");
                    b_note("  %s: mean %.5f variance %.5f ns/sample %.2f efficiency 1e6/(var*ns) %.1f", name, mean,
                           var, ns, 1e6 / (var * ns));
                }
    }
    b_row("phase", "isotropic eval", b_time(run_iso_eval, 0, N), -1.0, "");
    b_row("phase", "isotropic pdf", b_time(run_iso_pdf, 0, N), -1.0, "");
    b_row("phase", "isotropic sample", b_time(run_iso_sample, 0, N), -1.0, "");
    for (k = 0; k < 3; ++k) {
        for (i = 0; i < N; ++i) g_in->g[i] = gs[k];
        snprintf(name, sizeof name, "hg eval g=%g", gs[k]);
        b_row("phase", name, b_time(run_hg_eval, 0, N), -1.0, "");
        snprintf(name, sizeof name, "hg pdf g=%g", gs[k]);
        b_row("phase", name, b_time(run_hg_pdf, 0, N), -1.0, "");
        err = hg_err(gs[k], 0);
        snprintf(name, sizeof name, "hg sample g=%g (appear)", gs[k]);
        b_row("phase", name, b_time(run_hg_sample, 0, N), err, "err = max |cos - exact|");
        err = hg_err(gs[k], 1);
        snprintf(name, sizeof name, "hg sample g=%g (textbook, libm)", gs[k]);
        b_row("phase", name, b_time(run_hg_textbook, 0, N), err, "baseline");
    }
    free(g_in);
}
