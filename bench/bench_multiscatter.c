/* bench/bench_multiscatter.c - speed against energy error of the three ways
   to handle multiple scattering between microfacets: single scattering
   (energy lost), albedo-scaling compensation (Turquin 2019, tables) and the
   Heitz 2016 random walk (stochastic eval, exact sampler).
   One table (group "ms tradeoff"): per variant x (GGX, Beckmann) x alpha in
   {0.1, 0.5, 1, 2}, a conductor with F = 1 (white furnace):
     eval row:   ns per eval (wo, wi uniform on the hemisphere; the walk's
                 eval = one unbiased estimate = two walks),
     sample row: ns per sample,
   both with err = max over 16 values of cos theta_o (mu = (j + 1/2)/16)
   of |E(mu) - 1|: for single scattering E = the double-precision albedo
   quadrature of tests/gen/albedo_ref.h (the model's own albedo, to ~1e-4),
   compensated: that times the factor the code applies
   (appear_conductor_comp_scale, i.e. 1/E_table), random walk: the mean
   sample weight over 2048 walks per mu (exactly 1 per completed walk with
   F = 1, so the error is the fraction of walks dropped).
   Also writes bench/out/ms_tradeoff_<build>.dat for bench/plots.gp:
     type alpha variant ns_eval ns_sample err
   plus three lossless-dielectric sample rows (GGX alpha 1, eta 1.5). */
#include "bench.h"
#define AR_NO_NODES
#include "../tests/gen/albedo_ref.h"
#include <math.h>
#include <stdio.h>

#ifndef BENCH_BUILD
#define BENCH_BUILD "dev"
#endif

enum { MS_N = 4096 };
typedef struct {
    appear_conductor c;
    appear_dielectric d;
    appear_vec3 wo[MS_N], wi[MS_N];
    float u[MS_N][3];
} ms_ctx;
static ms_ctx ms;

#define MS_LOOP(name, body) \
    static void name(void *p) { ms_ctx *c = (ms_ctx *)p; float a = 0; int i; appear_bsdf_record s; appear_rng r = appear_rng_make(1); \
        (void)s; (void)r; for (i = 0; i < MS_N; ++i) { body } b_sink = a; }
MS_LOOP(run_ss_eval, a += appear_conductor_eval(&c->c, c->wo[i], c->wi[i]).v[0];)
MS_LOOP(run_comp_eval, a += appear_conductor_comp_eval(&c->c, c->wo[i], c->wi[i]).v[0];)
MS_LOOP(run_ms_eval, a += appear_conductor_ms_eval(&c->c, c->wo[i], c->wi[i], &r).v[0];)
MS_LOOP(run_ss_sample, if (appear_conductor_sample(&c->c, c->wo[i], c->u[i][0], c->u[i][1], c->u[i][2], &s)) a += s.weight.v[0];)
MS_LOOP(run_comp_sample, if (appear_conductor_comp_sample(&c->c, c->wo[i], c->u[i][0], c->u[i][1], c->u[i][2], &s)) a += s.weight.v[0];)
MS_LOOP(run_ms_sample, if (appear_conductor_ms_sample(&c->c, c->wo[i], &r, &s)) a += s.weight.v[0];)
MS_LOOP(run_dss_sample, if (appear_dielectric_sample(&c->d, c->wo[i], c->u[i][0], c->u[i][1], c->u[i][2], &s)) a += s.weight.v[0];)
MS_LOOP(run_dcomp_sample, if (appear_dielectric_comp_sample(&c->d, c->wo[i], c->u[i][0], c->u[i][1], c->u[i][2], &s)) a += s.weight.v[0];)
MS_LOOP(run_dms_sample, if (appear_dielectric_ms_sample(&c->d, c->wo[i], &r, &s)) a += s.weight.v[0];)

/* max over 16 mu of |E(mu) - 1| of the conductor ms.c (F = 1), variant k
   (0 single, 1 compensated: from the double quadrature; 2 walk: sampled) */
static double ms_err_cond(int type, float alpha, int k)
{
    double worst = 0;
    int j;
    appear_rng ar = appear_rng_make(5);
    for (j = 0; j < 16; ++j) {
        float mu = (j + 0.5f) / 16.0f;
        appear_vec3 wo = appear_vec3_make(sqrtf(1.0f - mu * mu), 0.0f, mu);
        double E;
        if (k < 2) {
            E = ar_albedo(type, alpha, mu, -1.0, b_quick() ? 32 : 64);
            if (k == 1) E *= appear_conductor_comp_scale(&ms.c, wo).v[0];
        } else {
            int i, n = b_quick() ? 512 : 2048;
            double sum = 0;
            for (i = 0; i < n; ++i) {
                appear_bsdf_record s;
                if (appear_conductor_ms_sample(&ms.c, wo, &ar, &s)) sum += s.weight.v[0];
            }
            E = sum / n;
        }
        worst = fmax(worst, fabs(E - 1));
    }
    return worst;
}

/* dielectric: max over 16 mu of |mean flux weight - 1| of variant k (Monte Carlo, 2048 samples per mu) */
static double ms_err(int diel, int k)
{
    b_rng r = b_rng_make(99);
    appear_rng ar = appear_rng_make(5);
    double worst = 0;
    int j, i, n = b_quick() ? 512 : 2048;
    for (j = 0; j < 16; ++j) {
        float mu = (j + 0.5f) / 16.0f;
        appear_vec3 wo = appear_vec3_make(sqrtf(1.0f - mu * mu), 0.0f, mu);
        double sum = 0;
        for (i = 0; i < n; ++i) {
            appear_bsdf_record s;
            int ok;
            float u0 = b_randf(&r), u1 = b_randf(&r), u2 = b_randf(&r);
            if (!diel) ok = k == 0 ? appear_conductor_sample(&ms.c, wo, u0, u1, u2, &s)
                          : k == 1 ? appear_conductor_comp_sample(&ms.c, wo, u0, u1, u2, &s)
                                   : appear_conductor_ms_sample(&ms.c, wo, &ar, &s);
            else ok = k == 0 ? appear_dielectric_sample(&ms.d, wo, u0, u1, u2, &s)
                    : k == 1 ? appear_dielectric_comp_sample(&ms.d, wo, u0, u1, u2, &s)
                             : appear_dielectric_ms_sample(&ms.d, wo, &ar, &s);
            if (ok) sum += s.weight.v[0] * ((s.flags & APPEAR_LOBE_TRANSMISSION) ? s.eta * s.eta : 1.0f);
        }
        worst = fmax(worst, fabs(sum / n - 1));
    }
    return worst;
}

void bench_multiscatter(void)
{
    static const float alphas[] = { 0.1f, 0.5f, 1.0f, 2.0f };
    static const char *vname[] = { "single scattering", "compensated", "random walk" };
    static const char *vkey[] = { "single_scattering", "compensated", "random_walk" };
    static void (*const ev[3])(void *) = { run_ss_eval, run_comp_eval, run_ms_eval };
    static void (*const sa[3])(void *) = { run_ss_sample, run_comp_sample, run_ms_sample };
    b_rng r = b_rng_make(7);
    int i, t, a, v;
    FILE *dat;
    char note[160];
    for (i = 0; i < MS_N; ++i) {
        ms.wo[i] = b_rand_hemi(&r);
        ms.wi[i] = b_rand_hemi(&r);
        ms.u[i][0] = b_randf(&r); ms.u[i][1] = b_randf(&r); ms.u[i][2] = b_randf(&r);
    }
    dat = fopen("bench/out/ms_tradeoff_" BENCH_BUILD ".dat", "w");
    if (dat) fprintf(dat, "# type alpha variant ns_eval ns_sample furnace_err (bench_multiscatter.c, build %s)\n", BENCH_BUILD);
    b_note("ms tradeoff: conductor F = 1, wo (and wi) uniform on the hemisphere; err = max over 16 mu of |furnace albedo - 1| "
           "(single, compensated: double quadrature x the applied factor; walk: %d walks per mu); walk <= %d bounces, eval = 2 walks",
           b_quick() ? 512 : 2048, APPEAR_MS_MAX_BOUNCES);
    for (t = 0; t < 2; ++t)
        for (a = 0; a < 4; ++a) {
            appear_microfacet mf = appear_microfacet_make(t ? APPEAR_BECKMANN : APPEAR_GGX, alphas[a], alphas[a], APPEAR_SAMPLE_VISIBLE);
            ms.c = appear_conductor_make_f82(mf, appear_spectrum_splat(1.0f), appear_spectrum_splat(1.0f));
            for (v = 0; v < 3; ++v) {
                double te = b_time(ev[v], &ms, MS_N), ts = b_time(sa[v], &ms, MS_N), e = ms_err_cond(t ? APPEAR_BECKMANN : APPEAR_GGX, alphas[a], v);
                char name[96];
                snprintf(note, sizeof note, "%s a=%g: err = max_mu |E - 1|", t ? "beckmann" : "ggx", alphas[a]);
                snprintf(name, sizeof name, "%s a=%g %s eval", t ? "beckmann" : "ggx", alphas[a], vname[v]);
                b_row("ms tradeoff", name, te, e, note);
                snprintf(name, sizeof name, "%s a=%g %s sample", t ? "beckmann" : "ggx", alphas[a], vname[v]);
                b_row("ms tradeoff", name, ts, e, note);
                if (dat) fprintf(dat, "%s %g %s %.4g %.4g %.4g\n", t ? "beckmann" : "ggx", alphas[a], vkey[v], te, ts, e);
            }
        }
    if (dat) fclose(dat);
    {
        appear_microfacet mf = appear_microfacet_make(APPEAR_GGX, 1.0f, 1.0f, APPEAR_SAMPLE_VISIBLE);
        ms.d = appear_dielectric_make(mf, 1.5f);
        snprintf(note, sizeof note, "lossless dielectric GGX a=1 eta 1.5, err = max_mu |R + e^2 T - 1|");
        b_row("multiscatter", "dielectric sample single scattering", b_time(run_dss_sample, &ms, MS_N), ms_err(1, 0), note);
        b_row("multiscatter", "dielectric sample compensated", b_time(run_dcomp_sample, &ms, MS_N), ms_err(1, 1), note);
        b_row("multiscatter", "dielectric sample random walk", b_time(run_dms_sample, &ms, MS_N), ms_err(1, 2), note);
    }
}
