/* tests/test_media.c - homogeneous free flight and the heterogeneous
   transmittance / free-flight trackers of appear.h (SECTION media).

   suite_media_homogeneous  transmittance vs double, chi-square of the
                            spectral-MIS free-flight distance vs the exact
                            mixture distribution, pdf/weight consistency,
                            per-channel unbiasedness, stability sweep.
   suite_media_trackers     every unbiased tracker on the canonical 1D
                            profiles of Georgiev et al. 2019 (constant,
                            cosine, Gaussian bump, hole, ramps up/down) with
                            tight and loose majorants (tightness 1, 0.1,
                            0.01), constant and piecewise (8 segments):
                            mean within 4 standard errors of the analytic
                            transmittance; chi-square of delta-tracking
                            collision distances vs the exact density.
   suite_media_edge         t_max = 0 / Inf, sigma = 0, majorant 0, huge
                            optical depth, NaN / negative density, violated
                            majorants, invalid setups, callback wrapper,
                            adversarial fuzz.

   The 1D chi-square tests bin distances (bins under 5 expected pooled by
   h_chi2_counts) and join the suite's Sidak family of chi-square tests. */
#include "harness.h"
#include "profiles.h"
#include <float.h>
#include <math.h>
#include <string.h>

#ifndef APPEAR_NO_MEDIA

/* ---------------------------------------------------------------------- */
/* profiles of Georgiev et al. 2019, on x in [0, 1]                        */
/* ---------------------------------------------------------------------- */
/* n_seg majorant segments over [0, 1]: per-segment max/min by dense
   sampling (derivative bound |sigma'| <= 30 covers the gap), then loosened:
   maj / tight, min * tight. n_seg = 1 uses the exact global bounds. */
static void make_segments(int p, int n_seg, double tight, appear_majorant_segment *seg)
{
    int i, j;
    for (i = 0; i < n_seg; ++i) {
        double a = (double)i / n_seg, b = (double)(i + 1) / n_seg, mx, mn;
        if (n_seg == 1) prof_bounds(p, &mx, &mn);
        else {
            mx = -1e30; mn = 1e30;
            for (j = 0; j <= 2000; ++j) {
                double s = prof_sigma(p, a + (b - a) * j / 2000.0);
                mx = s > mx ? s : mx; mn = s < mn ? s : mn;
            }
            mx += 30.0 * (b - a) / 4000.0 + 1e-9; mn -= 30.0 * (b - a) / 4000.0 + 1e-9;
            if (p == P_CONST) { mx = mn = 2.0; }
            if (mn < 0.0) mn = 0.0;
        }
        seg[i] = appear_majorant_make(i == n_seg - 1 ? 1.0f : (float)b, (float)(mx / tight), (float)(mn * tight));
        /* float rounding must keep them bounds */
        if ((double)seg[i].sigma_maj < mx / tight) seg[i].sigma_maj = nextafterf(seg[i].sigma_maj, 1e30f);
        if ((double)seg[i].sigma_min > mn * tight) seg[i].sigma_min = nextafterf(seg[i].sigma_min, 0.0f);
    }
}

typedef struct { int p; } dens_ctx;
static float dens_cb(void *ctx, float t) { return (float)prof_sigma(((dens_ctx *)ctx)->p, (double)t); }
static float rng_cb(void *ctx) { return h_randf((h_rng *)ctx); }

static void run_one(appear_tracker *tr, int p, h_rng *r)
{
    float t;
    for (;;) {
        float u1 = h_randf(r), u2 = h_randf(r);
        if (!appear_tracker_next(tr, u1, u2, &t)) break;
        appear_tracker_feed(tr, (float)prof_sigma(p, (double)t));
    }
}

static const char *const kind_name[APPEAR_TRACK_KIND_COUNT] = {
    "delta", "ratio", "next_flight", "residual", "urm", "power_series", "ray_march" };

/* ---------------------------------------------------------------------- */
/* homogeneous                                                             */
/* ---------------------------------------------------------------------- */

static void homog_chi2(const char *name, appear_spectrum sig, float d, long n, uint64_t seed)
{
    enum { NB = 40 };
    double obs[NB + 1], expct[NB + 1], dmax;
    long i; int b, c;
    h_rng r = h_rng_make(seed);
    appear_medium_sample s;
    /* bins on [0, dmax): dmax = d, or (d infinite) the 99.9% quantile of the mixture */
    dmax = d;
    if (!(d < 1e30f)) { double smin = 1e30; for (c = 0; c < APPEAR_SPECTRUM_SAMPLES; ++c) if (sig.v[c] > 0 && sig.v[c] < smin) smin = sig.v[c]; dmax = 7.0 / smin; }
    memset(obs, 0, sizeof obs);
    for (b = 0; b <= NB; ++b) {
        double lo = dmax * b / NB, hi = b < NB ? dmax * (b + 1) / NB : 1e300, e = 0.0;
        for (c = 0; c < APPEAR_SPECTRUM_SAMPLES; ++c) {
            double sc = sig.v[c];
            double Fhi = b < NB ? exp(-sc * hi) : (d < 1e30f ? exp(-sc * (double)d) : 0.0);
            e += exp(-sc * lo) - Fhi;
        }
        if (b == NB) { /* tail beyond dmax (for finite d it is the pass mass) */
            e = 0.0;
            for (c = 0; c < APPEAR_SPECTRUM_SAMPLES; ++c) e += exp(-(double)sig.v[c] * dmax);
        }
        expct[b] = e / APPEAR_SPECTRUM_SAMPLES * n;
    }
    for (i = 0; i < n; ++i) {
        float uc = h_randf(&r), u = h_randf(&r);
        int ok = appear_homogeneous_sample(sig, d, uc, u, &s);
        if (!ok) { h_fail("%s: sample failed", name); return; }
        b = s.scattered ? (int)(s.t / dmax * NB) : NB;
        if (b > NB || !s.scattered) b = NB;
        if ((double)s.t >= dmax) b = NB;
        obs[b] += 1.0;
    }
    {
        char full[96];
        snprintf(full, sizeof full, "homogeneous free flight %s", name);
        h_chi2_counts(full, obs, expct, NB + 1);
    }
}

void suite_media_homogeneous(void)
{
    static const float sd[] = { 0.0f, 1e-38f, 1e-30f, 1e-7f, 1e-3f, 0.5f, 1.0f, 20.0f, 87.0f, 103.0f, 1e4f, 1e30f };
    int i, c;
    long n = h_n(400000);
    h_rng r = h_rng_make(77);

    h_case("media homogeneous: transmittance vs double, sigma d in 0 .. 1e30");
    {
        h_err e = { "homogeneous_transmittance", 0, 0, 0, 0, 0 };
        for (i = 0; i < (int)(sizeof sd / sizeof sd[0]); ++i) {
            static const float dd[] = { 0.0f, 1e-3f, 1.0f, 7.0f, 1e6f };
            int j;
            for (j = 0; j < 5; ++j) {
                float s = dd[j] > 0.0f ? sd[i] / dd[j] : sd[i];
                float T = appear_homogeneous_transmittance1(s, dd[j]);
                double ref = exp(-(double)s * dd[j]);
                H_CHECK(H_OK_VALUE(T) && T <= 1.0f, "T(%g, %g) = %g", s, dd[j], T);
                h_err_add(&e, T, ref, 1e-40);
                /* float: sigma d rounds (tau 2^-24 relative in T) plus a few ulp of exp */
                H_CHECK(fabs(T - ref) <= (4e-7 + 1.2e-7 * (double)s * dd[j]) * ref + 1.5e-45, "T(%g, %g) = %.9g ref %.9g", s, dd[j], T, ref);
            }
        }
        H_CHECK(appear_homogeneous_transmittance1(0.0f, HUGE_VALF) == 1.0f, "sigma 0, d Inf must give 1");
        H_CHECK(appear_homogeneous_transmittance1(1e-30f, HUGE_VALF) == 0.0f, "sigma > 0, d Inf must give 0");
        H_CHECK(appear_homogeneous_transmittance1(NAN, 1.0f) == 0.0f, "NaN sigma");
        H_CHECK(appear_homogeneous_transmittance1(1.0f, NAN) == 0.0f, "NaN d");
        H_CHECK(appear_homogeneous_transmittance1(-1.0f, 1.0f) == 0.0f, "negative sigma");
        h_err_report(&e);
    }

    h_case("media homogeneous: chi-square of the spectral-MIS free-flight distance");
    homog_chi2("grey d=1", appear_spectrum_splat(1.3f), 1.0f, n, 1);
    homog_chi2("chromatic d=1", appear_spectrum_rgb(0.5f, 2.0f, 8.0f), 1.0f, n, 2);
    homog_chi2("chromatic d=Inf", appear_spectrum_rgb(0.5f, 2.0f, 8.0f), HUGE_VALF, n, 3);
    homog_chi2("one channel 0", appear_spectrum_rgb(0.0f, 1.0f, 3.0f), 2.0f, n, 4);
    homog_chi2("thin 1e-4, d 3000", appear_spectrum_rgb(1e-4f, 2e-4f, 5e-5f), 3000.0f, n, 5);

    h_case("media homogeneous: pdf, weight = T/pdf, per-channel unbiasedness (4 SE)");
    {
        appear_spectrum sig = appear_spectrum_rgb(0.5f, 2.0f, 8.0f);
        float d = 0.7f;
        double mp[APPEAR_SPECTRUM_SAMPLES] = { 0 }, mp2[APPEAR_SPECTRUM_SAMPLES] = { 0 };
        double ms[APPEAR_SPECTRUM_SAMPLES] = { 0 }, ms2[APPEAR_SPECTRUM_SAMPLES] = { 0 };
        long k, nn = h_n(200000);
        for (k = 0; k < nn; ++k) {
            appear_medium_sample s;
            float q30 = h_randf(&r), q31 = h_randf(&r); /* in this order */
            appear_homogeneous_sample(sig, d, q30, q31, &s);
            {
                float pdf = appear_homogeneous_pdf(sig, d, s.t, s.scattered);
                H_CHECK(fabsf(pdf - s.pdf) <= 1e-5f * pdf, "pdf %g vs sample pdf %g", pdf, s.pdf);
            }
            for (c = 0; c < APPEAR_SPECTRUM_SAMPLES; ++c) {
                double wref = (double)s.tr.v[c] / s.pdf;
                double sp = s.scattered ? 0.0 : s.weight.v[c];
                double ss = s.scattered ? (double)sig.v[c] * s.weight.v[c] : 0.0;
                H_CHECK(fabs(s.weight.v[c] - wref) <= 1e-5 * wref + 1e-30, "weight %g vs T/pdf %g", s.weight.v[c], wref);
                mp[c] += sp; mp2[c] += sp * sp; ms[c] += ss; ms2[c] += ss * ss;
            }
        }
        for (c = 0; c < APPEAR_SPECTRUM_SAMPLES; ++c) {
            double Tc = exp(-(double)sig.v[c] * d);
            double m1 = mp[c] / nn, se1 = sqrt((mp2[c] / nn - m1 * m1) / nn);
            double m2 = ms[c] / nn, se2 = sqrt((ms2[c] / nn - m2 * m2) / nn);
            H_CHECK(fabs(m1 - Tc) <= 4 * se1 + 1e-6, "channel %d: E[pass weight] %.6f vs T %.6f (se %.2g)", c, m1, Tc, se1);
            H_CHECK(fabs(m2 - (1 - Tc)) <= 4 * se2 + 1e-6, "channel %d: E[sigma weight at collision] %.6f vs 1-T %.6f (se %.2g)", c, m2, 1 - Tc, se2);
        }
    }

    h_case("media homogeneous: stability sweep (sigma, d, u, uc adversarial)");
    {
        long k, nn = h_n(300000);
        static const float sp[] = { 0.0f, 1e-45f, 1e-30f, 1e-3f, 1.0f, 1e3f, 1e30f, 3.4e38f };
        for (k = 0; k < nn; ++k) {
            appear_spectrum sig;
            appear_medium_sample s;
            float d = (k & 3) ? h_adv_float(&r) : sp[k % 8];
            float uc = h_adv_u(&r), u = h_adv_u(&r), pdf;
            int ok;
            for (c = 0; c < APPEAR_SPECTRUM_SAMPLES; ++c) sig.v[c] = (k & 4) ? h_adv_float(&r) : sp[(k / 8 + c * 3) % 8];
            ok = appear_homogeneous_sample(sig, d, uc, u, &s);
            /* t = d = +Inf is the one non-finite output: a pass to infinity */
            H_CHECK((H_OK_VALUE(s.t) || (s.t == HUGE_VALF && d == HUGE_VALF && !s.scattered)) && H_OK_VALUE(s.pdf), "t %g pdf %g (d %g)", s.t, s.pdf, d);
            for (c = 0; c < APPEAR_SPECTRUM_SAMPLES; ++c)
                H_CHECK(H_OK_VALUE(s.tr.v[c]) && s.tr.v[c] <= 1.0f && H_OK_VALUE(s.weight.v[c]), "tr %g weight %g", s.tr.v[c], s.weight.v[c]);
            H_CHECK(!ok || (s.t <= d || d != d), "t %g beyond d %g", s.t, d);
            pdf = appear_homogeneous_pdf(sig, d, h_adv_float(&r), (int)(k & 1));
            H_CHECK(H_OK_VALUE(pdf), "pdf %g", pdf);
            {
                appear_spectrum T = appear_homogeneous_transmittance(sig, d);
                for (c = 0; c < APPEAR_SPECTRUM_SAMPLES; ++c) H_CHECK(H_OK_VALUE(T.v[c]) && T.v[c] <= 1.0f, "T %g", T.v[c]);
            }
        }
        /* the physical limits */
        {
            appear_medium_sample s;
            appear_homogeneous_sample(appear_spectrum_splat(0.0f), HUGE_VALF, 0.3f, 0.5f, &s);
            H_CHECK(!s.scattered && s.pdf == 1.0f && s.weight.v[0] == 1.0f, "sigma 0: pass, pdf 1, weight 1 (got %d %g %g)", s.scattered, s.pdf, s.weight.v[0]);
            appear_homogeneous_sample(appear_spectrum_splat(1e30f), 1.0f, 0.3f, 0.5f, &s);
            H_CHECK(s.scattered && s.t > 0.0f && s.t < 1e-29f && s.weight.v[0] > 0.9e-30f && s.weight.v[0] < 1.1e-30f,
                    "sigma 1e30: collision near 0 with weight 1/sigma (t %g w %g)", s.t, s.weight.v[0]);
            appear_homogeneous_sample(appear_spectrum_splat(2.0f), 0.0f, 0.3f, 0.5f, &s);
            H_CHECK(!s.scattered && s.pdf == 1.0f, "d = 0 passes");
            appear_homogeneous_sample(appear_spectrum_splat(2.0f), 1.0f, 0.3f, 1e-9f, &s);
            H_CHECK(s.scattered && fabs(s.t - 5e-10) < 1e-15, "small u keeps digits: t %g", s.t);
        }
    }
}

/* ---------------------------------------------------------------------- */
/* heterogeneous trackers                                                  */
/* ---------------------------------------------------------------------- */

static void tracker_chi2(int p, const appear_majorant_segment *seg, int nseg, long n, uint64_t seed, const char *label)
{
    enum { NB = 40 };
    double obs[NB + 1], expct[NB + 1];
    int b;
    long i;
    unsigned flags = 0;
    h_rng r = h_rng_make(seed);
    memset(obs, 0, sizeof obs);
    for (b = 0; b < NB; ++b) expct[b] = (exp(-prof_tau(p, (double)b / NB)) - exp(-prof_tau(p, (double)(b + 1) / NB))) * n;
    expct[NB] = exp(-prof_tau(p, 1.0)) * n;
    for (i = 0; i < n; ++i) {
        appear_tracker tr;
        appear_tracker_init(&tr, APPEAR_TRACK_DELTA, 1.0f, seg, nseg, 0);
        run_one(&tr, p, &r);
        flags |= tr.flags;
        b = tr.collided ? (int)(tr.t * NB) : NB;
        obs[b < NB ? b : (tr.collided ? NB - 1 : NB)] += 1.0;
    }
    H_CHECK(flags == 0, "%s: flags %u", label, flags);
    {
        char full[160];
        snprintf(full, sizeof full, "delta tracking distances %s", label);
        h_chi2_counts(full, obs, expct, NB + 1);
    }
}

void suite_media_trackers(void)
{
    static const double tights[] = { 1.0, 0.1, 0.01 };
    appear_majorant_segment seg[8];
    int p, ti, ns, k;
    long n = h_n(16000);

    h_case("media trackers: every unbiased estimator within 4 SE of exp(-tau), Georgiev 2019 profiles");
    for (p = 0; p < P_COUNT; ++p)
        for (ti = 0; ti < 3; ++ti)
            for (ns = 0; ns < 2; ++ns) {
                int nseg = ns ? 8 : 1;
                double Tref = exp(-prof_tau(p, 1.0));
                make_segments(p, nseg, tights[ti], seg);
                for (k = 0; k <= APPEAR_TRACK_KIND_COUNT; ++k) {
                    /* k == KIND_COUNT: ratio tracking with Russian roulette */
                    int kind = k == APPEAR_TRACK_KIND_COUNT ? APPEAR_TRACK_RATIO : k;
                    appear_tracker_params prm = appear_tracker_defaults(kind);
                    double s1 = 0, s2 = 0, m, se, lk = 0;
                    unsigned flags = 0;
                    long neg = 0;
                    long i, nn = ti == 2 ? n / 4 : n; /* loose: 100x the lookups, fewer runs */
                    h_rng r = h_rng_make((uint64_t)(1000 + p * 100 + ti * 10 + ns * 7 + k));
                    if (kind == APPEAR_TRACK_RAY_MARCH) continue; /* biased: checked below */
                    if (k == APPEAR_TRACK_KIND_COUNT) prm.rr_threshold = 0.1f;
                    for (i = 0; i < nn; ++i) {
                        appear_tracker tr;
                        appear_tracker_init(&tr, kind, 1.0f, seg, nseg, &prm);
                        run_one(&tr, p, &r);
                        /* NEGATIVE is set exactly when T < 0 (bits: -0 is not negative) */
                        if (((tr.flags & APPEAR_TRACK_NEGATIVE) != 0) != (tr.T < 0.0f)) {
                            h_fail("%s: T %g with flags %u", kind_name[kind], tr.T, tr.flags); break;
                        }
                        neg += tr.T < 0.0f;
                        flags |= tr.flags & ~(unsigned)APPEAR_TRACK_NEGATIVE;
                        s1 += tr.T; s2 += (double)tr.T * tr.T; lk += tr.lookups;
                        if (!tr.done || !h_finite(tr.T)) { h_fail("not done or non-finite"); break; }
                    }
                    m = s1 / nn;
                    se = sqrt(fmax(s2 / nn - m * m, 0.0) / nn);
                    H_CHECK(flags == 0, "%s %s tight %g seg %d: flags %u", kind_name[kind], prof_name[p], tights[ti], nseg, flags);
                    /* the header: only URM may go below 0 with valid bounds, in under 10% here */
                    if (kind == APPEAR_TRACK_URM && neg > 0)
                        h_measure("urm negative share", "%s tight %g seg %d: %.4f (%ld of %ld)", prof_name[p],
                                  tights[ti], nseg, (double)neg / nn, neg, nn);
                    H_CHECK(kind == APPEAR_TRACK_URM ? neg * 10 <= nn : neg == 0,
                            "%s %s tight %g seg %d: %ld of %ld estimates negative", kind_name[kind], prof_name[p],
                            tights[ti], nseg, neg, nn);
                    H_CHECK(fabs(m - Tref) <= 4.0 * se + 2e-5 * Tref,
                            "%s%s %s tight %g seg %d: mean %.6f vs T %.6f (%.1f SE, se %.2g, lookups %.1f)",
                            kind_name[kind], k == APPEAR_TRACK_KIND_COUNT ? "+rr" : "", prof_name[p], tights[ti], nseg,
                            m, Tref, se > 0 ? fabs(m - Tref) / se : 0.0, se, lk / nn);
                    if (p == P_CONST && (kind == APPEAR_TRACK_URM || (kind == APPEAR_TRACK_RESIDUAL && ti == 0)))
                        H_CHECK(se < 1e-6, "%s on a constant profile must have zero variance (se %g)", kind_name[kind], se);
                }
            }

    h_case("media trackers: chi-square of delta-tracking collision distance vs sigma(t) exp(-tau(t))");
    for (p = 0; p < P_COUNT; ++p)
        for (ti = 0; ti < 3; ti += 2)
            for (ns = 0; ns < 2; ++ns) {
                char label[96];
                int nseg = ns ? 8 : 1;
                make_segments(p, nseg, tights[ti], seg);
                sprintf(label, "delta %s tight %g seg %d", prof_name[p], tights[ti], nseg);
                tracker_chi2(p, seg, nseg, h_n(ti == 0 ? 100000 : 30000), (uint64_t)(5000 + p * 10 + ti * 3 + ns), label);
            }

    h_case("media trackers: deterministic ray marching converges to exp(-tau) (biased, error falls with M)");
    for (p = 0; p < P_COUNT; ++p) {
        double err_prev = 1e30;
        int M;
        make_segments(p, 1, 1.0, seg);
        for (M = 4; M <= 256; M *= 4) {
            appear_tracker_params prm = appear_tracker_defaults(APPEAR_TRACK_RAY_MARCH);
            appear_tracker tr;
            double err;
            h_rng r = h_rng_make(9);
            prm.comb = M;
            appear_tracker_init(&tr, APPEAR_TRACK_RAY_MARCH, 1.0f, seg, 1, &prm);
            /* midpoint rule: feed u1 = 0.5 */
            {
                float t;
                while (appear_tracker_next(&tr, 0.5f, h_randf(&r), &t)) appear_tracker_feed(&tr, (float)prof_sigma(p, t));
            }
            err = fabs(tr.T - exp(-prof_tau(p, 1.0)));
            H_CHECK(tr.lookups == M, "ray march lookups %d != M %d", tr.lookups, M);
            H_CHECK(err <= err_prev * 1.01 + 2e-6, "%s: ray-march error %.3g at M = %d not below %.3g", prof_name[p], err, M, err_prev);
            err_prev = err;
        }
        H_CHECK(err_prev < 1e-4, "%s: midpoint ray marching with 256 points off by %.3g", prof_name[p], err_prev);
    }
}

/* ---------------------------------------------------------------------- */
/* edge cases                                                              */
/* ---------------------------------------------------------------------- */

static appear_tracker run_const(int kind, float t_max, const appear_majorant_segment *seg, int nseg, float sigma,
                                const appear_tracker_params *prm, uint64_t seed)
{
    appear_tracker tr;
    float t;
    h_rng r = h_rng_make(seed);
    appear_tracker_init(&tr, kind, t_max, seg, nseg, prm);
    float tu1, tu2; /* drawn in this order (a call's arguments have none) */
    while ((tu1 = h_randf(&r), tu2 = h_randf(&r), appear_tracker_next(&tr, tu1, tu2, &t))) appear_tracker_feed(&tr, sigma);
    return tr;
}

void suite_media_edge(void)
{
    int kind;
    appear_majorant_segment seg[4];
    h_rng r = h_rng_make(4242);

    h_case("media edge: t_max = 0 gives T = 1 with no lookup; majorant 0 gives T = 1");
    for (kind = 0; kind < APPEAR_TRACK_KIND_COUNT; ++kind) {
        appear_tracker tr;
        seg[0] = appear_majorant_make_constant(3.0f);
        tr = run_const(kind, 0.0f, seg, 1, 1.0f, 0, 1);
        H_CHECK(tr.done && tr.T == 1.0f && tr.lookups == 0 && tr.flags == 0 && !tr.collided, "%s t_max 0: T %g lookups %d", kind_name[kind], tr.T, tr.lookups);
        seg[0] = appear_majorant_make_constant(0.0f);
        tr = run_const(kind, 5.0f, seg, 1, 0.0f, 0, 1);
        H_CHECK(tr.T == 1.0f && tr.lookups == 0 && tr.flags == 0, "%s majorant 0: T %g lookups %d", kind_name[kind], tr.T, tr.lookups);
        tr = run_const(kind, HUGE_VALF, seg, 1, 0.0f, 0, 1);
        H_CHECK(tr.T == 1.0f && tr.lookups == 0 && tr.flags == 0, "%s majorant 0, t_max Inf: T %g flags %u", kind_name[kind], tr.T, tr.flags);
    }

    h_case("media edge: t_max = Inf with the medium confined to [0, 2) by the majorant");
    for (kind = 0; kind < APPEAR_TRACK_KIND_COUNT; ++kind) {
        long i, n = h_n(20000);
        double s = 0, s2 = 0, se;
        seg[0] = appear_majorant_make(2.0f, 1.5f, 0.0f);
        seg[1] = appear_majorant_make(HUGE_VALF, 0.0f, 0.0f);
        for (i = 0; i < n; ++i) {
            appear_tracker tr = run_const(kind, HUGE_VALF, seg, 2, 0.5f, 0, (uint64_t)i + 7);
            H_CHECK(tr.flags == 0 && tr.done, "%s: flags %u", kind_name[kind], tr.flags);
            s += tr.T; s2 += (double)tr.T * tr.T;
        }
        s /= n;
        se = sqrt(fmax(s2 / n - s * s, 0.0) / n);
        H_CHECK(fabs(s - exp(-1.0)) <= 4.0 * se + 1e-5, "%s: mean %g vs %g (se %.2g)", kind_name[kind], s, exp(-1.0), se);
    }

    h_case("media edge: sigma = 0 everywhere, finite t_max: unbiased T = 1, delta never collides");
    for (kind = 0; kind < APPEAR_TRACK_KIND_COUNT; ++kind) {
        appear_tracker tr;
        long i, n = h_n(20000);
        double s = 0, s2 = 0, se;
        seg[0] = appear_majorant_make_constant(2.0f);
        for (i = 0; i < n; ++i) {
            tr = run_const(kind, 1.0f, seg, 1, 0.0f, 0, (uint64_t)i);
            s += tr.T; s2 += (double)tr.T * tr.T;
            H_CHECK(!tr.collided && tr.flags == 0, "%s collided / flags %u", kind_name[kind], tr.flags);
        }
        s /= n;
        se = sqrt(fmax(s2 / n - s * s, 0.0) / n);
        H_CHECK(fabs(s - 1.0) <= 4.0 * se + 1e-6, "%s: mean %g (se %.2g)", kind_name[kind], s, se);
        if (kind == APPEAR_TRACK_RATIO || kind == APPEAR_TRACK_DELTA || kind == APPEAR_TRACK_URM || kind == APPEAR_TRACK_RAY_MARCH)
            H_CHECK(s == 1.0, "%s: sigma 0 must give exactly 1 (got %.9g)", kind_name[kind], s);
    }

    h_case("media edge: t_max = Inf, sigma 0, sigma_maj > 0: tracking stops at max_lookups, flagged");
    {
        appear_tracker_params prm = appear_tracker_defaults(APPEAR_TRACK_RATIO);
        appear_tracker tr;
        prm.max_lookups = 1000;
        seg[0] = appear_majorant_make_constant(2.0f);
        tr = run_const(APPEAR_TRACK_RATIO, HUGE_VALF, seg, 1, 0.0f, &prm, 3);
        H_CHECK(tr.done && (tr.flags & APPEAR_TRACK_TRUNCATED) && tr.lookups == 1000 && tr.T == 0.0f, "flags %u lookups %d T %g", tr.flags, tr.lookups, tr.T);
        tr = run_const(APPEAR_TRACK_URM, HUGE_VALF, seg, 1, 0.0f, 0, 3);
        H_CHECK(tr.done && (tr.flags & APPEAR_TRACK_BAD_INPUT) && tr.T == 0.0f, "URM over infinite length: flags %u", tr.flags);
    }

    h_case("media edge: huge optical depth gives T = 0 (finite), few lookups");
    for (kind = 0; kind < APPEAR_TRACK_KIND_COUNT; ++kind) {
        appear_tracker tr;
        seg[0] = appear_majorant_make(HUGE_VALF, 1e30f, 1e30f);
        tr = run_const(kind, 1.0f, seg, 1, 1e30f, 0, 5);
        H_CHECK(tr.done && tr.T == 0.0f && tr.flags == 0 && tr.lookups <= 64 * 3 + 64, "%s tau 1e30: T %g flags %u lookups %d", kind_name[kind], tr.T, tr.flags, tr.lookups);
        seg[0] = appear_majorant_make(HUGE_VALF, 1e6f, 0.0f);
        tr = run_const(kind, 1e3f, seg, 1, 1e6f, 0, 5);
        H_CHECK(tr.done && tr.T == 0.0f && tr.flags == 0, "%s tau 1e9: T %g flags %u", kind_name[kind], tr.T, tr.flags);
        if (kind == APPEAR_TRACK_DELTA) H_CHECK(tr.collided && tr.t >= 0.0f && tr.t < 1e-3f, "delta collides at once: t %g", tr.t);
    }

    h_case("media edge: NaN / Inf / negative density -> BAD_DENSITY, T = 0");
    for (kind = 0; kind < APPEAR_TRACK_KIND_COUNT; ++kind) {
        static const float bad[] = { NAN, -1.0f, HUGE_VALF, -HUGE_VALF };
        int b;
        seg[0] = appear_majorant_make_constant(2.0f);
        for (b = 0; b < 4; ++b) {
            appear_tracker tr = run_const(kind, 20.0f, seg, 1, bad[b], 0, 11);
            H_CHECK(tr.done && tr.T == 0.0f && (tr.flags & APPEAR_TRACK_BAD_DENSITY) && !tr.collided,
                    "%s density %g: T %g flags %u", kind_name[kind], bad[b], tr.T, tr.flags);
        }
    }

    h_case("media edge: violated majorant is reported, not clamped");
    for (kind = 0; kind < APPEAR_TRACK_KIND_COUNT; ++kind) {
        appear_tracker tr;
        int i, seen = 0, neg = 0;
        seg[0] = appear_majorant_make_constant(1.0f);
        for (i = 0; i < 200; ++i) {
            tr = run_const(kind, 10.0f, seg, 1, 2.5f, 0, (uint64_t)i);
            seen += (tr.flags & APPEAR_TRACK_MAJORANT_VIOLATED) != 0;
            neg += tr.T < 0.0f;
            H_CHECK(h_finite(tr.T), "%s: non-finite", kind_name[kind]);
        }
        /* every walk that looked up the density must flag it */
        H_CHECK(seen >= 150, "%s: violation flagged in only %d of 200 runs", kind_name[kind], seen);
        if (kind == APPEAR_TRACK_RATIO) H_CHECK(neg > 0, "ratio tracking with sigma > sigma_maj must keep its negative (unbiased) weights");
    }
    {
        /* ratio tracking under a violated majorant stays unbiased */
        long i, n = h_n(200000);
        double s = 0, s2 = 0, se;
        seg[0] = appear_majorant_make_constant(1.5f);
        for (i = 0; i < n; ++i) { double v = run_const(APPEAR_TRACK_RATIO, 1.0f, seg, 1, 2.0f, 0, (uint64_t)i + 99).T; s += v; s2 += v * v; }
        s /= n;
        se = sqrt(fmax(s2 / n - s * s, 0.0) / n);
        H_CHECK(fabs(s - exp(-2.0)) <= 4.0 * se, "ratio tracking, sigma 2 > maj 1.5: mean %g vs %g (se %.2g)", s, exp(-2.0), se);
        /* residual: density below the minorant */
        seg[0] = appear_majorant_make(HUGE_VALF, 3.0f, 1.0f);
        H_CHECK(run_const(APPEAR_TRACK_RESIDUAL, 1.0f, seg, 1, 0.5f, 0, 1).flags & APPEAR_TRACK_MAJORANT_VIOLATED, "below minorant not flagged");
    }

    h_case("media edge: signs on piecewise majorants: power series >= 0, URM below 0 only flagged, minorant checked");
    {
        /* the reproducer: majorant 100 on [0, 0.5), 1 on [0.5, 1], density
           at both bounds' top (tau = 50.25). Before the comb followed the
           majorant, the power series' single tooth scored X = 100 > tau_maj
           = 50.5 in half the runs and averaged -4.7e-4 (50% negative) */
        static const int kinds[] = { APPEAR_TRACK_URM, APPEAR_TRACK_POWER_SERIES };
        appear_majorant_segment two[2];
        int k;
        two[0] = appear_majorant_make(0.5f, 100.0f, 0.0f);
        two[1] = appear_majorant_make(1.0f, 1.0f, 0.0f);
        for (k = 0; k < 2; ++k) {
            long i, n = h_n(100000), neg = 0, bad = 0;
            double s = 0, s2 = 0, se, Tref = exp(-50.25);
            for (i = 0; i < n; ++i) {
                appear_tracker tr;
                float t;
                appear_tracker_init(&tr, kinds[k], 1.0f, two, 2, 0);
                float tu1, tu2; /* drawn in this order (a call's arguments have none) */
                while ((tu1 = h_randf(&r), tu2 = h_randf(&r), appear_tracker_next(&tr, tu1, tu2, &t)))
                    appear_tracker_feed(&tr, t < 0.5f ? 100.0f : 0.5f);
                neg += tr.T < 0.0f;
                bad += (tr.flags & ~(unsigned)APPEAR_TRACK_NEGATIVE) != 0 ||
                       ((tr.flags & APPEAR_TRACK_NEGATIVE) != 0) != (tr.T < 0.0f);
                s += tr.T; s2 += (double)tr.T * tr.T;
            }
            s /= n;
            se = sqrt(fmax(s2 / n - s * s, 0.0) / n);
            H_CHECK(bad == 0, "%s: %ld runs with wrong flags", kind_name[kinds[k]], bad);
            if (kinds[k] == APPEAR_TRACK_POWER_SERIES) H_CHECK(neg == 0, "power series: %ld of %ld negative", neg, n);
            H_CHECK(fabs(s - Tref) <= 4.0 * se + 1e-3 * Tref, "%s two segments: mean %g vs %g (se %.2g)",
                    kind_name[kinds[k]], s, Tref, se);
        }
        /* a density below sigma_min sizes URM's comb wrongly: flagged */
        seg[0] = appear_majorant_make(HUGE_VALF, 6.0f, 5.0f);
        H_CHECK(run_const(APPEAR_TRACK_URM, 1.0f, seg, 1, 0.1f, 0, 1).flags & APPEAR_TRACK_MAJORANT_VIOLATED,
                "URM below the minorant not flagged");
        H_CHECK(run_const(APPEAR_TRACK_POWER_SERIES, 1.0f, seg, 1, 0.1f, 0, 1).flags &
                    APPEAR_TRACK_MAJORANT_VIOLATED, "power series below the minorant not flagged");
        H_CHECK(!(run_const(APPEAR_TRACK_RATIO, 1.0f, seg, 1, 0.1f, 0, 1).flags & APPEAR_TRACK_MAJORANT_VIOLATED),
                "ratio tracking does not use the minorant: no flag");
    }

    h_case("media edge: an unbounded ray never asks for a lookup at t = +Inf (u = 1, denormal majorant)");
    for (kind = 0; kind <= APPEAR_TRACK_RESIDUAL; ++kind) {
        static const float majs[] = { 1.0f, 1e-40f, 1e-45f };
        int j;
        for (j = 0; j < 3; ++j) {
            appear_tracker tr;
            float t, us[2] = { 1.0f, 0.5f };
            int steps = 0, asked_inf = 0;
            seg[0] = appear_majorant_make_constant(majs[j]);
            appear_tracker_init(&tr, kind, HUGE_VALF, seg, 1, 0);
            while (steps < 64 && appear_tracker_next(&tr, us[steps & 1], us[steps & 1], &t)) {
                asked_inf += !(t <= FLT_MAX);
                appear_tracker_feed(&tr, 0.0f);
                ++steps;
            }
            H_CHECK(tr.done && !asked_inf && h_finite(tr.T), "%s maj %g: done %d, %d lookups at +Inf",
                    kind_name[kind], majs[j], tr.done, asked_inf);
        }
    }

    h_case("media edge: invalid setups -> BAD_INPUT, T = 0");
    for (kind = 0; kind < APPEAR_TRACK_KIND_COUNT; ++kind) {
        appear_tracker tr;
        seg[0] = appear_majorant_make_constant(1.0f);
        tr = run_const(kind, NAN, seg, 1, 0.5f, 0, 1);
        H_CHECK(tr.done && (tr.flags & APPEAR_TRACK_BAD_INPUT) && tr.T == 0.0f, "%s NaN t_max", kind_name[kind]);
        tr = run_const(kind, -1.0f, seg, 1, 0.5f, 0, 1);
        H_CHECK(tr.flags & APPEAR_TRACK_BAD_INPUT, "%s negative t_max", kind_name[kind]);
        tr = run_const(kind, 1.0f, 0, 0, 0.5f, 0, 1);
        H_CHECK(tr.flags & APPEAR_TRACK_BAD_INPUT, "%s no segments", kind_name[kind]);
        seg[0] = appear_majorant_make(0.5f, 1.0f, 0.0f);
        tr = run_const(kind, 1.0f, seg, 1, 0.5f, 0, 1);
        H_CHECK(tr.flags & APPEAR_TRACK_BAD_INPUT, "%s segments end before t_max", kind_name[kind]);
        seg[0] = appear_majorant_make(0.5f, 1.0f, 0.0f); seg[1] = appear_majorant_make(0.2f, 1.0f, 0.0f);
        tr = run_const(kind, 0.4f, seg, 2, 0.5f, 0, 1);
        H_CHECK(tr.flags & APPEAR_TRACK_BAD_INPUT, "%s decreasing segments", kind_name[kind]);
        seg[0] = appear_majorant_make(2.0f, 1.0f, 2.0f);
        tr = run_const(kind, 1.0f, seg, 1, 0.5f, 0, 1);
        H_CHECK(tr.flags & APPEAR_TRACK_BAD_INPUT, "%s minorant above majorant", kind_name[kind]);
        seg[0] = appear_majorant_make(2.0f, NAN, 0.0f);
        tr = run_const(kind, 1.0f, seg, 1, 0.5f, 0, 1);
        H_CHECK(tr.flags & APPEAR_TRACK_BAD_INPUT, "%s NaN majorant", kind_name[kind]);
    }
    {
        appear_tracker tr;
        seg[0] = appear_majorant_make_constant(1.0f);
        tr = run_const(99, 1.0f, seg, 1, 0.5f, 0, 1);
        H_CHECK(tr.flags & APPEAR_TRACK_BAD_INPUT, "unknown kind");
    }

    h_case("media edge: callback wrapper gives the same estimate as the caller-driven loop");
    for (kind = 0; kind < APPEAR_TRACK_KIND_COUNT; ++kind) {
        appear_tracker a, b;
        dens_ctx dc;
        h_rng r1 = h_rng_make(31), r2 = h_rng_make(31);
        dc.p = P_COS;
        {
            appear_majorant_segment s8[8];
            make_segments(P_COS, 8, 0.5, s8);
            appear_tracker_init(&a, kind, 1.0f, s8, 8, 0);
            appear_tracker_init(&b, kind, 1.0f, s8, 8, 0);
            run_one(&a, P_COS, &r1);
            appear_tracker_run(&b, dens_cb, &dc, rng_cb, &r2);
        }
        H_CHECK(a.T == b.T && a.lookups == b.lookups && a.t == b.t, "%s: loop %g/%d vs wrapper %g/%d", kind_name[kind], a.T, a.lookups, b.T, b.lookups);
    }

    h_case("media edge: adversarial fuzz of every tracker (finite results, termination)");
    {
        long i, n = h_n(60000);
        for (i = 0; i < n; ++i) {
            appear_tracker tr;
            appear_tracker_params prm;
            int ns = 1 + (int)(h_rand(&r) * 4), j, steps = 0;
            float t, tm = (i & 1) ? h_adv_float(&r) : 4.0f * h_randf(&r);
            float prev = 0.0f;
            kind = (int)(h_rand(&r) * APPEAR_TRACK_KIND_COUNT);
            prm = appear_tracker_defaults(kind);
            prm.max_lookups = 5000;
            if (i & 2) prm.rr_threshold = h_adv_float(&r);
            if (i & 4) prm.control = h_adv_float(&r);
            if (i & 8) { prm.comb = (int)(h_rand(&r) * 8) - 1; prm.comb_rate = h_adv_float(&r); prm.order = (int)(h_rand(&r) * 6) - 1; prm.order_c = h_adv_float(&r); }
            for (j = 0; j < ns; ++j) {
                float e = (i & 16) ? h_adv_float(&r) : prev + h_randf(&r) * 2.0f;
                float mj = (i & 32) ? h_adv_float(&r) : 5.0f * h_randf(&r);
                float mn = (i & 64) ? h_adv_float(&r) : mj * h_randf(&r);
                seg[j] = appear_majorant_make(j == ns - 1 && (i & 128) ? HUGE_VALF : e, mj, mn);
                prev = e;
            }
            appear_tracker_init(&tr, kind, tm, seg, ns, &prm);
            float tu1, tu2; /* drawn in this order (a call's arguments have none) */
            while ((tu1 = h_adv_u(&r), tu2 = h_adv_u(&r), appear_tracker_next(&tr, tu1, tu2, &t))) {
                float s = (i & 256) ? h_adv_float(&r) : seg[0].sigma_maj * h_randf(&r);
                H_CHECK(h_finite(t) || t == HUGE_VALF, "lookup position %g", t);
                if ((i & 512) && (steps & 1)) { ++steps; continue; } /* next() twice without feed */
                appear_tracker_feed(&tr, s);
                if (++steps > 20000) { h_fail("%s did not terminate", kind_name[kind]); break; }
            }
            H_CHECK(tr.done && h_finite(tr.T) && (h_finite(tr.t) || tr.t == HUGE_VALF) && tr.lookups <= 5000, "%s: done %d T %g t %g lookups %d", kind_name[kind], tr.done, tr.T, tr.t, tr.lookups);
        }
    }
}

/* ---------------------------------------------------------------------- */
/* return codes, single-channel free flight                                */
/* ---------------------------------------------------------------------- */

void suite_media_sample1(void)
{
    h_rng r = h_rng_make(1601);
    long i, n = h_n(400000);

    h_case("homogeneous_sample returns 2 scattered, 1 passed, 0 invalid; = s.scattered");
    {
        appear_medium_sample s;
        appear_spectrum sig = appear_spectrum_rgb(0.5f, 1.0f, 2.0f);
        long bad = 0, n2 = 0, n1 = 0;
        for (i = 0; i < 10000; ++i) {
            float q22 = h_randf(&r), q23 = h_randf(&r); /* in this order */
            int ret = appear_homogeneous_sample(sig, 1.0f, q22, q23, &s);
            bad += !(ret == APPEAR_MEDIUM_SCATTERED ? s.scattered && s.t < 1.0f
                     : ret == APPEAR_MEDIUM_PASSED  ? !s.scattered && s.t == 1.0f
                                                    : 0);
            n2 += ret == 2;
            n1 += ret == 1;
        }
        H_CHECK(bad == 0 && n1 > 1000 && n2 > 1000,
                "%ld bad return codes (%ld passed, %ld scattered)", bad, n1, n2);
        H_CHECK(appear_homogeneous_sample(sig, 0.0f, 0.5f, 0.5f, &s) == APPEAR_MEDIUM_PASSED,
                "d = 0 passes");
        H_CHECK(appear_homogeneous_sample(sig, NAN, 0.5f, 0.5f, &s) == APPEAR_MEDIUM_FAILED,
                "d NaN fails");
        sig.v[1] = -1.0f;
        H_CHECK(appear_homogeneous_sample(sig, 1.0f, 0.5f, 0.5f, &s) == APPEAR_MEDIUM_FAILED,
                "sigma < 0 fails");
    }

    h_case(
        "homogeneous_sample1: chi2 of t against 1 - exp(-sigma t) and the pass mass exp(-sigma d)");
    {
        enum { NB = 40 };
        static const float sg[3] = {0.3f, 2.0f, 7.0f};
        static const float dd[3] = {1.0f, 1.5f, HUGE_VALF};
        int k, b;
        for (k = 0; k < 3; ++k) {
            double obs[NB + 1], expct[NB + 1], dmax = dd[k] == HUGE_VALF ? 6.0 / sg[k] : dd[k];
            double sum = 0.0, sum2 = 0.0, sq;
            char name[96];
            long nsc = 0;
            memset(obs, 0, sizeof obs);
            for (b = 0; b < NB; ++b)
                expct[b] = (exp(-(double)sg[k] * dmax * b / NB) -
                            exp(-(double)sg[k] * dmax * (b + 1) / NB)) *
                           n;
            expct[NB] = exp(-(double)sg[k] * dmax) * n; /* pass, or beyond dmax for d = Inf */
            for (i = 0; i < n; ++i) {
                appear_medium_sample1 s;
                int ret = appear_homogeneous_sample1(sg[k], dd[k], h_randf(&r), &s);
                if (ret == APPEAR_MEDIUM_SCATTERED && s.t < dmax) {
                    b = (int)(s.t / dmax * NB);
                    obs[b < NB ? b : NB - 1] += 1.0;
                } else
                    obs[NB] += 1.0;
                if (ret == APPEAR_MEDIUM_SCATTERED) {
                    sum += s.t;
                    sum2 += (double)s.t * s.t;
                    ++nsc;
                }
                if (!ret) {
                    h_fail("sigma %g d %g: sample failed", sg[k], dd[k]);
                    return;
                }
            }
            snprintf(name, sizeof name, "sample1 sigma %g d %g", sg[k], dd[k]);
            h_chi2_counts(name, obs, expct, NB + 1);
            if (dd[k] == HUGE_VALF) { /* mean free path 1/sigma, within 5 standard errors */
                double mean = sum / nsc;
                sq = sqrt((sum2 / nsc - mean * mean) / nsc);
                H_CHECK(nsc == n && fabs(mean - 1.0 / sg[k]) < 5.0 * sq,
                        "mean t %g, 1/sigma %g (se %g)", mean, 1.0 / sg[k], sq);
            }
        }
    }

    h_case("homogeneous_sample1: pdf = pdf1 (collision: to rounding, pass: bit for bit), weight = "
           "tr / pdf, "
           "pdf1 integrates to 1, t = grey spectral t (to 1e-6)");
    {
        static const float sg[4] = {0.0f, 0.25f, 1.0f, 40.0f};
        static const float dd[3] = {0.5f, 3.0f, HUGE_VALF};
        long bad = 0, badw = 0, badg = 0;
        int k, j;
        for (k = 0; k < 4; ++k)
            for (j = 0; j < 3; ++j) {
                double q = 0.0, hq,
                       tm = dd[j] == HUGE_VALF ? 60.0 / (sg[k] > 0 ? sg[k] : 1.0f) : dd[j];
                int m, nq = 200000;
                for (i = 0; i < 2000; ++i) {
                    appear_medium_sample1 s;
                    appear_medium_sample sp;
                    float u = h_randf(&r);
                    int ret = appear_homogeneous_sample1(sg[k], dd[j], u, &s), rs;
                    float p1 =
                        appear_homogeneous_pdf1(sg[k], dd[j], s.t, ret == APPEAR_MEDIUM_SCATTERED);
                    bad += ret == APPEAR_MEDIUM_SCATTERED
                               ? !(fabs(p1 - (double)s.pdf) <=
                                   1e-6 * (1.0 + sg[k] * (double)s.t) * s.pdf)
                               : memcmp(&p1, &s.pdf, sizeof p1) != 0;
                    if (ret == APPEAR_MEDIUM_SCATTERED) /* tr = exp(-sigma t) to float rounding */
                        badw += !(fabs(s.tr - exp(-(double)sg[k] * s.t)) <=
                                  1e-6 * (1.0 + sg[k] * (double)s.t) * s.tr);
                    if (s.pdf > 1e-30f)
                        badw += fabs(s.weight - (double)s.tr / s.pdf) > 1e-6 * s.weight;
                    rs = appear_homogeneous_sample(appear_spectrum_splat(sg[k]), dd[j], 0.5f, u,
                                                   &sp);
                    badg += rs != ret || sp.weight.v[0] != s.weight ||
                            !(sp.t == s.t || fabs(sp.t - (double)s.t) <= 1e-6 * s.t);
                }
                if (sg[k] == 0.0f) continue; /* all mass in the pass */
                hq = tm / nq; /* midpoint rule over [0, min(d, tm)) */
                for (m = 0; m < nq; ++m)
                    q += appear_homogeneous_pdf1(sg[k], dd[j], (float)((m + 0.5) * hq), 1) * hq;
                q += appear_homogeneous_pdf1(sg[k], dd[j], 0.0f, 0);
                H_CHECK(fabs(q - 1.0) < 2e-3, "sigma %g d %g: pdf1 integrates to %.6f", sg[k],
                        dd[j], q);
            }
        H_CHECK(bad == 0, "%ld samples whose pdf differs from pdf1", bad);
        H_CHECK(badw == 0, "%ld weights differ from tr / pdf", badw);
        H_CHECK(badg == 0, "%ld samples differ from the grey spectral sampler (t, weight, return)",
                badg);
    }

    h_case(
        "homogeneous_sample1: adversarial inputs (NaN, Inf, sigma < 0, d = 0, d = Inf, u = 0 / 1)");
    {
        appear_medium_sample1 s;
        int ret;
        ret = appear_homogeneous_sample1(NAN, 1.0f, 0.5f, &s);
        H_CHECK(ret == 0 && s.t == 0 && s.pdf == 0 && s.weight == 0 && s.tr == 0, "sigma NaN: %d",
                ret);
        ret = appear_homogeneous_sample1(HUGE_VALF, 1.0f, 0.5f, &s);
        H_CHECK(ret == 0 && s.weight == 0, "sigma Inf: %d", ret);
        ret = appear_homogeneous_sample1(-1.0f, 1.0f, 0.5f, &s);
        H_CHECK(ret == 0 && s.weight == 0, "sigma < 0: %d", ret);
        ret = appear_homogeneous_sample1(1.0f, NAN, 0.5f, &s);
        H_CHECK(ret == 0, "d NaN: %d", ret);
        ret = appear_homogeneous_sample1(1.0f, -1.0f, 0.5f, &s);
        H_CHECK(ret == 0, "d < 0: %d", ret);
        ret = appear_homogeneous_sample1(1.0f, 1.0f, NAN, &s);
        H_CHECK(ret == 0, "u NaN: %d", ret);
        ret = appear_homogeneous_sample1(1.0f, 1.0f, 1.5f, &s);
        H_CHECK(ret == 0, "u > 1: %d", ret);
        ret = appear_homogeneous_sample1(2.0f, 0.0f, 0.5f, &s);
        H_CHECK(ret == APPEAR_MEDIUM_PASSED && s.t == 0 && s.pdf == 1 && s.weight == 1,
                "d = 0: %d t %g pdf %g", ret, s.t, s.pdf);
        ret = appear_homogeneous_sample1(2.0f, HUGE_VALF, 0.5f, &s);
        H_CHECK(ret == APPEAR_MEDIUM_SCATTERED && fabs(s.t - 0.34657359) < 1e-6 && s.weight == 0.5f,
                "d = Inf: %d t %g", ret, s.t);
        ret = appear_homogeneous_sample1(2.0f, 1.0f, 0.0f, &s);
        H_CHECK(ret == APPEAR_MEDIUM_SCATTERED && s.t == 0 && s.pdf == 2.0f && s.weight == 0.5f,
                "u = 0: %d t %g", ret, s.t);
        ret = appear_homogeneous_sample1(2.0f, 1.0f, 1.0f, &s);
        H_CHECK(ret == APPEAR_MEDIUM_PASSED && s.t == 1.0f, "u = 1 passes: %d t %g", ret, s.t);
        ret = appear_homogeneous_sample1(2.0f, HUGE_VALF, 1.0f, &s);
        H_CHECK(ret == APPEAR_MEDIUM_PASSED && s.t == HUGE_VALF && s.pdf == 0 && s.weight == 1,
                "u = 1, d = Inf: pass to infinity: %d t %g", ret, s.t);
        ret = appear_homogeneous_sample1(0.0f, HUGE_VALF, 0.5f, &s);
        H_CHECK(ret == APPEAR_MEDIUM_PASSED && s.pdf == 1 && s.weight == 1, "sigma 0: %d pdf %g",
                ret, s.pdf);
        ret = appear_homogeneous_sample1(1e-40f, HUGE_VALF, 0.5f, &s);
        H_CHECK(ret != 0 && h_finite(s.weight) && h_finite(s.pdf) && s.weight >= 0,
                "denormal sigma: weight %g", s.weight);
        H_CHECK(appear_homogeneous_pdf1(NAN, 1, 0.5f, 1) == 0 &&
                    appear_homogeneous_pdf1(1, 1, 1.0f, 1) == 0 &&
                    appear_homogeneous_pdf1(1, 1, -0.1f, 1) == 0 &&
                    appear_homogeneous_pdf1(1, 1, NAN, 1) == 0 &&
                    appear_homogeneous_pdf1(1, NAN, 0.5f, 0) == 0 &&
                    appear_homogeneous_pdf1(-1, 1, 0.5f, 1) == 0,
                "pdf1 of invalid input is not 0");
        for (i = 0; i < h_n(200000); ++i) {
            float sg = h_adv_float(&r), d = h_adv_float(&r), u = h_adv_u(&r), p;
            ret = appear_homogeneous_sample1(sg, d, u, &s);
            H_CHECK(
                (H_OK_VALUE(s.t) || (s.t == HUGE_VALF && d == HUGE_VALF && ret == 1)) &&
                    H_OK_VALUE(s.pdf) && H_OK_VALUE(s.tr) && s.tr <= 1.0f && H_OK_VALUE(s.weight) &&
                    ret >= 0 && ret <= 2 && (ret || (s.pdf == 0 && s.weight == 0)),
                "sample1(%a, %a, %a) = %d t %g pdf %g w %g", sg, d, u, ret, s.t, s.pdf, s.weight);
            p = appear_homogeneous_pdf1(sg, d, h_adv_float(&r), (int)(i & 1));
            H_CHECK(H_OK_VALUE(p), "pdf1 %g", p);
        }
    }
}

#else
void suite_media_homogeneous(void) { h_case("media: compiled out"); }
void suite_media_trackers(void) { h_case("media: compiled out"); }
void suite_media_edge(void) { h_case("media: compiled out"); }
void suite_media_sample1(void) { h_case("media: compiled out"); }
#endif
