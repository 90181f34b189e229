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
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts); /* on-CPU time, see bench.c */
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

/* Chromatic media (appear_ctracker): channel i density k_i * profile,
   k = (0.02, 0.2, 2) (channels 10x and 100x apart), t_max = 1. Methods:
   the chromatic ratio / next-flight tracker with per-channel majorants
   (k_i max / tightness) and with one common majorant (the largest
   channel's), against the scalar ratio tracker run once per channel on its
   own majorant (3 walks). Cost: density lookups per spectrum estimate (a
   chromatic lookup returns the 3 channels, the scalar walks pay one lookup
   each); efficiency 1/(variance_i x cost) per channel, and its ratio to the
   3-walk scalar baseline. */
static const double ck[3] = { 0.02, 0.2, 2.0 };
void bench_media_chromatic(void)
{
    static const float tights[] = { 1.0f, 0.1f };
    static const char *const mname[] = { "scalar x3", "chroma ratio", "chroma ratio common", "chroma nf",
                                         "chroma nf common" };
    long n = b_quick() ? 2000 : 20000;
    int p, ti, m, c;
    b_note("media_chromatic: k = (0.02, 0.2, 2) x profile, t_max = 1, %ld estimates each; eff_i = 1/(var_i x "
           "lookups), rel_i = eff_i / eff_i(scalar x3)", n);
    b_note("%-9s %5s %-20s %7s %8s | %9s %9s %9s | %7s %7s %7s", "profile", "tight", "method", "lookups", "ns",
           "var_0", "var_1", "var_2", "rel_0", "rel_1", "rel_2");
    for (p = 0; p < P_COUNT; ++p)
        for (ti = 0; ti < 2; ++ti) {
            float mx, mn;
            double eff0[3] = { 0, 0, 0 };
            appear_majorant_segment sseg[3];
            appear_cmajorant_segment cs, cc;
            prof_bounds(p, &mx, &mn);
            for (c = 0; c < 3; ++c) {
                float mj = (float)(ck[c] * mx / tights[ti]) * 1.000001f;
                sseg[c] = appear_majorant_make(HUGE_VALF, mj, 0.0f);
                cs.sigma_maj.v[c] = mj;
                cc.sigma_maj.v[c] = (float)(ck[2] * mx / tights[ti]) * 1.000001f;
            }
            cs.t_end = cc.t_end = HUGE_VALF;
            for (m = 0; m < 5; ++m) {
                double s1[3] = { 0, 0, 0 }, s2[3] = { 0, 0, 0 }, var[3], lk = 0, t0, ns;
                uint64_t rs = 777u + (uint64_t)(p * 100 + ti * 10 + m) * 0x9E3779B97F4A7C15ull;
                long i;
                int kind = m >= 3 ? APPEAR_TRACK_NEXT_FLIGHT : APPEAR_TRACK_RATIO;
                const appear_cmajorant_segment *seg = (m == 2 || m == 4) ? &cc : &cs;
                t0 = now_ns();
                for (i = 0; i < n; ++i) {
                    float T[3], t;
                    if (m == 0) {
                        for (c = 0; c < 3; ++c) {
                            appear_tracker tr;
                            appear_tracker_init(&tr, APPEAR_TRACK_RATIO, 1.0f, &sseg[c], 1, 0);
                            for (;;) {
                                float u1 = rngf(&rs), u2 = rngf(&rs);
                                if (!appear_tracker_next(&tr, u1, u2, &t)) break;
                                appear_tracker_feed(&tr, (float)ck[c] * prof_sigma(p, t));
                            }
                            T[c] = tr.T;
                            lk += tr.lookups;
                        }
                    } else {
                        appear_ctracker tr;
                        appear_ctracker_init(&tr, kind, 1.0f, seg, 1, rngf(&rs), 0);
                        for (;;) {
                            float u1 = rngf(&rs), u2 = rngf(&rs), sg;
                            appear_spectrum s;
                            if (!appear_ctracker_next(&tr, u1, u2, &t)) break;
                            sg = prof_sigma(p, t);
                            for (c = 0; c < 3; ++c) s.v[c] = (float)ck[c] * sg;
                            appear_ctracker_feed(&tr, s);
                        }
                        for (c = 0; c < 3; ++c) T[c] = tr.T.v[c];
                        lk += tr.lookups;
                    }
                    for (c = 0; c < 3; ++c) { s1[c] += T[c]; s2[c] += (double)T[c] * T[c]; }
                }
                ns = (now_ns() - t0) / n;
                lk /= n;
                for (c = 0; c < 3; ++c) {
                    double mean = s1[c] / n;
                    var[c] = s2[c] / n - mean * mean;
                    var[c] = var[c] > 0 ? var[c] : 0;
                    if (m == 0) eff0[c] = var[c] > 0 ? 1.0 / (var[c] * lk) : 0.0;
                }
#define B_REL(c) (eff0[c] > 0 && var[c] > 0 ? 1.0 / (var[c] * lk) / eff0[c] : 0.0)
                b_note("%-9s %5.2f %-20s %7.2f %8.0f | %9.3g %9.3g %9.3g | %7.3g %7.3g %7.3g", prof_name[p],
                       tights[ti], mname[m], lk, ns, var[0], var[1], var[2], B_REL(0), B_REL(1), B_REL(2));
#undef B_REL
            }
        }
}

#else
void bench_media_homog(void) {}
void bench_media(void) {}
void bench_media_chromatic(void) {}
#endif
