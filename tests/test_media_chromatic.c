/* tests/test_media_chromatic.c - the chromatic caller-driven tracker of
   appear.h (appear_ctracker, SECTION media, "Chromatic heterogeneous
   media").

   suite_media_chromatic_ratio  RATIO and NEXT_FLIGHT: every channel within
                                4 SE of exp(-tau_i) on chromatic versions of
                                the Georgiev et al. 2019 profiles (channel i
                                density k_i * profile, k = (0.02, 0.2, 2):
                                channels 10x and 100x apart), majorant
                                tightness 1 and 0.05, per-channel and common
                                (max over channels) majorants, 1 and 8
                                segments.
   suite_media_chromatic_delta  DELTA: constant chromatic medium against the
                                homogeneous closed forms (pass weight, and
                                the collision-distance histogram weighted by
                                weight_i), heterogeneous energy identity
                                E[w_i sigma_i(t) 1{coll}] + E[w_i 1{pass}]
                                = 1 and E[w_i 1{pass}] = T_i; grey input
                                reproduces the scalar tracker.
   suite_media_chromatic_furnace  the example tracer (examples/tracer.c,
                                MED_CLOUD_CHROMATIC: appear_ctracker free
                                flights with the path's hero, chromatic
                                ratio-tracked shadow rays) renders a
                                chromatic heterogeneous cloud of albedo 1
                                (sigma_t peak (1.2, 4, 12)) in a white
                                furnace as 1 in every channel: object mean
                                within 5 SE, every pixel within 6 pixel
                                sigmas, no non-finite sample.
   suite_media_chromatic_edge   t_max 0 / Inf, empty segments, NaN / Inf /
                                negative densities, violated majorants,
                                invalid setups, the callback wrapper, and an
                                adversarial fuzz (termination, finite
                                results, finite lookup positions). */
#include "harness.h"
#include "profiles.h"
#include "../examples/tracer.h"
#include <float.h>
#include <math.h>
#include <string.h>

#ifndef APPEAR_NO_MEDIA

#define NCH APPEAR_SPECTRUM_SAMPLES

static const double chan_k[3] = { 0.02, 0.2, 2.0 };

static double kch(int i) { return chan_k[i % 3]; }

/* (h_rng_make hashes its seed too now; this extra hash was written when the
   streams of nearby seeds were the same stream shifted by a few draws) */
static h_rng rng_for(uint64_t seed)
{
    uint64_t z = seed * 0xD1B54A32D192ED03ull + 0x2545F4914F6CDD1Dull;
    z = (z ^ (z >> 32)) * 0x9E3779B97F4A7C15ull;
    return h_rng_make(z ^ (z >> 29));
}

static double prof_max(int p)
{
    static const double MX[P_COUNT] = { 2.0, 3.5, 4.5, 3.0, 4.0, 4.0 };
    return MX[p];
}

/* chromatic density: k_i * profile, rounded to float (monotone rounding:
   below the float majorants made by make_csegments) */
static appear_spectrum csigma(int p, double x)
{
    appear_spectrum s;
    int i;
    double v = prof_sigma(p, x);
    for (i = 0; i < NCH; ++i) s.v[i] = (float)(kch(i) * v);
    return s;
}

static float up_float(double x)
{
    float f = (float)x;
    if ((double)f < x) f = nextafterf(f, 1e30f);
    return f;
}

/* n_seg segments over [0, 1]: per-segment max by dense sampling plus the
   derivative slack (|sigma'| <= 30), divided by tight; per channel
   (k_i max / tight) or common (max over channels). */
static void make_csegments(int p, int n_seg, double tight, int common,
                           appear_cmajorant_segment *seg)
{
    int i, j, c;
    for (i = 0; i < n_seg; ++i) {
        double a = (double)i / n_seg, b = (double)(i + 1) / n_seg, mx;
        if (n_seg == 1)
            mx = prof_max(p);
        else {
            mx = -1e30;
            for (j = 0; j <= 2000; ++j) {
                double s = prof_sigma(p, a + (b - a) * j / 2000.0);
                mx = s > mx ? s : mx;
            }
            mx += 30.0 * (b - a) / 4000.0 + 1e-9;
            if (p == P_CONST) mx = 2.0;
        }
        seg[i].t_end = i == n_seg - 1 ? 1.0f : (float)b;
        for (c = 0; c < NCH; ++c)
            seg[i].sigma_maj.v[c] = up_float((common ? 2.0 : kch(c)) * mx / tight);
    }
}

static void crun(appear_ctracker *tr, int p, h_rng *r)
{
    float t;
    float tu1, tu2; /* drawn in this order (a call's arguments have none) */
    while ((tu1 = h_randf(r), tu2 = h_randf(r), appear_ctracker_next(tr, tu1, tu2, &t)))
        appear_ctracker_feed(tr, csigma(p, (double)t));
}

/* running mean / standard error */
typedef struct {
    double s, s2;
    long n;
} acc_t;
static void acc_add(acc_t *a, double x)
{
    a->s += x;
    a->s2 += x * x;
    a->n++;
}
static double acc_mean(const acc_t *a) { return a->n ? a->s / a->n : 0.0; }
static double acc_se(const acc_t *a)
{
    double m = acc_mean(a);
    return a->n ? sqrt(fmax(a->s2 / a->n - m * m, 0.0) / a->n) : 0.0;
}

/* ---------------------------------------------------------------------- */
void suite_media_chromatic_ratio(void)
{
    static const double tights[] = { 1.0, 0.05 };
    static const int kinds[] = { APPEAR_TRACK_RATIO, APPEAR_TRACK_NEXT_FLIGHT };
    appear_cmajorant_segment seg[8];
    int p, ti, ns, cm, k, c;
    long n = h_n(16000);
    double worst = 0.0;

    h_case("media chromatic: RATIO / NEXT_FLIGHT every channel within 4 SE of exp(-tau_i)");
    for (p = 0; p < P_COUNT; ++p)
        for (ti = 0; ti < 2; ++ti)
            for (ns = 0; ns < 2; ++ns)
                for (cm = 0; cm < 2; ++cm) {
                    int nseg = ns ? 8 : 1;
                    make_csegments(p, nseg, tights[ti], cm, seg);
                    for (k = 0; k < 2; ++k) {
                        acc_t a[NCH];
                        double lk = 0.0;
                        unsigned flags = 0;
                        long i, neg = 0;
                        h_rng r =
                            rng_for((uint64_t)(5000 + p * 100 + ti * 20 + ns * 10 + cm * 3 + k));
                        memset(a, 0, sizeof a);
                        for (i = 0; i < n; ++i) {
                            appear_ctracker tr;
                            appear_ctracker_init(&tr, kinds[k], 1.0f, seg, nseg, h_randf(&r), 0);
                            crun(&tr, p, &r);
                            flags |= tr.flags;
                            lk += tr.lookups;
                            if (!tr.done) {
                                h_fail("not done");
                                break;
                            }
                            for (c = 0; c < NCH; ++c) {
                                acc_add(&a[c], tr.T.v[c]);
                                neg += tr.T.v[c] < 0.0f;
                                if (!h_finite(tr.T.v[c]) || tr.T.v[c] != tr.weight.v[c]) {
                                    h_fail("T %g weight %g", tr.T.v[c], tr.weight.v[c]);
                                    i = n;
                                    break;
                                }
                            }
                        }
                        H_CHECK(flags == 0 && neg == 0, "%s %s: flags %u, %ld negative",
                                prof_name[p], k ? "next_flight" : "ratio", flags, neg);
                        for (c = 0; c < NCH; ++c) {
                            double Tref = exp(-kch(c) * prof_tau(p, 1.0));
                            double m = acc_mean(&a[c]), se = acc_se(&a[c]),
                                   z = se > 0 ? fabs(m - Tref) / se : 0;
                            if (se > 1e-4 * Tref)
                                worst = z > worst ? z : worst; /* else the 2e-5 floor rules */
                            H_CHECK(fabs(m - Tref) <= 4.0 * se + 2e-5 * Tref,
                                    "%s %s tight %g seg %d %s ch %d: mean %.6g vs T %.6g (%.1f SE, "
                                    "se %.2g, lookups %.1f)",
                                    k ? "next_flight" : "ratio", prof_name[p], tights[ti], nseg,
                                    cm ? "common" : "per-channel", c, m, Tref, z, se, lk / n);
                        }
                        if (p == P_COS && ns == 0)
                            h_measure("chromatic tracker",
                                      "%s cosine tight %g %s: T = (%.5f %.5f %.5f), "
                                      "se (%.2g %.2g %.2g), ref (%.5f %.5f %.5f), lookups %.2f",
                                      k ? "next_flight" : "ratio", tights[ti],
                                      cm ? "common" : "per-channel", acc_mean(&a[0]),
                                      acc_mean(&a[1]), acc_mean(&a[2]), acc_se(&a[0]),
                                      acc_se(&a[1]), acc_se(&a[2]), exp(-kch(0) * prof_tau(p, 1.0)),
                                      exp(-kch(1) * prof_tau(p, 1.0)),
                                      exp(-kch(2) * prof_tau(p, 1.0)), lk / n);
                    }
                }
    h_measure("chromatic tracker",
              "RATIO/NEXT_FLIGHT: %d cells x %d channels, largest deviation %.2f SE (cells with se "
              "> 1e-4 T)",
              P_COUNT * 2 * 2 * 2 * 2, NCH, worst);

    h_case("media chromatic: common majorant RATIO = plain ratio tracking per channel (same walk, "
           "same T)");
    {
        h_rng r = h_rng_make(99);
        long i;
        make_csegments(P_BUMP, 8, 0.5, 1, seg);
        for (i = 0; i < h_n(2000); ++i) {
            appear_ctracker tr;
            appear_tracker st[NCH];
            appear_majorant_segment sseg[8];
            float t, u1, u2;
            int j, live;
            for (j = 0; j < 8; ++j)
                sseg[j] = appear_majorant_make(seg[j].t_end, seg[j].sigma_maj.v[0], 0.0f);
            appear_ctracker_init(&tr, APPEAR_TRACK_RATIO, 1.0f, seg, 8, h_randf(&r), 0);
            for (c = 0; c < NCH; ++c)
                appear_tracker_init(&st[c], APPEAR_TRACK_RATIO, 1.0f, sseg, 8, 0);
            for (;;) {
                u1 = h_randf(&r);
                u2 = h_randf(&r);
                live = appear_ctracker_next(&tr, u1, u2, &t);
                for (c = 0; c < NCH; ++c) {
                    float ts;
                    if (appear_tracker_next(&st[c], u1, u2, &ts)) {
                        appear_tracker_feed(&st[c], csigma(P_BUMP, (double)ts).v[c]);
                        if (!live || ts != t) {
                            h_fail("walks differ: %g vs %g", t, ts);
                            i = 1 << 30;
                        }
                    }
                }
                if (!live) break;
                appear_ctracker_feed(&tr, csigma(P_BUMP, (double)t));
            }
            for (c = 0; c < NCH; ++c)
                /* the same bits in IEEE builds; -ffast-math may reassociate 1 - s/m */
                if (i < (1 << 30) && !(fabsf(tr.T.v[c] - st[c].T) <= 1e-6f * fabsf(st[c].T) ||
                                       (st[c].T == 0.0f && st[c].done))) {
                    h_fail("ch %d: %g vs scalar %g", c, tr.T.v[c], st[c].T);
                    i = 1 << 30;
                }
        }
    }
}

/* ---------------------------------------------------------------------- */
typedef struct {
    int p;
    int constant;
    appear_spectrum s;
} cdens_ctx;
static appear_spectrum cdens_cb(void *ctx, float t)
{
    cdens_ctx *d = (cdens_ctx *)ctx;
    return d->constant ? d->s : csigma(d->p, (double)t);
}
static float rng_cb(void *ctx) { return h_randf((h_rng *)ctx); }

/* cm: 0 DELTA per-channel majorants, 1 DELTA common majorant, 2 SPECTRAL */
#define CM_NAME(cm) ((cm) == 0 ? "per-channel" : (cm) == 1 ? "common" : "spectral tracking")
#define CM_KIND(cm) ((cm) == 2 ? APPEAR_TRACK_SPECTRAL : APPEAR_TRACK_DELTA)
void suite_media_chromatic_delta(void)
{
    enum { NB = 10 };
    static const double tights[] = { 1.0, 0.05 };
    long n = h_n(200000);
    int ti, cm, c, b, p;
    appear_cmajorant_segment seg[8];

    h_case("media chromatic: DELTA / SPECTRAL on a constant chromatic medium vs the homogeneous "
           "closed forms");
    for (ti = 0; ti < 2; ++ti)
        for (cm = 0; cm < 3; ++cm) {
            /* sigma = (0.05, 0.5, 5), d = 1 */
            appear_spectrum sig = appear_spectrum_rgb(0.05f, 0.5f, 5.0f);
            double d = 1.0;
            acc_t pass[NCH], hist[NCH][NB];
            long i;
            unsigned flags = 0;
            h_rng r = rng_for((uint64_t)(700 + ti * 2 + cm));
            cdens_ctx ctx;
            ctx.p = 0;
            ctx.constant = 1;
            ctx.s = sig;
            memset(pass, 0, sizeof pass);
            memset(hist, 0, sizeof hist);
            for (c = 0; c < NCH; ++c)
                seg[0].sigma_maj.v[c] = up_float((cm == 1 ? 5.0 : sig.v[c]) / tights[ti]);
            seg[0].t_end = HUGE_VALF;
            for (i = 0; i < n; ++i) {
                appear_ctracker tr;
                appear_ctracker_init(&tr, CM_KIND(cm), (float)d, seg, 1, h_randf(&r), 0);
                appear_ctracker_run(&tr, cdens_cb, &ctx, rng_cb, &r);
                flags |= tr.flags;
                for (c = 0; c < NCH; ++c) {
                    acc_add(&pass[c], tr.collided ? 0.0 : tr.weight.v[c]);
                    if (tr.T.v[c] != (tr.collided ? 0.0f : tr.weight.v[c]))
                        h_fail("T %g vs weight", tr.T.v[c]);
                    for (b = 0; b < NB; ++b) {
                        int in = tr.collided && (int)(tr.t / d * NB) == b;
                        acc_add(&hist[c][b], in ? tr.weight.v[c] : 0.0);
                    }
                }
            }
            H_CHECK(flags == 0, "flags %u", flags);
            for (c = 0; c < NCH; ++c) {
                double s = sig.v[c], T = exp(-s * d), m = acc_mean(&pass[c]), se = acc_se(&pass[c]);
                H_CHECK(fabs(m - T) <= 4 * se + 1e-6,
                        "tight %g %s ch %d: E[w 1{pass}] %.6g vs T %.6g (se %.2g)", tights[ti],
                        CM_NAME(cm), c, m, T, se);
                for (b = 0; b < NB; ++b) {
                    double lo = d * b / NB, hi = d * (b + 1) / NB;
                    double ref = (exp(-s * lo) - exp(-s * hi)) / s; /* int_bin T_i(t) dt */
                    double mb = acc_mean(&hist[c][b]), sb = acc_se(&hist[c][b]);
                    H_CHECK(
                        fabs(mb - ref) <= 4 * sb + 1e-6 * ref,
                        "tight %g %s ch %d bin %d: E[w 1{t in bin}] %.6g vs int T %.6g (%.1f SE)",
                        tights[ti], CM_NAME(cm), c, b, mb, ref, sb > 0 ? fabs(mb - ref) / sb : 0.0);
                }
                if (ti == 1 && cm == 0)
                    h_measure("chromatic delta",
                              "constant (0.05,0.5,5) tight 0.05 ch %d: E[w 1{pass}] %.5f (se %.2g) "
                              "vs %.5f",
                              c, m, se, T);
            }
        }

    h_case("media chromatic: DELTA, constant medium, exact majorants = appear_homogeneous_sample");
    {
        appear_spectrum sig = appear_spectrum_rgb(0.05f, 0.5f, 5.0f);
        h_rng r = rng_for(4711);
        long i, bad = 0;
        float d = 1.3f;
        seg[0] = appear_cmajorant_make_constant(sig);
        for (i = 0; i < h_n(100000); ++i) {
            appear_ctracker tr;
            appear_medium_sample ms;
            float uc = h_randf(&r), u = h_randf(&r), t;
            appear_ctracker_init(&tr, APPEAR_TRACK_DELTA, d, seg, 1, uc, 0);
            if (appear_ctracker_next(&tr, h_randf(&r), u, &t)) {
                appear_ctracker_feed(&tr, sig);
                float q40 = h_randf(&r), q41 = h_randf(&r); /* in this order */
                appear_ctracker_next(&tr, q40, q41, &t); /* accepts: sigma = mu */
            }
            appear_homogeneous_sample(sig, d, uc, u, &ms);
            bad +=
                !(tr.done && tr.collided == ms.scattered && tr.t == ms.t && tr.hero == ms.channel);
            for (c = 0; c < NCH; ++c)
                bad += !(fabsf(tr.weight.v[c] - ms.weight.v[c]) <= 1e-5f * ms.weight.v[c] + 1e-30f);
        }
        H_CHECK(bad == 0, "%ld mismatches (t, collided, hero or weight vs the homogeneous sampler)",
                bad);
    }

    h_case("media chromatic: DELTA / SPECTRAL energy identity and pass weight on the chromatic "
           "profiles");
    for (p = 0; p < P_COUNT; ++p)
        for (ti = 0; ti < 2; ++ti)
            for (cm = 0; cm < 3; ++cm) {
                acc_t en[NCH], pass[NCH];
                double lk = 0.0;
                long i, nn = h_n(40000);
                unsigned flags = 0;
                h_rng r = rng_for((uint64_t)(900 + p * 10 + ti * 2 + cm));
                memset(en, 0, sizeof en);
                memset(pass, 0, sizeof pass);
                make_csegments(p, 8, tights[ti], cm == 1, seg);
                for (i = 0; i < nn; ++i) {
                    appear_ctracker tr;
                    appear_ctracker_init(&tr, CM_KIND(cm), 1.0f, seg, 8, h_randf(&r), 0);
                    crun(&tr, p, &r);
                    flags |= tr.flags;
                    lk += tr.lookups;
                    for (c = 0; c < NCH; ++c) {
                        double w = tr.weight.v[c];
                        double sc = tr.collided ? (double)csigma(p, (double)tr.t).v[c] : 0.0;
                        acc_add(&en[c], tr.collided ? w * sc : w);
                        acc_add(&pass[c], tr.collided ? 0.0 : w);
                    }
                }
                H_CHECK(flags == 0, "flags %u", flags);
                for (c = 0; c < NCH; ++c) {
                    double T = exp(-kch(c) * prof_tau(p, 1.0));
                    double me = acc_mean(&en[c]), se = acc_se(&en[c]), mp = acc_mean(&pass[c]),
                           sp = acc_se(&pass[c]);
                    H_CHECK(fabs(me - 1.0) <= 4 * se + 1e-6,
                            "%s tight %g %s ch %d: energy %.6f (se %.2g)", prof_name[p], tights[ti],
                            CM_NAME(cm), c, me, se);
                    H_CHECK(fabs(mp - T) <= 4 * sp + 1e-6,
                            "%s tight %g %s ch %d: E[w 1{pass}] %.6g vs %.6g (se %.2g)",
                            prof_name[p], tights[ti], CM_NAME(cm), c, mp, T, sp);
                }
                if (p == P_COS)
                    h_measure("chromatic free flight",
                              "cosine tight %g %-17s: lookups %.2f, se of E[w 1{pass}] (%.2g %.2g "
                              "%.2g), of the energy (%.2g %.2g %.2g)",
                              tights[ti], CM_NAME(cm), lk / nn, acc_se(&pass[0]), acc_se(&pass[1]),
                              acc_se(&pass[2]), acc_se(&en[0]), acc_se(&en[1]), acc_se(&en[2]));
            }

    h_case(
        "media chromatic: grey input reproduces the scalar delta / ratio / next-flight trackers");
    {
        static const int kinds[] = { APPEAR_TRACK_DELTA, APPEAR_TRACK_RATIO,
                                     APPEAR_TRACK_NEXT_FLIGHT };
        appear_majorant_segment sseg[8];
        int j, k;
        long i, bad = 0;
        make_csegments(P_COS, 8, 0.5, 1, seg);
        for (j = 0; j < 8; ++j)
            sseg[j] = appear_majorant_make(seg[j].t_end, seg[j].sigma_maj.v[0], 0.0f);
        for (k = 0; k < 3; ++k) {
            h_rng r = rng_for((uint64_t)(31 + k));
            for (i = 0; i < h_n(20000); ++i) {
                appear_ctracker tr;
                appear_tracker st;
                float t, ts, uc = h_randf(&r);
                h_rng r2 = r;
                appear_ctracker_init(&tr, kinds[k], 1.0f, seg, 8, uc, 0);
                float tu1, tu2; /* drawn in this order (a call's arguments have none) */
                while ((tu1 = h_randf(&r), tu2 = h_randf(&r), appear_ctracker_next(&tr, tu1, tu2, &t)))
                    appear_ctracker_feed(&tr, appear_spectrum_splat((float)prof_sigma(P_COS, t)));
                appear_tracker_init(&st, kinds[k], 1.0f, sseg, 8, 0);
                while ((tu1 = h_randf(&r2), tu2 = h_randf(&r2), appear_tracker_next(&st, tu1, tu2, &ts)))
                    appear_tracker_feed(&st, (float)prof_sigma(P_COS, ts));
                for (c = 0; c < NCH; ++c) {
                    float want = kinds[k] == APPEAR_TRACK_DELTA
                                     ? (st.collided ? 1.0f / (float)prof_sigma(P_COS, st.t) : 1.0f)
                                     : st.T;
                    bad +=
                        !(tr.collided == st.collided && tr.t == st.t && tr.lookups == st.lookups &&
                          fabsf(tr.weight.v[c] - want) <= 1e-5f * fabsf(want) + 1e-7f);
                }
            }
            H_CHECK(bad == 0, "kind %d: %ld channel results differ from the scalar tracker",
                    kinds[k], bad);
        }
    }
}

/* ---------------------------------------------------------------------- */
static appear_ctracker crun_const(int kind, float t_max, const appear_cmajorant_segment *seg,
                                  int nseg, appear_spectrum sigma, float uc,
                                  const appear_tracker_params *prm, uint64_t seed)
{
    appear_ctracker tr;
    float t;
    h_rng r = h_rng_make(seed);
    appear_ctracker_init(&tr, kind, t_max, seg, nseg, uc, prm);
    float tu1, tu2; /* drawn in this order (a call's arguments have none) */
    while ((tu1 = h_randf(&r), tu2 = h_randf(&r), appear_ctracker_next(&tr, tu1, tu2, &t))) {
        if (!(t >= 0.0f && t <= t_max && t <= FLT_MAX)) {
            h_fail("lookup at t = %g (t_max %g)", t, t_max);
            break;
        }
        appear_ctracker_feed(&tr, sigma);
    }
    return tr;
}

static int spec_eq(appear_spectrum a, float v)
{
    int i, ok = 1;
    for (i = 0; i < NCH; ++i) ok &= a.v[i] == v;
    return ok;
}

void suite_media_chromatic_edge(void)
{
    static const int kinds[] = { APPEAR_TRACK_DELTA, APPEAR_TRACK_RATIO, APPEAR_TRACK_NEXT_FLIGHT,
                                 APPEAR_TRACK_SPECTRAL };
    enum { NK = 4 };
    appear_cmajorant_segment seg[4];
    appear_spectrum one = appear_spectrum_rgb(0.5f, 1.0f, 2.0f);
    int k, c;
    h_rng r = h_rng_make(4242);

    h_case("media chromatic edge: t_max = 0 gives T = weight = 1 with no lookup");
    for (k = 0; k < NK; ++k) {
        appear_ctracker tr;
        seg[0] = appear_cmajorant_make_constant(appear_spectrum_rgb(1.0f, 2.0f, 4.0f));
        tr = crun_const(kinds[k], 0.0f, seg, 1, one, 0.5f, 0, 1);
        H_CHECK(tr.done && spec_eq(tr.T, 1.0f) && spec_eq(tr.weight, 1.0f) && tr.lookups == 0 &&
                    tr.flags == 0,
                "kind %d: T %g lookups %d flags %u", kinds[k], tr.T.v[0], tr.lookups, tr.flags);
        tr = crun_const(kinds[k], 0.0f, 0, 0, one, 0.5f, 0, 1);
        H_CHECK(tr.done && spec_eq(tr.T, 1.0f) && tr.flags == 0, "kind %d, no segments, t_max 0",
                kinds[k]);
    }

    h_case("media chromatic edge: t_max = Inf, medium confined to [0, 2) (and an empty segment)");
    for (k = 0; k < NK; ++k) {
        acc_t a[NCH];
        long i, n = h_n(20000);
        appear_spectrum sg = appear_spectrum_rgb(0.05f, 0.5f, 1.5f);
        memset(a, 0, sizeof a);
        seg[0] = appear_cmajorant_make(1.0f, appear_spectrum_rgb(0.1f, 1.0f, 3.0f));
        seg[1] = appear_cmajorant_make(1.0f, appear_spectrum_rgb(7.0f, 7.0f, 7.0f)); /* empty */
        seg[2] = appear_cmajorant_make(2.0f, appear_spectrum_rgb(0.1f, 1.0f, 3.0f));
        seg[3] = appear_cmajorant_make(HUGE_VALF, appear_spectrum_splat(0.0f));
        for (i = 0; i < n; ++i) {
            appear_ctracker tr =
                crun_const(kinds[k], HUGE_VALF, seg, 4, sg, h_randf(&r), 0, (uint64_t)i + 7);
            H_CHECK(tr.done && tr.flags == 0, "kind %d: flags %u", kinds[k], tr.flags);
            for (c = 0; c < NCH; ++c) acc_add(&a[c], tr.T.v[c]);
        }
        for (c = 0; c < NCH; ++c) {
            double T = exp(-2.0 * sg.v[c]);
            H_CHECK(fabs(acc_mean(&a[c]) - T) <= 4 * acc_se(&a[c]) + 1e-5,
                    "kind %d ch %d: %g vs %g (se %.2g)", kinds[k], c, acc_mean(&a[c]), T,
                    acc_se(&a[c]));
        }
    }

    h_case("media chromatic edge: t_max = Inf in an unbounded medium terminates; sigma 0 "
           "truncates, flagged");
    for (k = 0; k < NK; ++k) {
        appear_tracker_params prm = appear_tracker_defaults(kinds[k]);
        appear_ctracker tr;
        prm.max_lookups = 1000;
        seg[0] = appear_cmajorant_make_constant(appear_spectrum_rgb(1.0f, 2.0f, 4.0f));
        tr = crun_const(kinds[k], HUGE_VALF, seg, 1, appear_spectrum_rgb(0.5f, 1.0f, 3.0f), 0.4f, 0,
                        3);
        H_CHECK(tr.done && tr.flags == 0 && spec_eq(tr.T, 0.0f), "kind %d: T %g flags %u", kinds[k],
                tr.T.v[0], tr.flags);
        tr = crun_const(kinds[k], HUGE_VALF, seg, 1, appear_spectrum_splat(0.0f), 0.4f, &prm, 3);
        H_CHECK(tr.done && tr.lookups == 1000 && (tr.flags & APPEAR_TRACK_TRUNCATED) &&
                    spec_eq(tr.T, 0.0f),
                "kind %d sigma 0: lookups %d flags %u", kinds[k], tr.lookups, tr.flags);
    }

    h_case("media chromatic edge: NaN / Inf / negative density in any channel: BAD_DENSITY, zero "
           "results");
    for (k = 0; k < NK; ++k) {
        static const float badv[] = { NAN, HUGE_VALF, -1.0f, -HUGE_VALF };
        int b;
        for (b = 0; b < 4; ++b)
            for (c = 0; c < NCH; ++c) {
                appear_spectrum s = appear_spectrum_splat(0.5f);
                appear_ctracker tr;
                s.v[c] = badv[b];
                seg[0] = appear_cmajorant_make_constant(appear_spectrum_rgb(1.0f, 2.0f, 4.0f));
                tr = crun_const(kinds[k], 3.0f, seg, 1, s, 0.7f, 0, 5);
                H_CHECK(tr.done && (tr.flags & APPEAR_TRACK_BAD_DENSITY) && spec_eq(tr.T, 0.0f) &&
                            spec_eq(tr.weight, 0.0f) && !tr.collided && tr.lookups == 1,
                        "kind %d bad %g in ch %d: flags %u T %g", kinds[k], badv[b], c, tr.flags,
                        tr.T.v[0]);
            }
    }

    h_case("media chromatic edge: invalid setups give BAD_INPUT and zero results");
    for (k = 0; k <= NK; ++k) {
        int kind = k < NK ? kinds[k] : APPEAR_TRACK_URM;
        appear_ctracker tr;
        int j;
        for (j = 0; j < 8; ++j) {
            float tmax = 2.0f, uc = 0.3f;
            int ns = 2;
            const appear_cmajorant_segment *sp = seg;
            seg[0] = appear_cmajorant_make(1.0f, appear_spectrum_rgb(1.0f, 2.0f, 3.0f));
            seg[1] = appear_cmajorant_make(3.0f, appear_spectrum_rgb(1.0f, 2.0f, 3.0f));
            switch (j) {
            case 0:
                if (k < NK) continue;
                break; /* unsupported kind */
            case 1: tmax = NAN; break;
            case 2: tmax = -1.0f; break;
            case 3: uc = NAN; break;
            case 4: seg[1].t_end = 0.5f; break; /* decreasing */
            case 5: seg[1].sigma_maj.v[2] = NAN; break;
            case 6: seg[0].sigma_maj.v[1] = -1.0f; break;
            default: tmax = 5.0f; break; /* segments end before t_max */
            }
            if (j == 3 && k == 0) {
                sp = 0;
                ns = 1;
                uc = 0.3f;
            } /* NULL segments */
            tr = crun_const(kind, tmax, sp, ns, one, uc, 0, 9);
            H_CHECK(tr.done && (tr.flags & APPEAR_TRACK_BAD_INPUT) && spec_eq(tr.T, 0.0f) &&
                        tr.lookups == 0,
                    "kind %d case %d: flags %u T %g", kind, j, tr.flags, tr.T.v[0]);
        }
    }

    h_case("media chromatic edge: violated majorant is flagged, NEGATIVE set exactly when a result "
           "< 0");
    for (k = 0; k < NK; ++k) {
        long i, n = h_n(5000), neg = 0;
        seg[0] = appear_cmajorant_make_constant(appear_spectrum_rgb(1.0f, 1.0f, 1.0f));
        for (i = 0; i < n; ++i) {
            appear_ctracker tr =
                crun_const(kinds[k], 1.0f, seg, 1, appear_spectrum_rgb(0.5f, 3.0f, 0.2f),
                           h_randf(&r), 0, (uint64_t)i);
            int anyneg = 0;
            for (c = 0; c < NCH; ++c) {
                anyneg |= tr.T.v[c] < 0.0f || tr.weight.v[c] < 0.0f;
                H_CHECK(h_finite(tr.T.v[c]) && h_finite(tr.weight.v[c]), "non-finite");
            }
            neg += anyneg;
            H_CHECK(tr.lookups == 0 || (tr.flags & APPEAR_TRACK_MAJORANT_VIOLATED),
                    "kind %d: not flagged", kinds[k]);
            H_CHECK(anyneg == ((tr.flags & APPEAR_TRACK_NEGATIVE) != 0),
                    "kind %d: NEGATIVE %u vs %d", kinds[k], tr.flags, anyneg);
        }
        H_CHECK(neg > 0, "kind %d: expected some negative estimates", kinds[k]);
    }

    h_case("media chromatic edge: weight = beta / avg(r_u), r_u[hero] = 1; no segments with t_max "
           "> 0");
    for (k = 0; k < 2; ++k) {
        long i, bad = 0;
        appear_ctracker tr;
        seg[0] = appear_cmajorant_make(0.5f, appear_spectrum_rgb(0.3f, 2.0f, 9.0f));
        seg[1] = appear_cmajorant_make(HUGE_VALF, appear_spectrum_rgb(1.0f, 1.5f, 2.0f));
        for (i = 0; i < h_n(20000); ++i) {
            double avg = 0.0;
            tr = crun_const(kinds[k], 1.5f, seg, 2, appear_spectrum_rgb(0.2f, 1.0f, 1.5f),
                            h_randf(&r), 0, (uint64_t)i + 100);
            for (c = 0; c < NCH; ++c) avg += tr.r_u.v[c] / NCH;
            bad += tr.r_u.v[tr.hero] != 1.0f;
            for (c = 0; c < NCH; ++c)
                bad += !(fabs(tr.weight.v[c] - tr.beta.v[c] / avg) <=
                         1e-5 * fabs(tr.weight.v[c]) + 1e-30);
        }
        H_CHECK(bad == 0, "kind %d: %ld mismatches of weight vs beta / avg(r_u)", kinds[k], bad);
        tr = crun_const(kinds[k], 1.0f, seg, 0, one, 0.5f, 0, 1);
        H_CHECK(tr.done && (tr.flags & APPEAR_TRACK_BAD_INPUT) && spec_eq(tr.T, 0.0f),
                "n_seg 0, t_max 1");
    }

    h_case("media chromatic edge: extreme majorant ratios (1e-30 .. 1e30) stay finite (rescaling)");
    for (k = 0; k < NK; ++k) {
        long i;
        seg[0] = appear_cmajorant_make(1.0f, appear_spectrum_rgb(1e-30f, 1.0f, 1e30f));
        seg[1] = appear_cmajorant_make(HUGE_VALF, appear_spectrum_rgb(1e30f, 1e-3f, 1e-30f));
        for (i = 0; i < 300; ++i) {
            appear_tracker_params prm = appear_tracker_defaults(kinds[k]);
            appear_ctracker tr;
            prm.max_lookups = 20000;
            tr = crun_const(kinds[k], 2.0f, seg, 2, appear_spectrum_rgb(0.0f, 1e-3f, 0.0f),
                            (float)(i % 3) / 3.0f + 0.1f, &prm, (uint64_t)i);
            H_CHECK(tr.done, "not done");
            for (c = 0; c < NCH; ++c)
                H_CHECK(h_finite(tr.T.v[c]) && h_finite(tr.weight.v[c]), "kind %d ch %d: T %g w %g",
                        kinds[k], c, tr.T.v[c], tr.weight.v[c]);
        }
    }

    h_case("media chromatic edge: adversarial fuzz (terminates, finite results, finite lookups in "
           "[0, t_max])");
    {
        long i, n = h_n(200000);
        for (i = 0; i < n; ++i) {
            appear_tracker_params prm = appear_tracker_defaults(APPEAR_TRACK_RATIO);
            appear_ctracker tr;
            appear_cmajorant_segment sg[3];
            int ns = (int)(h_randf(&r) * 4.0f), j, kind = kinds[i % NK], steps = 0;
            float tmax = (i & 1) ? h_adv_float(&r) : h_randf(&r) * 3.0f, t;
            prm.max_lookups = 200;
            for (j = 0; j < 3; ++j) {
                sg[j].t_end = (i & 2) ? h_adv_float(&r) : (float)(j + 1);
                for (c = 0; c < NCH; ++c)
                    sg[j].sigma_maj.v[c] = (i & 4) ? h_adv_float(&r) : h_randf(&r) * 5.0f;
            }
            if (i & 8) sg[ns > 0 ? ns - 1 : 0].t_end = HUGE_VALF;
            appear_ctracker_init(&tr, kind, tmax, sg, ns, (i & 16) ? h_adv_u(&r) : h_randf(&r),
                                 &prm);
            float tu1, tu2; /* drawn in this order (a call's arguments have none) */
            while ((tu1 = h_adv_u(&r), tu2 = h_adv_u(&r), appear_ctracker_next(&tr, tu1, tu2, &t))) {
                appear_spectrum s;
                if (!(t >= 0.0f && t <= tmax && t <= FLT_MAX)) {
                    h_fail("lookup at %g, t_max %g", t, tmax);
                    break;
                }
                for (c = 0; c < NCH; ++c) s.v[c] = (i & 32) ? h_adv_float(&r) : h_randf(&r) * 5.0f;
                appear_ctracker_feed(&tr, s);
                if (++steps > 1000) {
                    h_fail("no termination");
                    break;
                }
            }
            H_CHECK(tr.done && tr.lookups <= 200, "done %d lookups %d", tr.done, tr.lookups);
            for (c = 0; c < NCH; ++c)
                if (!(h_finite(tr.T.v[c]) && h_finite(tr.weight.v[c]))) {
                    h_fail("kind %d: T %g weight %g (t_max %g)", kind, tr.T.v[c], tr.weight.v[c],
                           tmax);
                    break;
                }
            if ((tr.flags & APPEAR_TRACK_NEGATIVE) && !(tr.flags & APPEAR_TRACK_MAJORANT_VIOLATED))
                h_fail("negative without a violated majorant (flags %u)", tr.flags);
        }
    }
}

/* ---------------------------------------------------------------------- */
void suite_media_chromatic_furnace(void)
{
#if TRACER_HAS_CTRACKER && !defined(H_NO_IMAGES) /* make check builds without the tracer */
    static tracer_scene sc;
    tracer_medium m;
    tracer_image img;
    tracer_options opt;
    appear_vec3 lo = appear_vec3_make(-0.45f, -0.45f, -0.45f),
                hi = appear_vec3_make(0.45f, 0.45f, 0.45f);
    int c, s;
    long i;
    h_case(
        "media chromatic furnace: chromatic heterogeneous cloud, albedo 1, renders 1 per channel");
    tracer_scene_init(&sc, "chromatic furnace");
    sc.env_top = sc.env_bottom = appear_spectrum_splat(1.0f);
    memset(&m, 0, sizeof m);
    m.kind = MED_CLOUD_CHROMATIC;
    m.lo = lo;
    m.hi = hi;
    m.phase = appear_phase_hg(appear_hg_make(0.3f));
    m.sigma_t = appear_spectrum_rgb(1.2f, 4.0f, 12.0f);
    m.albedo = appear_spectrum_splat(1.0f);
    s = tracer_add_box(&sc, lo, hi, tracer_add_material(&sc, tracer_mat_none()),
                       tracer_add_medium(&sc, m));
    sc.eye = appear_vec3_make(0.3f, 0.4f, 2.2f);
    sc.look = appear_vec3_make(0, 0, 0);
    sc.fov = 0.5f;
    memset(&opt, 0, sizeof opt);
    opt.w = h_quick() ? 32 : 64;
    opt.h = h_quick() ? 24 : 48;
    opt.spp = h_quick() ? 16 : 256;
    opt.threads = 2;
    opt.seed = 11;
    opt.pixel_centre = 1;
    if (tracer_render(&sc, &opt, &img)) {
        h_fail("render failed");
        return;
    }
    H_CHECK(img.nonfinite == 0, "%ld non-finite samples", img.nonfinite);
    for (c = 0; c < 3; ++c) {
        double sum = 0, var = 0, se, sig_pool, zmax = 0, mean;
        long n = 0;
        for (i = 0; i < (long)img.w * img.h; ++i)
            if (img.id[i] == s) {
                sum += img.rgb[3 * i + c];
                var += img.var[3 * i + c];
                n++;
            } else
                H_CHECK(img.rgb[3 * i + c] == 1.0f, "environment pixel %ld = %g", i,
                        img.rgb[3 * i + c]);
        if (n < 100) {
            h_fail("only %ld cloud pixels", n);
            break;
        }
        mean = sum / n;
        sig_pool = sqrt(var / n / opt.spp);
        se = sig_pool / sqrt((double)n);
        for (i = 0; i < (long)img.w * img.h; ++i) {
            double sg, z;
            if (img.id[i] != s) continue;
            sg = sqrt(img.var[3 * i + c] / opt.spp);
            sg = (sg > sig_pool ? sg : sig_pool) + 2e-4 / 6;
            z = fabs(img.rgb[3 * i + c] - 1.0) / sg;
            zmax = z > zmax ? z : zmax;
        }
        H_CHECK(fabs(mean - 1.0) <= 5 * se + 2e-4, "ch %d: mean %.5f (se %.2g)", c, mean, se);
        H_CHECK(zmax <= 6.0, "ch %d: a pixel is %.1f sigma from 1", c, zmax);
        h_measure("chromatic furnace",
                  "ch %d: %ld pixels, mean %.5f, se %.2e, pixel sigma %.4f, max dev %.1f sigma", c,
                  n, mean, se, sig_pool, zmax);
    }
    tracer_image_free(&img);
#else
    h_case("media chromatic furnace: the tracer has no chromatic tracker");
#endif
}

#else
void suite_media_chromatic_furnace(void) { h_case("media chromatic: compiled out"); }
void suite_media_chromatic_ratio(void) { h_case("media chromatic: compiled out"); }
void suite_media_chromatic_delta(void) { h_case("media chromatic: compiled out"); }
void suite_media_chromatic_edge(void) { h_case("media chromatic: compiled out"); }
#endif
