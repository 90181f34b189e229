/* tests/test_harness.c - the harness tests itself: a test that cannot fail
   proves nothing, so each instrument is shown to fail on wrong input. */
#include "harness.h"
#include "check.h"
#include <math.h>
#include <stdlib.h>

typedef struct { float g_sample, g_pdf; appear_vec3 wo; } mis_ctx;
static int mis_sample(void *c, float uc, float u1, float u2, appear_vec3 *wi)
{
    mis_ctx *x = (mis_ctx *)c;
    appear_phase_record s;
    (void)uc;
    *wi = appear_vec3_make(0, 0, 0);
    if (!appear_hg_sample_g(x->g_sample, x->wo, u1, u2, &s)) return 0;
    *wi = s.wi;
    return 1;
}
static double mis_pdf(void *c, appear_vec3 wi) { mis_ctx *x = (mis_ctx *)c; return appear_hg_pdf_g(x->g_pdf, x->wo, wi); }
static double cos2(void *c, appear_vec3 w) { (void)c; return (double)w.z * w.z; }
static double lobe(void *c, appear_vec3 w)
{   /* normalised exp(-k (1 - z)) with k = 1e6: mass 1 within ~1e-3 rad */
    double k = *(double *)c, omz = ((double)w.x * w.x + (double)w.y * w.y) / (1.0 + fabs(w.z));
    return w.z > 0 ? k / (2.0 * 3.141592653589793 * (1.0 - exp(-2.0 * k))) * exp(-k * omz) : 0.0;
}

static int dbl_cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}
/* Two streams of n draws: the number of values they share, and the largest
   |correlation| of a[i] with b[i + lag] for lags -4..4 (sd 1/sqrt(n) if unrelated). */
static void stream_pair(const double *a, const double *b, int n, long *shared, double *maxcorr)
{
    double *sa = (double *)malloc(sizeof(double) * (size_t)n), *sb = (double *)malloc(sizeof(double) * (size_t)n);
    int i, j, lag;
    *shared = 0; *maxcorr = 0;
    for (i = 0; i < n; ++i) { sa[i] = a[i]; sb[i] = b[i]; }
    qsort(sa, (size_t)n, sizeof(double), dbl_cmp);
    qsort(sb, (size_t)n, sizeof(double), dbl_cmp);
    for (i = 0, j = 0; i < n && j < n;) {
        if (sa[i] < sb[j]) ++i; else if (sb[j] < sa[i]) ++j; else { ++*shared; ++i; ++j; }
    }
    for (lag = -4; lag <= 4; ++lag) {
        double c = 0;
        int m = 0;
        for (i = 0; i < n; ++i)
            if (i + lag >= 0 && i + lag < n) { c += (a[i] - 0.5) * (b[i + lag] - 0.5); ++m; }
        c = fabs(12.0 * c / m);
        if (c > *maxcorr) *maxcorr = c;
    }
    free(sa); free(sb);
}

/* h_rng_make and check_rng_make: seeds s and s + d (d = 1, 2, 3, 6, 1000003)
   give streams that share no value and are uncorrelated at small lags */
static void seed_streams(int which)
{
    enum { N = 4096 };
    static const uint64_t base[] = { 0, 1, 77, 12345, 1ull << 32 };
    static const uint64_t delta[] = { 1, 2, 3, 6, 1000003 };
    static double a[N], b[N];
    int i, j, k;
    for (i = 0; i < 5; ++i)
        for (j = 0; j < 5; ++j) {
            long shared;
            double corr;
            if (which == 0) {
                h_rng ra = h_rng_make(base[i]), rb = h_rng_make(base[i] + delta[j]);
                for (k = 0; k < N; ++k) a[k] = h_rand(&ra);
                for (k = 0; k < N; ++k) b[k] = h_rand(&rb);
            } else {
                check_rng ra = check_rng_make(base[i]), rb = check_rng_make(base[i] + delta[j]);
                for (k = 0; k < N; ++k) a[k] = check_rand(&ra);
                for (k = 0; k < N; ++k) b[k] = check_rand(&rb);
            }
            stream_pair(a, b, N, &shared, &corr);
            /* 225 correlations at 5.5 sd: a false alarm has probability ~1e-5 */
            H_CHECK(shared == 0 && corr < 5.5 / sqrt((double)N),
                    "%s seeds %llu and %llu: %ld of %d values shared, |correlation| %.3g at some lag in -4..4 (bound %.3g)",
                    which ? "check_rng_make" : "h_rng_make", (unsigned long long)base[i],
                    (unsigned long long)(base[i] + delta[j]), shared, N, corr, 5.5 / sqrt((double)N));
        }
}

/* A thin arc: a Gaussian band in z (sd 5e-4, centred halfway between two nodes
   of a cell's 5x5 grid, 16 sd from either) times phi uniform on [a, b], whose
   ends cut slivers of 10% and 5% off two cells: the shape of a transmitted lobe
   that hugs the horizon. A 5x5 Simpson grid per cell sees none of it. */
typedef struct { double zc, sd, a, b; } arc_ctx;
static int arc_sample(void *c, float uc, float u1, float u2, appear_vec3 *wi)
{
    arc_ctx *x = (arc_ctx *)c;
    double r = sqrt(-2.0 * log(1.0 - (double)uc)), z = x->zc + x->sd * r * cos(6.283185307179586 * u1);
    double phi = x->a + (x->b - x->a) * u2, s = sqrt(fmax(0.0, 1.0 - z * z));
    *wi = appear_vec3_make((float)(s * cos(phi)), (float)(s * sin(phi)), (float)z);
    return 1;
}
static double arc_pdf(void *c, appear_vec3 w)
{
    arc_ctx *x = (arc_ctx *)c;
    double t = (w.z - x->zc) / x->sd, phi = atan2((double)w.y, (double)w.x);
    if (phi < 0) phi += 6.283185307179586;
    if (phi < x->a || phi > x->b) return 0.0;
    return exp(-0.5 * t * t) / (2.5066282746310002 * x->sd * (x->b - x->a));
}

/* a sampler whose weight is a known function of its numbers: u1^2 + uc^2, failing where u2 > 0.75 */
static int grid_sampler(const void *m, appear_vec3 wo, float uc, float u1, float u2, appear_bsdf_record *s)
{
    (void)m;
    (void)wo;
    s->weight = appear_spectrum_splat(u1 * u1 + uc * uc);
    return u2 <= 0.75f;
}

void suite_harness(void)
{
    mis_ctx c;
    h_chi2_spec sp = { 0 };
    double p, v, k = 1e6;
    c.wo = appear_normalize(appear_vec3_make(0.2f, 0.1f, 0.9f));
    sp.sample = mis_sample; sp.pdf = mis_pdf; sp.ctx = &c; sp.unrecorded = 1; sp.seed = 77;
    sp.n_samples = 400000; /* 25000 in quick mode: the mismatch below is chosen to be caught even then */

    h_case("harness: chi2 rejects a sampler that does not match its pdf (g 0.30 vs 0.36)");
    c.g_sample = 0.30f; c.g_pdf = 0.36f; sp.name = "self-test mismatch";
    p = h_chi2(&sp);
    H_CHECK(p < 1e-5, "p = %.3g for a wrong pdf (the suite rejects below ~1e-4)", p);

    h_case("harness: chi2 accepts a matching sampler");
    c.g_sample = 0.30f; c.g_pdf = 0.30f; sp.name = "self-test match";
    p = h_chi2(&sp);
    H_CHECK(p > 1e-4, "p = %.3g for the right pdf", p);

    h_case("harness: chi2 rejects samples where the pdf is zero");
    c.g_sample = 0.0f; c.g_pdf = 0.0f; sp.name = "self-test cap";
    sp.zmin = 0.5; sp.axis = appear_vec3_make(0, 0, 1);
    p = h_chi2(&sp); /* sampler is uniform on the sphere, bins cover a cap: the rest bin takes the others */
    H_CHECK(p > 1e-4, "p = %.3g with a cap domain", p);

    h_case("harness: chi2 quadrature sees a thin arc between the nodes of every cell's coarse grid");
    {
        arc_ctx a;
        h_chi2_spec sa = { 0 };
        const double cz = 2.0 / 32, cp = 6.283185307179586 / 64; /* the default 32 x 64 bins */
        a.zc = -1.0 + 10.0 * cz + cz / 8; a.sd = 5e-4; a.a = 3.9 * cp; a.b = 20.05 * cp;
        sa.sample = arc_sample; sa.pdf = arc_pdf; sa.ctx = &a; sa.unrecorded = 1; sa.seed = 78;
        sa.n_samples = 400000; sa.name = "self-test thin arc";
        p = h_chi2(&sa); /* the 5x5 grids gave 0 expected in every cell: p = 0 */
        H_CHECK(p > 1e-4, "p = %.3g for a thin arc whose sampler matches its pdf", p);
    }

    h_case("harness: the mean weight on a grid (h_sample_mean_grid) integrates its numbers");
    v = h_sample_mean_grid(grid_sampler, 0, appear_vec3_make(0, 0, 1), 200, 0);
    /* 0.75 (1/3 + 1/3): 0.4375 with uc constant at 1/2, 0.6667 if failures counted */
    H_CHECK(fabs(v - 0.5) < 1e-3, "mean of u1^2 + uc^2 over u2 <= 0.75: %.6f, want 0.5", v);

    h_case("harness: nearby seeds give unrelated streams (h_rng_make)");
    seed_streams(0);
    h_case("harness: nearby seeds give unrelated streams (check_rng_make)");
    seed_streams(1);

    h_case("harness: p-values against closed forms");
    v = h_chi2_pvalue(3.0, 2.0);
    H_CHECK(fabs(v - exp(-1.5)) < 1e-12, "Q(1, 1.5) = %.15g, want %.15g", v, exp(-1.5));
    v = h_chi2_pvalue(200.0, 150.0);
    H_CHECK(fabs(v - 0.003973185970798) < 1e-12, "chi2 200 with 150 dof: p = %.15g", v); /* reference: series for P(75, 100) in double, independent code */
    v = h_chi2_pvalue(1.0, 1.0);
    H_CHECK(fabs(v - erfc(sqrt(0.5))) < 1e-12, "chi2 1 with 1 dof: p = %.15g", v);

    h_case("harness: sphere quadrature of cos^2 and of a 1e-3-wide lobe");
    v = h_integrate_sphere(cos2, 0, appear_vec3_make(0.3f, 0.4f, 0.866f), 1e-8);
    H_CHECK(fabs(v - 4.0 * 3.141592653589793 / 3.0) < 1e-6, "integral of z^2 = %.9f", v);
    v = h_integrate_sphere(lobe, &k, appear_vec3_make(0, 0, 1), 1e-8);
    H_CHECK(fabs(v - 1.0) < 1e-5, "narrow lobe integral = %.9f", v);
}

static double lobe_down(void *c, appear_vec3 w) { appear_vec3 f = appear_neg(w); return lobe(c, f); }
void suite_harness_poles(void)
{
    double k = 1e6, v;
    h_case("harness: sphere quadrature resolves a narrow peak at -axis too");
    v = h_integrate_sphere(lobe_down, &k, appear_vec3_make(0, 0, 1), 1e-8);
    H_CHECK(fabs(v - 1.0) < 1e-5, "narrow lobe at -axis: integral = %.9f", v);
}
