/* tests/gen/fit_fuzz.c - measures the "fuzzy metal" of Ray Tracing in One Weekend against
   appear.h's GGX conductor, and fits appear_alpha_from_fuzz (appear.h, SECTION microfacet).

   The book's metal (v4, "Ray Tracing in One Weekend" listing metal-fuzz; the same vector in
   v4.0.0-alpha.1, reflect(unit(r_in), n) + fuzz * random_unit_vector()):
       reflected = reflect(r_in.direction(), rec.normal);
       reflected = unit_vector(reflected) + (fuzz * random_unit_vector());
       absorbed when dot(scattered, n) <= 0;   fuzz(f < 1 ? f : 1) in the constructor.
   random_unit_vector() is uniform on the unit sphere (v4: rejection in the cube, normalised);
   here z = 1 - 2 u1, phi = 2 pi u2, the same distribution. The v3 books (v3.2.3) and
   v4.0.0-alpha.1's The Rest of Your Life add fuzz * random_in_unit_sphere() (a point in the
   ball) instead: measured too, as "v3 (ball)". (The Rest of Your Life's metal returns true
   without the dot test, so its below-surface rays enter the object instead of being
   absorbed: the absorbed fractions below are One Weekend's.)

   What it measures, all accumulated in double, deterministic seeds (one per cell):
   1. The book's scatter, in double, as a function of fuzz and of the incidence angle theta_o
      (wo at theta_o from the normal, mirror direction r = reflect): the mean angle between
      the scattered direction and r over the rays that survive (weight 1 each, as the book's
      attenuation is the albedo), its median and 90th percentile, the tilt of the lobe's mean
      direction (its angle from the normal minus theta_o: > 0 toward the horizon), its
      aspect (mean |component out of the plane of incidence| / mean |component in the plane,
      normal to r|: 1 for a round lobe), and the fraction absorbed (below the surface).
   2. appear.h's GGX conductor, sampled by visible normals:
      appear_conductor_make_reflectance(appear_microfacet_make(APPEAR_GGX, a, a,
      APPEAR_SAMPLE_VISIBLE), F0 = 1) and appear_conductor_sample (float), as a renderer sees
      it: every statistic weighted by s.weight, a failed sample weighs 0; "lost" = 1 - mean
      weight (below-horizon samples and the single-scattering masking loss).
   3. At normal incidence, both in closed form by quadrature in double (adaptive Simpson,
      tolerance 1e-13): book, mean angle = (1/2) int_0^pi atan2(f sin a, 1 + f cos a) sin a da
      (it comes out as 45 degrees * fuzz, to 1e-14 degrees); GGX, with t = tan(theta_m) distributed
   as 2 a^2 t / (a^2 + t^2)^2 (the visible normals at wo = n), wi at 2 atan t, weight G1(wi) = 2 (1
   - t^2) / (1 - t^2 + sqrt((1 - t^2)^2 + 4 a^2 t^2)) for t < 1, else 0 (integrated in ln t by
   composite Gauss-Legendre, checked against adaptive Simpson). The MC of 1 and 2 is checked against
   these.
   4. alpha*(fuzz): the alpha whose GGX mean angle at normal incidence (3) equals the book's,
      on 801 values of fuzz in [0, 1] (bracketed secant); then fits of the form
          alpha(f) = f (1/4 + f N(f) / (1 - f Q(f)))
      (1/4 is the exact slope at 0: the book's mean is f pi/4, GGX's pi alpha + O(alpha^2)),
      N, Q polynomials with coefficients >= 0, so that every float operation of the form has
      non-negative operands and the evaluation is monotone in f under any rounding. N by
      weighted least squares on the relative error of the mean angle, with Lawson's minimax
      reweighting; Q by Nelder-Mead around it. Two plain polynomials are printed for
      comparison. Each fit's error is then measured by quadrature on 4001 values of fuzz: the
      mean angle of GGX at alpha(f) against the book's (relative and in degrees), and alpha
      against alpha* (on 200 of them). The same for appear.h's float appear_alpha_from_fuzz,
      plus a monotonicity check over every float in [0, 1] and the fuzz below which the
      result is under APPEAR_MICROFACET_ALPHA_MIN (the smooth conductor).
   5. Tables: the book over fuzz x theta_o in {0, 30, 45, 60, 75, 85}; GGX over alpha x
      theta_o; book vs GGX at alpha*(fuzz) at 0, 45, 75 degrees (lobe shapes, energy); the old
      porting row (alpha = fuzz) at normal incidence.

   Build and run (about a minute at the default 10^6 samples per cell; the output is the same
   on every run):
       cc -std=c99 -O2 -I. tests/gen/fit_fuzz.c -lm -o build/fit_fuzz && ./build/fit_fuzz [N]
*/
#include "appear.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define DEG (180.0 / PI)

/* ---- deterministic RNG (splitmix64) ---- */
typedef struct {
    unsigned long long s;
} rng;
static unsigned long long rng_next(rng *r)
{
    unsigned long long z = (r->s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}
static double rnd(rng *r) { return (double)(rng_next(r) >> 11) * (1.0 / 9007199254740992.0); }
static float rndf(rng *r) { return (float)(rng_next(r) >> 40) * (1.0f / 16777216.0f); }
static rng rng_cell(int a, int b, int c)
{
    rng r;
    r.s = 0x2545f4914f6cdd1dULL ^ ((unsigned long long)a << 40) ^ ((unsigned long long)b << 20) ^
          (unsigned long long)c;
    rng_next(&r);
    return r;
}

/* ---- adaptive Simpson ---- */
typedef double (*fn1)(const void *ctx, double x);
static double simpson_r(fn1 g, const void *c, double a, double b, double fa, double fm, double fb,
                        double S, double eps, int depth)
{
    double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
    double flm = g(c, lm), frm = g(c, rm);
    double Sl = (m - a) / 6 * (fa + 4 * flm + fm), Sr = (b - m) / 6 * (fm + 4 * frm + fb);
    if (depth <= 0 || fabs(Sl + Sr - S) <= 15 * eps) return Sl + Sr + (Sl + Sr - S) / 15;
    return simpson_r(g, c, a, m, fa, flm, fm, Sl, eps / 2, depth - 1) +
           simpson_r(g, c, m, b, fm, frm, fb, Sr, eps / 2, depth - 1);
}
static double integrate(fn1 g, const void *c, double a, double b)
{
    double fa = g(c, a), fb = g(c, b), fm = g(c, 0.5 * (a + b));
    return simpson_r(g, c, a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), 1e-13, 48);
}

/* ---- 3: normal incidence by quadrature ---- */
static double book_q_fn(const void *c, double a)
{
    double f = *(const double *)c;
    return 0.5 * atan2(f * sin(a), 1.0 + f * cos(a)) * sin(a);
}
/* the book's mean angle (radians) at normal incidence */
static double book_mean_q(double f) { return f > 0 ? integrate(book_q_fn, &f, 0.0, PI) : 0.0; }
typedef struct {
    double a;
    int moment;
} ggx_q;
/* in u = ln t (t = tan theta_m): density 2 a^2 t^2 / (a^2 + t^2)^2 du, smooth at the peak
   t ~ a and in the tail t -> 1 alike; t < a 1e-9 (mass < 1e-18) is left out */
static double ggx_q_fn(const void *c, double lt)
{
    const ggx_q *q = (const ggx_q *)c;
    double a = q->a, t = exp(lt), s = a * a + t * t, u = 1.0 - t * t, G1;
    if (!(u > 0)) return 0.0; /* t = 1: wi in the tangent plane, G1 = 0 */
    G1 = 2.0 * u / (u + sqrt(u * u + 4.0 * a * a * t * t));
    return 2.0 * a * a * t * t / (s * s) * G1 * (q->moment ? 2.0 * atan(t) : 1.0);
}
static double ggx_lo(double a) { return log(a * 1e-9); }
/* composite 16-point Gauss-Legendre on `panels` equal panels (nodes by Newton on P_16) */
#define GL_N 16
static double g_glx[GL_N], g_glw[GL_N];
static void gl_init(void)
{
    int i, k, j;
    for (i = 0; i < GL_N; ++i) {
        double x = cos(PI * (i + 0.75) / (GL_N + 0.5)), p0, p1, dp = 1;
        for (k = 0; k < 100; ++k) {
            double dx;
            p0 = 1;
            p1 = x;
            for (j = 2; j <= GL_N; ++j) {
                double p2 = ((2 * j - 1) * x * p1 - (j - 1) * p0) / j;
                p0 = p1;
                p1 = p2;
            }
            dp = GL_N * (x * p1 - p0) / (x * x - 1);
            dx = p1 / dp;
            x -= dx;
            if (fabs(dx) < 1e-16) break;
        }
        g_glx[i] = x;
        g_glw[i] = 2.0 / ((1 - x * x) * dp * dp);
    }
}
static double integrate_gl(fn1 g, const void *c, double a, double b, int panels)
{
    double h = (b - a) / panels, s = 0;
    int p, i;
    for (p = 0; p < panels; ++p)
        for (i = 0; i < GL_N; ++i) s += g_glw[i] * g(c, a + h * (p + 0.5 + 0.5 * g_glx[i]));
    return 0.5 * h * s;
}
static int g_ggx_simpson; /* 1: adaptive Simpson (the check of the Gauss-Legendre rule) */
/* GGX at normal incidence: mean weight (1 - lost energy) and weighted mean angle (radians) */
static double ggx_mean_q(double a, double *E)
{
    ggx_q q;
    double e, m;
    q.a = a;
    q.moment = 0;
    e = g_ggx_simpson ? integrate(ggx_q_fn, &q, ggx_lo(a), 0.0)
                      : integrate_gl(ggx_q_fn, &q, ggx_lo(a), 0.0, 48);
    q.moment = 1;
    m = g_ggx_simpson ? integrate(ggx_q_fn, &q, ggx_lo(a), 0.0)
                      : integrate_gl(ggx_q_fn, &q, ggx_lo(a), 0.0, 48);
    if (E) *E = e;
    return e > 0 ? m / e : 0.0;
}
/* alpha whose GGX mean angle at normal incidence is M (radians), on [0, 1.4] (GGX's mean
   grows with alpha up to 49 degrees at alpha 1.6): bracketed secant (Illinois) to 1e-15 */
static double alpha_star(double M)
{
    double lo = 0.0, hi = 1.4, flo = -M, fhi = ggx_mean_q(hi, NULL) - M, x = 0;
    int k, side = 0;
    if (M <= 0) return 0.0;
    for (k = 0; k < 200 && hi - lo > 1e-15; ++k) {
        double fx;
        x = (lo * fhi - hi * flo) / (fhi - flo);
        if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
        fx = ggx_mean_q(x, NULL) - M;
        if (fx == 0) return x;
        if (fx < 0) {
            lo = x;
            flo = fx;
            if (side == -1) fhi *= 0.5;
            side = -1;
        } else {
            hi = x;
            fhi = fx;
            if (side == 1) flo *= 0.5;
            side = 1;
        }
        if (fabs(fx) < 1e-15) break;
    }
    return x;
}

/* ---- 1, 2: Monte Carlo statistics of one cell ---- */
#define NBIN 18000 /* 0.01 degree bins of the angle to the mirror direction */
typedef struct {
    double n, w, wa, wv[3], beyond; /* samples, sum w, sum w angle, sum w wi, w beyond a cap */
    double win, wout;               /* sum w |wi.e1| (in the plane of incidence), w |wi.y| */
    double hist[NBIN];
} stats;
typedef struct {
    double mean, median, p90, tilt, kept, beyond, aspect;
} summary;
static void st_add(stats *s, double w, const double wi[3], const double r[3], double cap)
{
    double c, ang;
    int b;
    s->n += 1;
    if (!(w > 0)) return;
    c = wi[0] * r[0] + wi[1] * r[1] + wi[2] * r[2];
    ang = acos(c > 1 ? 1 : c < -1 ? -1 : c);
    s->w += w;
    s->wa += w * ang;
    s->wv[0] += w * wi[0];
    s->wv[1] += w * wi[1];
    s->wv[2] += w * wi[2];
    if (ang > cap) s->beyond += w;
    /* e1 = (r.z, 0, -r.x): the direction in the plane of incidence normal to r */
    s->win += w * fabs(wi[0] * r[2] - wi[2] * r[0]);
    s->wout += w * fabs(wi[1]);
    b = (int)(ang * DEG * 100.0);
    s->hist[b < 0 ? 0 : b >= NBIN ? NBIN - 1 : b] += w;
}
static double st_quantile(const stats *s, double q)
{
    double acc = 0, target = q * s->w;
    int b;
    for (b = 0; b < NBIN; ++b) {
        if (acc + s->hist[b] >= target)
            return (b + (s->hist[b] > 0 ? (target - acc) / s->hist[b] : 0.0)) / 100.0;
        acc += s->hist[b];
    }
    return 180.0;
}
static summary st_sum(const stats *s, double theta_o)
{
    summary m;
    double len = sqrt(s->wv[0] * s->wv[0] + s->wv[1] * s->wv[1] + s->wv[2] * s->wv[2]);
    m.kept = s->w / s->n;
    m.mean = s->w > 0 ? s->wa / s->w * DEG : 0;
    m.median = s->w > 0 ? st_quantile(s, 0.5) : 0;
    m.p90 = s->w > 0 ? st_quantile(s, 0.9) : 0;
    m.tilt = len > 0 ? acos(s->wv[2] / len) * DEG - theta_o * DEG : 0;
    m.beyond = s->w > 0 ? s->beyond / s->w : 0;
    m.aspect = s->win > 0 ? s->wout / s->win : 0;
    return m;
}
static stats g_st; /* one cell at a time (the histogram is large) */

/* variant 0: v4 (unit sphere), 1: v3 (ball). Returns 1 and wi (unit) if it survives. */
static int book_scatter(double f, int variant, const double r[3], rng *g, double wi[3])
{
    double z = 1.0 - 2.0 * rnd(g), phi = 2.0 * PI * rnd(g), s = sqrt(fmax(0.0, 1.0 - z * z));
    double rad = variant ? cbrt(rnd(g)) : 1.0, d[3], len;
    d[0] = r[0] + f * rad * s * cos(phi);
    d[1] = r[1] + f * rad * s * sin(phi);
    d[2] = r[2] + f * rad * z;
    if (!(d[2] > 0)) return 0; /* dot(scattered, n) <= 0: absorbed */
    len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    wi[0] = d[0] / len;
    wi[1] = d[1] / len;
    wi[2] = d[2] / len;
    return 1;
}
static summary book_cell(double f, int variant, double theta_o, long n, int seed_a, int seed_b,
                         double cap)
{
    double r[3] = {-sin(theta_o), 0.0, cos(theta_o)}, wi[3];
    rng g = rng_cell(1 + variant, seed_a, seed_b);
    long i;
    memset(&g_st, 0, sizeof g_st);
    for (i = 0; i < n; ++i) {
        int ok = book_scatter(f, variant, r, &g, wi);
        st_add(&g_st, ok ? 1.0 : 0.0, wi, r, cap);
    }
    return st_sum(&g_st, theta_o);
}
static summary ggx_cell(double a, double theta_o, long n, int seed_a, int seed_b, double cap,
                        double *lost_samples)
{
    appear_conductor c = appear_conductor_make_reflectance(
        appear_microfacet_make(APPEAR_GGX, (float)a, (float)a, APPEAR_SAMPLE_VISIBLE),
        appear_spectrum_splat(1.0f));
    appear_vec3 wo = appear_vec3_make((float)sin(theta_o), 0.0f, (float)cos(theta_o));
    double r[3] = {-(double)wo.x, 0.0, (double)wo.z}, wi[3], failed = 0;
    rng g = rng_cell(3, seed_a, seed_b);
    long i;
    memset(&g_st, 0, sizeof g_st);
    for (i = 0; i < n; ++i) {
        appear_bsdf_record s;
        float u1 = rndf(&g), u2 = rndf(&g);
        int ok = appear_conductor_sample(&c, wo, 0.5f, u1, u2, &s);
        wi[0] = s.wi.x;
        wi[1] = s.wi.y;
        wi[2] = s.wi.z;
        failed += !ok;
        st_add(&g_st, ok ? (double)s.weight.v[0] : 0.0, wi, r, cap);
    }
    if (lost_samples) *lost_samples = failed / (double)n;
    return st_sum(&g_st, theta_o);
}

/* ---- 4: the fit ---- */
#define NF 801  /* fit nodes */
#define NT 4001 /* test nodes */
#define MAXP 4
static double g_fn[NF], g_an[NF], g_sl[NF], g_mb[NF]; /* f, alpha*, d M / d alpha, book mean */

/* the form: alpha(f) = f (1/4 + f N(f) / (1 - f Q(f))), N = n0 + n1 f + ..., Q = q0 + q1 f + ...
   With every coefficient >= 0 (and 1 - f Q(f) > 0 on [0, 1]) each operation is monotone in f
   with non-negative operands, so the float evaluation is monotone whatever the rounding. */
typedef struct {
    int np, nq;
    double n[MAXP], q[MAXP];
} form;
static double poly(const double *c, int k, double f)
{
    double p = 0;
    while (k-- > 0) p = p * f + c[k];
    return p;
}
static double form_eval(const form *fm, double f)
{
    return f * (0.25 + f * poly(fm->n, fm->np, f) / (1.0 - f * poly(fm->q, fm->nq, f)));
}
/* least squares by Householder QR: A (m x n, row-major), b (m) -> x (n) */
static void lsq(double *A, double *b, int m, int n, double *x)
{
    int j, i, k;
    for (j = 0; j < n; ++j) {
        double nrm = 0, s, v0, beta, d;
        for (i = j; i < m; ++i) nrm += A[i * n + j] * A[i * n + j];
        nrm = sqrt(nrm);
        s = A[j * n + j] > 0 ? -nrm : nrm;
        v0 = A[j * n + j] - s;
        beta = s * v0; /* -(v'v)/2 */
        A[j * n + j] = v0;
        for (k = j + 1; k < n; ++k) {
            for (d = 0, i = j; i < m; ++i) d += A[i * n + j] * A[i * n + k];
            d /= beta;
            for (i = j; i < m; ++i) A[i * n + k] += d * A[i * n + j];
        }
        for (d = 0, i = j; i < m; ++i) d += A[i * n + j] * b[i];
        d /= beta;
        for (i = j; i < m; ++i) b[i] += d * A[i * n + j];
        A[j * n + j] = s;
    }
    for (j = n - 1; j >= 0; --j) {
        double d = b[j];
        for (k = j + 1; k < n; ++k) d -= A[j * n + k] * x[k];
        x[j] = d / A[j * n + j];
    }
}
static double g_A[NF * MAXP], g_b[NF];
/* N for a given Q: the residual f^2 N(f) - (alpha* - f/4) D(f), D = 1 - f Q(f), weighted by
   (d M / d alpha) / M_book / D turns an alpha error into the relative error of the mean angle
   (to first order); Lawson's reweighting drives least squares to minimax. Returns the
   largest weighted error, plus 1 when a coefficient is negative or D(1) < 0.02. */
static double fit_n(form *fm)
{
    static double lw[NF];
    int it, i, k, np = fm->np;
    double worst = 0, sum;
    for (k = 0; k < fm->nq; ++k)
        if (fm->q[k] < 0) return 2.0;
    if (1.0 - poly(fm->q, fm->nq, 1.0) < 0.02) return 2.0;
    for (i = 0; i < NF; ++i) lw[i] = 1.0;
    for (it = 0; it < 40; ++it) {
        for (i = 1; i < NF; ++i) {
            double f = g_fn[i], D = 1.0 - f * poly(fm->q, fm->nq, f), p = 1.0;
            double w = sqrt(lw[i]) * g_sl[i] / g_mb[i] / D;
            for (k = 0; k < np; ++k, p *= f) g_A[(i - 1) * np + k] = w * f * f * p;
            g_b[i - 1] = w * (g_an[i] - 0.25 * f) * D;
        }
        lsq(g_A, g_b, NF - 1, np, fm->n);
        worst = sum = 0;
        for (i = 1; i < NF; ++i) {
            double e = fabs(form_eval(fm, g_fn[i]) - g_an[i]) * g_sl[i] / g_mb[i];
            if (e > worst) worst = e;
            lw[i] *= e + 1e-300;
            sum += lw[i];
        }
        for (i = 1; i < NF; ++i) lw[i] /= sum;
    }
    for (k = 0; k < np; ++k)
        if (fm->n[k] < 0) worst += 1.0;
    return worst;
}
/* Q by Nelder-Mead (deterministic start, 4 restarts of 300 steps), N by fit_n inside */
static double nm_obj(form *fm, const double *q)
{
    memcpy(fm->q, q, sizeof fm->q);
    return fit_n(fm);
}
static double fit_form(form *fm)
{
    double s[MAXP + 1][MAXP], fv[MAXP + 1], x[MAXP] = {0.5, 0.25, 0.05, 0.0};
    int n = fm->nq, i, j, it, r;
    if (n == 0) return fit_n(fm);
    if (n == 1) x[0] = 0.75;
    for (r = 0; r < 4; ++r) {
        for (i = 0; i <= n; ++i) {
            for (j = 0; j < n; ++j) s[i][j] = x[j] + (i == j + 1 ? 0.05 : 0.0);
            fv[i] = nm_obj(fm, s[i]);
        }
        for (it = 0; it < 300; ++it) {
            double cen[MAXP] = {0}, xr[MAXP] = {0}, xt[MAXP] = {0}, fr, ft;
            int hi = 0, lo = 0, nh;
            for (i = 1; i <= n; ++i) {
                if (fv[i] > fv[hi]) hi = i;
                if (fv[i] < fv[lo]) lo = i;
            }
            nh = lo;
            for (i = 0; i <= n; ++i)
                if (i != hi && fv[i] > fv[nh]) nh = i;
            for (i = 0; i <= n; ++i)
                if (i != hi)
                    for (j = 0; j < n; ++j) cen[j] += s[i][j] / n;
            for (j = 0; j < n; ++j) xr[j] = 2 * cen[j] - s[hi][j];
            fr = nm_obj(fm, xr);
            if (fr < fv[lo]) { /* expand */
                for (j = 0; j < n; ++j) xt[j] = 3 * cen[j] - 2 * s[hi][j];
                ft = nm_obj(fm, xt);
                if (ft < fr) {
                    memcpy(s[hi], xt, sizeof xt);
                    fv[hi] = ft;
                } else {
                    memcpy(s[hi], xr, sizeof xr);
                    fv[hi] = fr;
                }
            } else if (fr < fv[nh]) {
                memcpy(s[hi], xr, sizeof xr);
                fv[hi] = fr;
            } else { /* contract, else shrink toward the best */
                for (j = 0; j < n; ++j) xt[j] = 0.5 * (cen[j] + s[hi][j]);
                ft = nm_obj(fm, xt);
                if (ft < fv[hi]) {
                    memcpy(s[hi], xt, sizeof xt);
                    fv[hi] = ft;
                } else
                    for (i = 0; i <= n; ++i)
                        if (i != lo) {
                            for (j = 0; j < n; ++j) s[i][j] = 0.5 * (s[lo][j] + s[i][j]);
                            fv[i] = nm_obj(fm, s[i]);
                        }
            }
        }
        for (i = 1, j = 0; i <= n; ++i)
            if (fv[i] < fv[j]) j = i;
        memcpy(x, s[j], sizeof x);
    }
    return nm_obj(fm, x);
}
/* the error of alpha(f), measured by quadrature on NT values of fuzz */
typedef struct {
    double rel, deg, at_rel, at_deg, arel, at_arel;
} fit_err;
static fit_err measure(double (*alpha_of)(double f, const void *ctx), const void *ctx)
{
    fit_err e;
    int i;
    memset(&e, 0, sizeof e);
    for (i = 1; i < NT; ++i) {
        double f = (double)i / (NT - 1), a = alpha_of(f, ctx), mb = book_mean_q(f);
        double mg = ggx_mean_q(a, NULL), rel = fabs(mg / mb - 1), deg = fabs(mg - mb) * DEG;
        if (rel > e.rel) {
            e.rel = rel;
            e.at_rel = f;
        }
        if (deg > e.deg) {
            e.deg = deg;
            e.at_deg = f;
        }
        if (i % 20 == 0) {
            double ar = fabs(a / alpha_star(mb) - 1);
            if (ar > e.arel) {
                e.arel = ar;
                e.at_arel = f;
            }
        }
    }
    return e;
}
static double form_alpha(double f, const void *ctx) { return form_eval((const form *)ctx, f); }
static double header_alpha(double f, const void *ctx)
{
    (void)ctx;
    return appear_alpha_from_fuzz((float)f);
}

static const double g_theta[] = {0, 30, 45, 60, 75, 85};
#define NTH 6

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 1000000L;
    static const double fz[] = {0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
    static const double al[] = {0.01, 0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.7, 1.0};
    static const double tf[] = {0.05, 0.1, 0.3, 0.5, 0.8, 1.0}; /* the test's fuzz values */
    static const int forms[][2] = {{3, 0}, {4, 0}, {1, 1}, {1, 2}, {1, 3}};
    const int nfz = (int)(sizeof fz / sizeof fz[0]), nal = (int)(sizeof al / sizeof al[0]);
    int i, j, v, k;
    double worst_q = 0, worst_m = 0;

    printf("fit_fuzz: %ld samples per Monte Carlo cell\n\n", n);
    gl_init();
    { /* the Gauss-Legendre rule against adaptive Simpson (tolerance 1e-13) */
        double worst = 0, a;
        for (a = 0.001; a < 1.5; a *= 1.3) {
            double E1, E2, m1 = ggx_mean_q(a, &E1), m2;
            g_ggx_simpson = 1;
            m2 = ggx_mean_q(a, &E2);
            g_ggx_simpson = 0;
            if (fabs(m1 / m2 - 1) > worst) worst = fabs(m1 / m2 - 1);
            if (fabs(E1 / E2 - 1) > worst) worst = fabs(E1 / E2 - 1);
        }
        printf("GGX quadrature: Gauss-Legendre 48 x 16 in ln t vs adaptive Simpson, max rel diff "
               "%.1e (alpha 0.001 .. 1.5)\n\n",
               worst);
    }

    /* ---- 3: quadrature at normal incidence ---- */
    printf("== Normal incidence by quadrature (double) ==\n");
    printf("fuzz  book mean (deg)  45*fuzz - book\n");
    for (i = 0; i <= 20; ++i) {
        double f = i / 20.0, m = book_mean_q(f) * DEG;
        if (fabs(m - 45 * f) > worst_q) worst_q = fabs(m - 45 * f);
        if (i % 2 == 0) printf("%4.2f  %15.10f  %9.2e\n", f, m, 45 * f - m);
    }
    printf("max |book mean - 45 fuzz| over 21 values: %.2e deg\n\n", worst_q);
    printf("alpha  GGX mean (deg)  lost energy  lost samples (a^2/(1+a^2))\n");
    for (i = 0; i < nal; ++i) {
        double E, m = ggx_mean_q(al[i], &E) * DEG;
        printf("%5.3f  %14.4f  %11.5f  %12.5f\n", al[i], m, 1 - E,
               al[i] * al[i] / (1 + al[i] * al[i]));
    }
    {
        double a, mx = 0, amx = 0;
        for (a = 0.5; a <= 3.0; a += 0.01) {
            double m = ggx_mean_q(a, NULL);
            if (m > mx) {
                mx = m;
                amx = a;
            }
        }
        printf("GGX mean at normal incidence is largest at alpha %.2f: %.4f deg\n\n", amx,
               mx * DEG);
    }

    /* ---- 1: the book by Monte Carlo ---- */
    for (v = 0; v < 2; ++v) {
        printf("== Book, %s, Monte Carlo ==\n",
               v ? "v3 (fuzz * random_in_unit_sphere)" : "v4 (fuzz * random_unit_vector)");
        printf("theta_o: mean angle to the mirror direction (deg) / absorbed fraction\n");
        printf("fuzz ");
        for (j = 0; j < NTH; ++j) printf("   %2.0f: mean  absorb", g_theta[j]);
        printf("\n");
        for (i = 0; i < nfz; ++i) {
            printf("%4.2f ", fz[i]);
            for (j = 0; j < NTH; ++j) {
                summary s = book_cell(fz[i], v, g_theta[j] / DEG, n, i, j, 10.0);
                double q = book_mean_q(fz[i]) * DEG * (v ? 0.75 : 1.0);
                printf(" %9.3f %7.4f", s.mean, 1 - s.kept);
                if (j == 0 && fabs(s.mean - q) > worst_m) worst_m = fabs(s.mean - q);
            }
            printf("\n");
        }
        printf("\n");
    }
    printf("max |MC - quadrature| at normal incidence (v3: 3/4 of v4's quadrature): %.4f deg\n\n",
           worst_m);

    /* ---- 2: GGX by Monte Carlo ---- */
    worst_m = 0;
    printf("== appear.h GGX conductor (VISIBLE, F0 = 1), weight-weighted, Monte Carlo ==\n");
    printf("theta_o: mean angle to the mirror direction (deg) / lost energy (1 - mean weight)\n");
    printf("alpha");
    for (j = 0; j < NTH; ++j) printf("   %2.0f: mean   lost", g_theta[j]);
    printf("\n");
    for (i = 0; i < nal; ++i) {
        printf("%5.3f", al[i]);
        for (j = 0; j < NTH; ++j) {
            summary s = ggx_cell(al[i], g_theta[j] / DEG, n, i, j, 10.0, NULL);
            printf(" %9.3f %7.4f", s.mean, 1 - s.kept);
            if (j == 0 && fabs(s.mean - ggx_mean_q(al[i], NULL) * DEG) > worst_m)
                worst_m = fabs(s.mean - ggx_mean_q(al[i], NULL) * DEG);
        }
        printf("\n");
    }
    printf("max |MC - quadrature| at normal incidence: %.4f deg\n\n", worst_m);

    /* ---- 4: alpha*(fuzz) and the fit ---- */
    for (i = 0; i < NF; ++i) {
        double f = (double)i / (NF - 1), a, h;
        g_fn[i] = f;
        g_mb[i] = book_mean_q(f);
        a = g_an[i] = alpha_star(g_mb[i]);
        h = 1e-5 * (a + 1e-4);
        g_sl[i] = a > h ? (ggx_mean_q(a + h, NULL) - ggx_mean_q(a - h, NULL)) / (2 * h) : PI;
    }
    printf("== alpha*(fuzz): GGX mean angle at normal incidence = the book's (v4) ==\n");
    printf("fuzz  book mean (deg)  alpha*     alpha*/fuzz\n");
    for (i = 0; i < NF; i += 40)
        printf("%4.2f  %15.4f  %9.6f  %9.6f\n", g_fn[i], g_mb[i] * DEG, g_an[i],
               i ? g_an[i] / g_fn[i] : 0.25);
    printf("\n== Fits alpha(f) = f (1/4 + f N(f) / (1 - f Q(f))), minimax on the relative error of "
           "the mean angle;\n   'monotone' = every coefficient >= 0 (float evaluation monotone by "
           "construction) ==\n");
    for (i = 0; i < (int)(sizeof forms / sizeof forms[0]); ++i) {
        form fm;
        double w;
        fit_err e;
        int pos = 1;
        memset(&fm, 0, sizeof fm);
        fm.np = forms[i][0];
        fm.nq = forms[i][1];
        w = fit_form(&fm);
        for (k = 0; k < fm.np; ++k) pos &= fm.n[k] >= 0;
        for (k = 0; k < fm.nq; ++k) pos &= fm.q[k] >= 0;
        e = measure(form_alpha, &fm);
        printf("N degree %d, Q degree %d: linearised %.2e; measured: mean angle rel %.2e "
               "(f %.3f), %.4f deg (f %.3f); alpha rel %.2e (f %.2f); monotone %s\n  N:",
               fm.np - 1, fm.nq - 1, w > 1 ? w - 1 : w, e.rel, e.at_rel, e.deg, e.at_deg, e.arel,
               e.at_arel, pos ? "yes" : "no");
        for (k = 0; k < fm.np; ++k) printf(" %.9g", fm.n[k]);
        printf("  Q:");
        for (k = 0; k < fm.nq; ++k) printf(" %.9g", fm.q[k]);
        printf("\n");
        if (fm.np == 1 && fm.nq == 2)
            printf(
                "  appear.h's form: alpha = f (0.25f + f %.6gf / (1.0f - f (%.6gf + %.6gf f)))\n",
                fm.n[0], fm.q[0], fm.q[1]);
    }
    {
        fit_err e = measure(header_alpha, NULL);
        float prev = 0.0f, f;
        unsigned long long nonmono = 0, nf = 0;
        unsigned int b;
        printf("\nappear.h appear_alpha_from_fuzz (float): mean angle rel %.2e (f %.3f), %.4f deg "
               "(f %.3f); alpha rel %.2e (f %.2f)\n",
               e.rel, e.at_rel, e.deg, e.at_deg, e.arel, e.at_arel);
        for (b = 0; b <= 0x3f800000u; ++b, ++nf) { /* every float in [0, 1] */
            float a;
            memcpy(&f, &b, sizeof f);
            a = appear_alpha_from_fuzz(f);
            nonmono += a < prev;
            prev = a;
        }
        for (f = 1e-3f, b = 0; b < 200; ++b) { /* the largest fuzz that stays smooth */
            float m = 0.5f * f;
            if (appear_alpha_from_fuzz(m) < APPEAR_MICROFACET_ALPHA_MIN) break;
            f = m;
        }
        {
            float lo = 0.0f, hi = f;
            for (b = 0; b < 100; ++b) {
                float m = 0.5f * (lo + hi);
                if (appear_alpha_from_fuzz(m) < APPEAR_MICROFACET_ALPHA_MIN)
                    lo = m;
                else
                    hi = m;
            }
            printf("  alpha(0) = %g, alpha(0.3) = %.6g, alpha(1) = %.9g; smooth (alpha < %g) for "
                   "fuzz < %.6g; decreasing steps over all %llu floats in [0, 1]: %llu\n\n",
                   (double)appear_alpha_from_fuzz(0.0f), (double)appear_alpha_from_fuzz(0.3f),
                   (double)appear_alpha_from_fuzz(1.0f), (double)APPEAR_MICROFACET_ALPHA_MIN,
                   (double)hi, nf, nonmono);
        }
    }

    /* ---- 5: book vs GGX at the mapped alpha, lobe shapes ---- */
    printf("== Book (v4) vs GGX at alpha*(fuzz) (the exact alpha, not the fit), lobe shapes ==\n");
    printf("(angles in degrees to the mirror direction r; tilt: the mean direction's angle from\n"
           " the normal minus theta_o, > 0 toward the horizon; asp: mean |out-of-plane component|\n"
           " / mean |in-plane component normal to r|; beyond: the share of the GGX energy past\n"
           " the book's widest angle asin(fuzz) (fuzz < 1); lost: book absorbed, GGX 1 - mean "
           "weight)\n");
    printf("th  fuzz  alpha* | book: mean median   p90   tilt  asp  lost | GGX: mean median    p90"
           "   tilt  asp  lost beyond\n");
    for (j = 0; j < NTH; ++j) {
        int t;
        if (g_theta[j] != 0 && g_theta[j] != 45 && g_theta[j] != 75) continue;
        for (t = 0; t < 6; ++t) {
            double f = tf[t], a = alpha_star(book_mean_q(f)), cap = f < 1 ? asin(f) : PI;
            summary b = book_cell(f, 0, g_theta[j] / DEG, n, 100 + t, j, cap);
            summary gx = ggx_cell(a, g_theta[j] / DEG, n, 100 + t, j, cap, NULL);
            printf("%2.0f  %4.2f  %6.4f | %9.3f %6.3f %6.3f %6.2f %4.2f %5.3f | %8.3f %6.3f %6.3f "
                   "%6.2f %4.2f %5.3f %5.3f\n",
                   g_theta[j], f, a, b.mean, b.median, b.p90, b.tilt, b.aspect, 1 - b.kept, gx.mean,
                   gx.median, gx.p90, gx.tilt, gx.aspect, 1 - gx.kept, gx.beyond);
        }
    }
    printf("\n== The old porting row, alpha = fuzz, normal incidence (quadrature) ==\n");
    for (i = 0; i < 6; ++i) {
        double E, f = tf[i], m = ggx_mean_q(f, &E) * DEG;
        printf("fuzz %4.2f: book %.3f deg, GGX alpha = fuzz %.3f deg, lost energy %.4f, lost "
               "samples %.4f\n",
               f, book_mean_q(f) * DEG, m, 1 - E, f * f / (1 + f * f));
    }
    return 0;
}
