/* bench/bench_media.c - transmittance estimators of appear.h (SECTION media)
   measured as Kettunen et al. 2021 do: variance, cost (density lookups and
   ns per estimate, lookups included) and efficiency 1/(variance x cost),
   which compares estimators at equal cost. Profiles: the canonical 1D
   profiles of Georgiev et al. 2019 on [0, 1] with a constant majorant of
   tightness 1, 0.1 and 0.01 (sigma_maj = max / tightness, sigma_min =
   min * tightness). Deterministic ray marching is biased: its row shows
   the MSE in place of the variance.
   Output: a table on stdout, bench/out/media.csv, and (when gnuplot is
   installed) bench/out/media_efficiency.png. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#endif
#include "bench.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#ifndef APPEAR_NO_MEDIA

enum { P_CONST, P_COS, P_BUMP, P_HOLE, P_RAMP_UP, P_RAMP_DOWN, P_COUNT };
static const char *const prof_name[P_COUNT] = { "constant", "cosine", "bump", "hole", "ramp_up", "ramp_down" };

static float prof_sigma(int p, float x)
{
    float g = expf(-(x - 0.5f) * (x - 0.5f) * 50.0f);
    switch (p) {
    case P_CONST: return 2.0f;
    case P_COS: return 1.5f * cosf(20.0f * x + 0.8f) + 2.0f;
    case P_BUMP: return 0.5f + 4.0f * g;
    case P_HOLE: return 3.0f - 2.9f * g;
    case P_RAMP_UP: return 0.2f + 3.8f * x;
    default: return 4.0f - 3.8f * x;
    }
}
static double prof_tau1(int p)
{
    double G = 0.1 * sqrt(3.14159265358979323846 / 2.0) * 2.0 * erf(0.5 / (0.1 * sqrt(2.0)));
    switch (p) {
    case P_CONST: return 2.0;
    case P_COS: return 2.0 + 1.5 / 20.0 * (sin(20.8) - sin(0.8));
    case P_BUMP: return 0.5 + 4.0 * G;
    case P_HOLE: return 3.0 - 2.9 * G;
    case P_RAMP_UP: return 0.2 + 1.9;
    default: return 4.0 - 1.9;
    }
}
static void prof_bounds(int p, float *mx, float *mn)
{
    static const float MX[P_COUNT] = { 2.0f, 3.5f, 4.5f, 3.0f, 4.0f, 4.0f };
    static const float MN[P_COUNT] = { 2.0f, 0.5f, 0.5f, 0.1f, 0.2f, 0.2f };
    *mx = MX[p]; *mn = MN[p];
}

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e9 + ts.tv_nsec;
}

/* small inline xorshift-style generator so the RNG costs little */
static inline float rngf(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (float)(z >> 40) * (1.0f / 16777216.0f);
}

typedef struct { const char *name; int kind; float rr; float comb_rate; int comb; float control; } est_def;
static const est_def ests[] = {
    { "ratio",        APPEAR_TRACK_RATIO,        0.0f, 0.0f, 0, 0.0f },
    { "delta(bool)",  APPEAR_TRACK_DELTA,        0.0f, 0.0f, 0, 0.0f },
    { "ratio+rr0.1",  APPEAR_TRACK_RATIO,        0.1f, 0.0f, 0, 0.0f },
    { "next_flight",  APPEAR_TRACK_NEXT_FLIGHT,  0.0f, 0.0f, 0, 0.0f },
    { "residual",     APPEAR_TRACK_RESIDUAL,     0.0f, 0.0f, 0, 0.0f },
    { "residual_c.5", APPEAR_TRACK_RESIDUAL,     0.0f, 0.0f, 0, 0.5f },
    { "power_series", APPEAR_TRACK_POWER_SERIES, 0.0f, 0.0f, 0, 1.0f },
    { "urm",          APPEAR_TRACK_URM,          0.0f, 1.0f, 0, 0.0f },
    { "urm_M4",       APPEAR_TRACK_URM,          0.0f, 0.0f, 4, 0.0f },
    { "raymarch_M16", APPEAR_TRACK_RAY_MARCH,    0.0f, 0.0f, 16, 0.0f },
};
#define N_EST ((int)(sizeof ests / sizeof ests[0]))

/* scalar homogeneous-medium entry points (the batch twin is in bench_batch.c) */
enum { HM_N = 1 << 14 };
static float hm_d[HM_N], hm_u1[HM_N], hm_u2[HM_N], hm_t[HM_N];
static appear_spectrum hm_sig;
static void run_hm_tr1(void *c)
{ float acc = 0; int i; (void)c; for (i = 0; i < HM_N; ++i) acc += appear_homogeneous_transmittance1(hm_sig.v[0], hm_d[i]); b_sink = acc; }
static void run_hm_tr(void *c)
{ float acc = 0; int i; (void)c; for (i = 0; i < HM_N; ++i) acc += appear_homogeneous_transmittance(hm_sig, hm_d[i]).v[1]; b_sink = acc; }
static void run_hm_pdf(void *c)
{ float acc = 0; int i; (void)c; for (i = 0; i < HM_N; ++i) acc += appear_homogeneous_pdf(hm_sig, hm_d[i], hm_t[i], i & 1); b_sink = acc; }
static void run_hm_sample(void *c)
{
    float acc = 0; int i; (void)c;
    for (i = 0; i < HM_N; ++i) { appear_medium_sample s; appear_homogeneous_sample(hm_sig, hm_d[i], hm_u1[i], hm_u2[i], &s); acc += s.t + s.pdf; }
    b_sink = acc;
}
void bench_media_homog(void)
{
    b_rng r = b_rng_make(5);
    int i;
    hm_sig = appear_spectrum_rgb(0.5f, 1.0f, 2.0f);
    for (i = 0; i < HM_N; ++i) { hm_d[i] = 4.0f * b_randf(&r); hm_t[i] = hm_d[i] * b_randf(&r); hm_u1[i] = b_randf(&r); hm_u2[i] = b_randf(&r); }
    b_row("homog", "transmittance1 (one channel)", b_time(run_hm_tr1, 0, HM_N), -1, "");
    b_row("homog", "transmittance (spectrum)", b_time(run_hm_tr, 0, HM_N), -1, "");
    b_row("homog", "pdf", b_time(run_hm_pdf, 0, HM_N), -1, "");
    b_row("homog", "sample (spectral MIS free flight)", b_time(run_hm_sample, 0, HM_N), -1, "");
}

void bench_media(void)
{
    static const float tights[] = { 1.0f, 0.1f, 0.01f };
    long n = b_quick() ? 2000 : 20000;
    int p, ti, e;
    FILE *csv;
    mkdir("bench/out", 0777);
    csv = fopen("bench/out/media.csv", "w");
    if (csv) fprintf(csv, "profile,tightness,estimator,mean,T_exact,variance,mse,lookups,ns,eff_lookups,eff_ns,eff_rel_ratio\n");
    b_note("media: transmittance estimators on Georgiev et al. 2019 profiles, t_max = 1, %ld estimates each", n);
    b_note("eff = 1/(var x cost), cost in lookups (eff_lk) or ns (eff_ns); rel = eff_lk / eff_lk(ratio tracking)");
    b_note("%-9s %5s %-13s %9s %9s %10s %8s %8s %10s %10s %8s", "profile", "tight", "estimator", "mean", "exact",
           "var(mse)", "lookups", "ns", "eff_lk", "eff_ns", "rel");
    for (p = 0; p < P_COUNT; ++p)
        for (ti = 0; ti < 3; ++ti) {
            float mx, mn;
            double eff_ratio = 0.0, Tref = exp(-prof_tau1(p));
            appear_majorant_segment seg;
            prof_bounds(p, &mx, &mn);
            seg = appear_majorant_make(HUGE_VALF, mx / tights[ti] * 1.000001f, mn * tights[ti] * 0.999999f);
            for (e = 0; e < N_EST; ++e) {
                appear_tracker_params prm = appear_tracker_defaults(ests[e].kind);
                double s1 = 0, s2 = 0, lk = 0, t0, ns, var, mse, mean, effl, effn;
                uint64_t rs = 12345u + (uint64_t)(p * 100 + ti * 10 + e);
                long i;
                prm.rr_threshold = ests[e].rr;
                if (ests[e].comb_rate > 0.0f) prm.comb_rate = ests[e].comb_rate;
                if (ests[e].comb > 0) prm.comb = ests[e].comb;
                prm.control = ests[e].control;
                t0 = now_ns();
                for (i = 0; i < n; ++i) {
                    appear_tracker tr;
                    float t;
                    appear_tracker_init(&tr, ests[e].kind, 1.0f, &seg, 1, &prm);
                    for (;;) {
                        float u1 = rngf(&rs), u2 = rngf(&rs);
                        if (!appear_tracker_next(&tr, u1, u2, &t)) break;
                        appear_tracker_feed(&tr, prof_sigma(p, t));
                    }
                    s1 += tr.T; s2 += (double)tr.T * tr.T; lk += tr.lookups;
                }
                ns = (now_ns() - t0) / n;
                mean = s1 / n;
                var = s2 / n - mean * mean;
                var = var > 0 ? var : 0;
                mse = var + (mean - Tref) * (mean - Tref);
                lk /= n;
                if (ests[e].kind == APPEAR_TRACK_RAY_MARCH) var = mse; /* biased: use the MSE */
                effl = var > 0 && lk > 0 ? 1.0 / (var * lk) : INFINITY;
                effn = var > 0 ? 1.0 / (var * ns) : INFINITY;
                if (e == 0) eff_ratio = effl;
                b_note("%-9s %5.2f %-13s %9.5f %9.5f %10.3e %8.1f %8.0f %10.3g %10.3g %8.3g", prof_name[p], tights[ti], ests[e].name,
                       mean, Tref, var, lk, ns, effl, effn, eff_ratio > 0 ? effl / eff_ratio : 0.0);
                if (csv) fprintf(csv, "%s,%g,%s,%.7g,%.7g,%.6g,%.6g,%.4g,%.4g,%.6g,%.6g,%.6g\n", prof_name[p], tights[ti], ests[e].name,
                                 mean, Tref, var, mse, lk, ns, effl, effn, eff_ratio > 0 ? effl / eff_ratio : 0.0);
            }
        }
    if (csv) fclose(csv);
    b_note("media: CSV in bench/out/media.csv");
}

#else
void bench_media_homog(void) {}
void bench_media(void) {}
#endif
