/* check.h - public domain / MIT - checks for any BSDF or phase function, yours or appear.h's
                                   no warranty implied; use at your own risk

   One file, C99 and C++ (C++11 on), libm only: no appear.h, no image
   library. build/appear-check and appear.h's own test suite are built on it.

   ===========================================================================
   DO THIS
   ===========================================================================

       #include "check.h"

   in every file that calls it, and in exactly ONE C or C++ file write

       #define CHECK_IMPLEMENTATION
       #include "check.h"

   which adds the functions' code. That file may have included check.h
   before (through another header): the code comes in at the first include
   that sees the macro, and any later include adds nothing.

   ===========================================================================
   WHAT IT CHECKS
   ===========================================================================

   Four checks that a renderer's own test program can run on its own
   materials through three callbacks (eval, pdf, sample) and a void*
   context:

     check_furnace      albedo at wo (mean sample weight) with its standard
                        error; reflected / transmitted / delta shares.
                        Transmitted weights count as energy: x e^2, e =
                        n(wi side) / n(wo side), for BSDFs with eta != 1
                        (radiance-convention BTDFs obey R + e^2 T <= 1).
     check_reciprocity  max relative violation of f(wo,wi) = f(wi,wo) over
                        random pairs (half uniform, half drawn by sample);
                        refraction: n_i^2 f(wo,wi) = n_o^2 f(wi,wo) (n_o,
                        n_i the indices on wo's and wi's side); with sigma
                        set (micro-flake media): sigma(wo) f(wo,wi) =
                        sigma(wi) f(wi,wo).
     check_chi2         Pearson chi-square of sample against pdf on equal-
                        area (phi, cos) bins about an axis (optionally a cap
                        cos >= zmin); expected counts by adaptive Gauss-
                        Legendre quadrature of pdf per bin; bins under 5
                        expected pooled; p from the regularised incomplete
                        gamma function. Keeps both histograms for output.
     check_consistency  at sampled directions: sample's f and pdf equal
                        eval and pdf, weight = f |cos| / pdf (phase: f/pdf).

   Conventions: directions are unit vectors pointing AWAY from the surface
   or the scattering point (local frame, z = normal for BSDFs); for a phase
   function cos(theta) = -dot(wo, wi). Values are scalars (average your
   colour channels or pick one). Delta lobes: sample sets s->delta = 1;
   they count in the furnace and go to the chi2's "rest" cell.

   The model: check_model_make(name, ctx, is_bsdf, eval, pdf, sample) fills
   every field (C and C++ alike); then set the optional ones that apply:

       m.eta = 1.5;              BSDF with refraction: n_inside / n_outside
                                 (wo.z < 0 is inside); default 1: none
       m.eval_is_estimate = 1;   eval returns a noisy unbiased estimate
                                 (random walks); default 0
       m.sigma = my_sigma;       micro-flake media: the projected area
                                 sigma(w) that weights reciprocity;
                                 default NULL

   Example (a renderer's Lambertian, albedo 0.8):

       #define CHECK_IMPLEMENTATION
       #include "check.h"
       static double ev(void *c, check_vec3 o, check_vec3 i)
       { (void)c; return o.z * i.z > 0 ? 0.8 / 3.14159265358979 : 0; }
       static double pd(void *c, check_vec3 o, check_vec3 i)
       { (void)c; return o.z * i.z > 0 ? fabs(i.z) / 3.14159265358979 : 0; }
       static int sa(void *c, check_vec3 o, double uc, double u1, double u2, check_sample *s)
       { double r = sqrt(u1), p = 6.283185307179586 * u2; (void)uc;
         s->wi.x = r * cos(p); s->wi.y = r * sin(p); s->wi.z = copysign(sqrt(1 - u1), o.z);
         s->f = ev(c, o, s->wi); s->pdf = pd(c, o, s->wi); s->weight = 0.8; s->delta = 0;
         return s->pdf > 0; }
       ...
       check_model m = check_model_make("my lambert", NULL, 1, ev, pd, sa);
       check_vec3 wo = check_vec3_make(0.6, 0, 0.8);
       check_furnace_result fr;  check_chi2_result cr;
       check_furnace(&m, wo, 100000, 1, &fr);        // fr.albedo 0.8, fr.se 0
       check_chi2(&m, wo, NULL, &cr);                // cr.p > 0.01: pass
       printf("albedo %.4f +- %.4f  chi2 p %.3f\n", fr.albedo, fr.se, cr.p);
       check_chi2_free(&cr);

   (tests/compile/tu_check.c is this example, built as C99 and C++ by
   make check-compile.)

   Every function returns 0 on success and -1 when it cannot run (no
   sampler, no pdf where one is needed, out of memory); the verdict is in
   the result (compare to your tolerance: e.g. |albedo - 1| <= 4 se for a
   lossless model, chi2 p above your significance after a Sidak or
   Bonferroni correction over your whole suite). Nothing is printed, and no
   state is kept between calls: the random numbers come from the seed.
*/
#ifndef APPEAR_CHECK_H
#define APPEAR_CHECK_H
#include <stddef.h> /* NULL */
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif

typedef struct check_vec3 { double x, y, z; } check_vec3;

/* What sample() fills. */
typedef struct check_sample {
    check_vec3 wi;  /* unit */
    double f;       /* value the sampler reports (delta: the delta coefficient) */
    double pdf;     /* solid-angle pdf (delta: probability of the lobe) */
    double weight;  /* f |wi.z| / pdf (BSDF), f / pdf (phase function) */
    int delta;      /* 1: a delta lobe, which eval/pdf do not describe */
} check_sample;

/* The callbacks: f without the cosine; the solid-angle pdf; a sample (returns 1 when it
   succeeded); the projected area of a micro-flake medium. */
typedef double (*check_eval_fn)(void *ctx, check_vec3 wo, check_vec3 wi);
typedef double (*check_pdf_fn)(void *ctx, check_vec3 wo, check_vec3 wi);
typedef int (*check_sample_fn)(void *ctx, check_vec3 wo, double uc, double u1, double u2,
                               check_sample *s);
typedef double (*check_sigma_fn)(void *ctx, check_vec3 w);

/* Build one with check_model_make, then set the optional fields that apply. */
typedef struct check_model {
    const char *name;
    void *ctx;              /* passed to every callback */
    int is_bsdf;            /* 1: BSDF (|wi.z| weighting, sides); 0: phase function */
    double eta;             /* optional, default 1. BSDF with refraction: n_inside / n_outside
                               (wo.z < 0 is inside); 1 or 0: none */
    int eval_is_estimate;   /* optional, default 0. 1: eval returns a noisy unbiased estimate
                               (random walks): reciprocity averages, consistency skips f */
    check_eval_fn eval;     /* f, no cosine; NULL: none (reciprocity cannot run) */
    check_pdf_fn pdf;       /* NULL: none (chi2 cannot run) */
    check_sample_fn sample; /* NULL: none (furnace, chi2, consistency cannot run) */
    check_sigma_fn sigma;   /* optional, default NULL; or the projected area of a micro-flake
                               medium */
} check_model;
/* Every field set: name, ctx, is_bsdf and the three callbacks as given, eta 1,
   eval_is_estimate 0, sigma NULL. Never fails. */
check_model check_model_make(const char *name, void *ctx, int is_bsdf, check_eval_fn eval,
                             check_pdf_fn pdf, check_sample_fn sample);

/* ---- furnace ---- */
typedef struct check_furnace_result {
    double albedo, se;          /* mean energy weight and its standard error */
    double reflect, transmit;   /* the shares of wi on wo's side / the other side */
    double delta;               /* share carried by delta lobes */
    double failed;              /* fraction of samples that failed */
    double max_weight;          /* largest single weight (a heavy tail shows here) */
    long n;
} check_furnace_result;
int check_furnace(const check_model *m, check_vec3 wo, long n, uint64_t seed,
                  check_furnace_result *r);

/* ---- reciprocity ---- */
typedef struct check_reciprocity_result {
    double max_rel;          /* max |a - b| / max(a, b) over pairs with max(a, b) > floor */
    double max_z;            /* eval_is_estimate: max |a - b| / (its standard error); else 0 */
    check_vec3 wo, wi;       /* where max_rel (estimates: max_z) was found */
    double f_fwd, f_rev;     /* the two sides compared there (already eta / sigma weighted) */
    long pairs, compared;
} check_reciprocity_result;
/* floor: pairs whose values are both below it are not compared (e.g. 1e-4);
   repeats: eval calls averaged per side when eval_is_estimate (e.g. 64). */
int check_reciprocity(const check_model *m, long n_pairs, double floor, int repeats,
                      uint64_t seed, check_reciprocity_result *r);

/* ---- chi-square ---- */
typedef struct check_chi2_opts {
    int n_z, n_phi;         /* bins; 0 = 32 x 64 */
    long n_samples;         /* 0 = 200000 */
    check_vec3 axis;        /* pole of the bins; zero = +z for BSDFs, -wo for phase functions */
    double zmin;            /* bins cover cos(angle to axis) in [zmin, 1]; 0 = whole sphere */
    uint64_t seed;          /* 0 = 1 */
} check_chi2_opts;
typedef struct check_chi2_result {
    double chi2, p;         /* statistic (after pooling) and p-value */
    int dof;
    double pdf_mass;        /* integral of pdf over the binned region (quadrature) */
    long n, rest_observed;  /* samples; those in the rest cell (outside, failed, delta) */
    double rest_expected;
    long zero_pdf_hits;     /* samples in bins whose pdf integral is 0 */
    int n_z, n_phi;
    double *observed, *expected; /* n_z * n_phi each, row = z band (band 0 at zmin);
                                    free with check_chi2_free */
} check_chi2_result;
/* o: NULL for the defaults. */
int check_chi2(const check_model *m, check_vec3 wo, const check_chi2_opts *o,
               check_chi2_result *r);
void check_chi2_free(check_chi2_result *r);
double check_chi2_pvalue(double chi2, double dof); /* Q(dof/2, chi2/2) */

/* ---- sample vs eval / pdf ---- */
typedef struct check_consistency_result {
    long n, checked, bad;    /* samples drawn, non-delta successes compared, beyond tol */
    double max_rel_f, max_rel_pdf, max_rel_weight;
    check_vec3 worst_wi;
} check_consistency_result;
/* tol: relative tolerance (e.g. 1e-3); f is not compared when eval_is_estimate. */
int check_consistency(const check_model *m, check_vec3 wo, long n, double tol, uint64_t seed,
                      check_consistency_result *r);

/* ---- helpers ---- */
typedef struct check_rng { uint64_t s; } check_rng;
check_rng check_rng_make(uint64_t seed);
double check_rand(check_rng *r);                 /* [0, 1), 53 bits */
check_vec3 check_vec3_make(double x, double y, double z);
check_vec3 check_dir_theta_phi(double theta_deg, double phi_deg); /* z = cos theta */

#ifdef __cplusplus
}
#endif
#endif /* APPEAR_CHECK_H */

/* ======================================================================== */
/* Implementation: in the one file that defines CHECK_IMPLEMENTATION        */
/* ======================================================================== */
#if defined(CHECK_IMPLEMENTATION) && !defined(CHECK__IMPLEMENTED)
#define CHECK__IMPLEMENTED
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CHECK__PI 3.14159265358979323846
#define CHECK__2PI 6.28318530717958647692

check_model check_model_make(const char *name, void *ctx, int is_bsdf, check_eval_fn eval,
                             check_pdf_fn pdf, check_sample_fn sample)
{
    check_model m;
    memset(&m, 0, sizeof m);
    m.name = name; m.ctx = ctx; m.is_bsdf = is_bsdf; m.eta = 1.0; m.eval_is_estimate = 0;
    m.eval = eval; m.pdf = pdf; m.sample = sample; m.sigma = NULL;
    return m;
}

check_rng check_rng_make(uint64_t seed)
{
    /* the state is a hash of the seed (splitmix64's output function, twice): a state of
       seed * gamma + c made seed s + 1's stream seed s's shifted by one draw */
    check_rng r;
    uint64_t z = seed + 0x632be59bd9b4e019ull;
    int i;
    for (i = 0; i < 2; ++i) {
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        z ^= z >> 31;
    }
    r.s = z;
    return r;
}
double check_rand(check_rng *r)
{   /* splitmix64 */
    uint64_t z = (r->s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}
check_vec3 check_vec3_make(double x, double y, double z)
{
    check_vec3 v;
    v.x = x; v.y = y; v.z = z;
    return v;
}
check_vec3 check_dir_theta_phi(double theta_deg, double phi_deg)
{
    double t = theta_deg * CHECK__PI / 180.0, p = phi_deg * CHECK__PI / 180.0;
    return check_vec3_make(sin(t) * cos(p), sin(t) * sin(p), cos(t));
}
static double check__dot3(check_vec3 a, check_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static check_vec3 check__neg3(check_vec3 a) { return check_vec3_make(-a.x, -a.y, -a.z); }
static check_vec3 check__rand_dir(check_rng *r)
{
    double z = 1.0 - 2.0 * check_rand(r), p = CHECK__2PI * check_rand(r);
    double s = sqrt(fmax(0.0, 1.0 - z * z));
    return check_vec3_make(s * cos(p), s * sin(p), z);
}
/* e = n(wi side) / n(wo side) for a BSDF with refraction, else 1 */
static double check__rel_eta(const check_model *m, check_vec3 wo, check_vec3 wi)
{
    double eta = m->eta > 0 ? m->eta : 1.0;
    if (!m->is_bsdf || eta == 1.0 || (wo.z > 0) == (wi.z > 0)) return 1.0;
    return wo.z > 0 ? eta : 1.0 / eta;
}

/* ------------------------------------------------------------------------ */
int check_furnace(const check_model *m, check_vec3 wo, long n, uint64_t seed,
                  check_furnace_result *r)
{
    check_rng rng = check_rng_make(seed);
    double s1 = 0, s2 = 0, refl = 0, tran = 0, dl = 0, mx = 0;
    long i, fail = 0;
    memset(r, 0, sizeof *r);
    if (!m->sample || n <= 0) return -1;
    for (i = 0; i < n; ++i) {
        check_sample s;
        double uc = check_rand(&rng), u1 = check_rand(&rng), u2 = check_rand(&rng), w = 0;
        memset(&s, 0, sizeof s);
        if (m->sample(m->ctx, wo, uc, u1, u2, &s) && isfinite(s.weight)) {
            double e = check__rel_eta(m, wo, s.wi);
            w = s.weight * e * e;
            if (!m->is_bsdf || (s.wi.z > 0) == (wo.z > 0)) refl += w; else tran += w;
            if (s.delta) dl += w;
        } else ++fail;
        s1 += w; s2 += w * w;
        mx = w > mx ? w : mx;
    }
    r->n = n;
    r->albedo = s1 / n;
    r->se = sqrt(fmax(0.0, s2 / n - r->albedo * r->albedo) / (n > 1 ? n - 1 : 1));
    r->reflect = refl / n; r->transmit = tran / n; r->delta = dl / n;
    r->failed = (double)fail / n;
    r->max_weight = mx;
    return 0;
}

/* ------------------------------------------------------------------------ */
static double check__eval_avg(const check_model *m, check_vec3 a, check_vec3 b, int k, double *se)
{
    double s1 = 0, s2 = 0, v;
    int i;
    if (!m->eval_is_estimate || k < 2) { *se = 0; return m->eval(m->ctx, a, b); }
    for (i = 0; i < k; ++i) { v = m->eval(m->ctx, a, b); s1 += v; s2 += v * v; }
    s1 /= k;
    *se = sqrt(fmax(0.0, s2 / k - s1 * s1) / (k - 1));
    return s1;
}
int check_reciprocity(const check_model *m, long n_pairs, double floor, int repeats, uint64_t seed,
                      check_reciprocity_result *r)
{
    check_rng rng = check_rng_make(seed);
    long i;
    memset(r, 0, sizeof *r);
    if (!m->eval || n_pairs <= 0) return -1;
    for (i = 0; i < n_pairs; ++i) {
        check_vec3 wo = check__rand_dir(&rng), wi = check__rand_dir(&rng);
        double a, b, sa, sb, e, rel, z = 0, big;
        if (m->is_bsdf && wo.z < 0 && (i & 2)) wo.z = -wo.z; /* most pairs from outside */
        if ((i & 1) && m->sample) { /* half the pairs in the lobe */
            check_sample s;
            memset(&s, 0, sizeof s);
            double uc = check_rand(&rng), u1 = check_rand(&rng), u2 = check_rand(&rng); /* in this order */
            if (!m->sample(m->ctx, wo, uc, u1, u2, &s) || s.delta) continue;
            wi = s.wi;
        }
        ++r->pairs;
        a = check__eval_avg(m, wo, wi, repeats, &sa);
        b = check__eval_avg(m, wi, wo, repeats, &sb);
        e = check__rel_eta(m, wo, wi);      /* n_i / n_o: n_i^2 f(wo,wi) = n_o^2 f(wi,wo) */
        a *= e * e; sa *= e * e;
        if (m->sigma) {
            double so = m->sigma(m->ctx, wo), si = m->sigma(m->ctx, wi);
            a *= so; sa *= so; b *= si; sb *= si;
        }
        big = fmax(fabs(a), fabs(b));
        if (!(big > floor) || !isfinite(big)) continue;
        ++r->compared;
        rel = fabs(a - b) / big;
        if (m->eval_is_estimate) z = fabs(a - b) / fmax(sqrt(sa * sa + sb * sb), 1e-300);
        if (r->compared == 1 || (m->eval_is_estimate ? z > r->max_z : rel > r->max_rel)) {
            r->wo = wo; r->wi = wi; r->f_fwd = a; r->f_rev = b;
        }
        if (rel > r->max_rel) r->max_rel = rel;
        if (z > r->max_z) r->max_z = z;
    }
    return 0;
}

/* ------------------------------------------------------------------------ */
/* regularised upper incomplete gamma Q(a, x) (series / continued fraction) */
static double check__gamma_q(double a, double x)
{
    double gln = lgamma(a);
    int i;
    if (x <= 0) return 1.0;
    if (x < a + 1.0) {
        double ap = a, sum = 1.0 / a, del = sum;
        for (i = 0; i < 10000; ++i) {
            ap += 1; del *= x / ap; sum += del;
            if (fabs(del) < fabs(sum) * 1e-15) break;
        }
        return fmax(0.0, 1.0 - sum * exp(-x + a * log(x) - gln));
    } else {
        double b = x + 1.0 - a, c = 1.0 / 1e-300, d = 1.0 / b, h = d, an, del;
        for (i = 1; i < 10000; ++i) {
            an = -i * (i - a); b += 2.0;
            d = an * d + b; if (fabs(d) < 1e-300) d = 1e-300;
            c = b + an / c; if (fabs(c) < 1e-300) c = 1e-300;
            d = 1.0 / d; del = d * c; h *= del;
            if (fabs(del - 1.0) < 1e-15) break;
        }
        return exp(-x + a * log(x) - gln) * h;
    }
}
double check_chi2_pvalue(double chi2, double dof)
{
    return dof > 0 ? check__gamma_q(dof / 2.0, chi2 / 2.0) : 1.0;
}

typedef struct { const check_model *m; check_vec3 wo, bx, by, bz; long evals; } check__quad;
static double check__quad_pdf(check__quad *q, double z, double phi)
{
    double s = sqrt(fmax(0.0, 1.0 - z * z)), c = cos(phi), sn = sin(phi), v;
    check_vec3 w = check_vec3_make(z * q->bz.x + s * (c * q->bx.x + sn * q->by.x),
                                   z * q->bz.y + s * (c * q->bx.y + sn * q->by.y),
                                   z * q->bz.z + s * (c * q->bx.z + sn * q->by.z));
    ++q->evals;
    v = q->m->pdf(q->m->ctx, q->wo, w);
    return isfinite(v) && v > 0 ? v : 0.0;
}
/* 4x4 Gauss-Legendre on [z0, z1] x [p0, p1] (dz dphi is solid angle) */
static double check__gl4(check__quad *q, double z0, double z1, double p0, double p1)
{
    static const double x[4] = { -0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                 0.8611363115940526 };
    static const double w[4] = { 0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                 0.3478548451374538 };
    double zm = 0.5 * (z0 + z1), zh = 0.5 * (z1 - z0), pm = 0.5 * (p0 + p1), ph = 0.5 * (p1 - p0);
    double s = 0;
    int i, j;
    for (i = 0; i < 4; ++i)
        for (j = 0; j < 4; ++j)
            s += w[i] * w[j] * check__quad_pdf(q, zm + zh * x[i], pm + ph * x[j]);
    return s * zh * ph;
}
static double check__adapt(check__quad *q, double z0, double z1, double p0, double p1, double whole,
                           double tol, int depth)
{
    double zm = 0.5 * (z0 + z1), pm = 0.5 * (p0 + p1);
    double a = check__gl4(q, z0, zm, p0, pm), b = check__gl4(q, zm, z1, p0, pm);
    double c = check__gl4(q, z0, zm, pm, p1), d = check__gl4(q, zm, z1, pm, p1);
    double sum = a + b + c + d;
    if (depth <= 0 || fabs(sum - whole) <= tol) return sum;
    return check__adapt(q, z0, zm, p0, pm, a, tol / 2, depth - 1) +
           check__adapt(q, zm, z1, p0, pm, b, tol / 2, depth - 1) +
           check__adapt(q, z0, zm, pm, p1, c, tol / 2, depth - 1) +
           check__adapt(q, zm, z1, pm, p1, d, tol / 2, depth - 1);
}
static void check__basis(check_vec3 n, check_vec3 *b1, check_vec3 *b2)
{   /* Duff et al. 2017 */
    double sign = n.z >= 0 ? 1.0 : -1.0, a = -1.0 / (sign + n.z), b = n.x * n.y * a;
    *b1 = check_vec3_make(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    *b2 = check_vec3_make(b, sign + n.y * n.y * a, -n.y);
}
typedef struct { double e, o; } check__cell;
static int check__cell_cmp(const void *a, const void *b)
{
    double x = ((const check__cell *)a)->e, y = ((const check__cell *)b)->e;
    return x < y ? -1 : x > y;
}
int check_chi2(const check_model *m, check_vec3 wo, const check_chi2_opts *o, check_chi2_result *r)
{
    check_chi2_opts op;
    check__quad q;
    check_rng rng;
    long i, ncell, n;
    double zmin, len, mass = 0, chi2 = 0, pe = 0, po = 0;
    int nz, np, dof = -1;
    check__cell *cells;
    memset(r, 0, sizeof *r);
    if (!m->sample || !m->pdf) return -1;
    if (o) op = *o; else memset(&op, 0, sizeof op);
    nz = op.n_z > 0 ? op.n_z : 32; np = op.n_phi > 0 ? op.n_phi : 64;
    n = op.n_samples > 0 ? op.n_samples : 200000;
    zmin = op.zmin == 0.0 ? -1.0 : op.zmin;
    len = sqrt(check__dot3(op.axis, op.axis));
    if (len == 0) { op.axis = m->is_bsdf ? check_vec3_make(0, 0, 1) : check__neg3(wo); len = 1; }
    q.m = m; q.wo = wo; q.evals = 0;
    q.bz = check_vec3_make(op.axis.x / len, op.axis.y / len, op.axis.z / len);
    check__basis(q.bz, &q.bx, &q.by);
    ncell = (long)nz * np;
    r->n_z = nz; r->n_phi = np; r->n = n;
    r->observed = (double *)calloc((size_t)ncell, sizeof(double));
    r->expected = (double *)calloc((size_t)ncell, sizeof(double));
    cells = (check__cell *)malloc((size_t)(ncell + 1) * sizeof(check__cell));
    if (!r->observed || !r->expected || !cells) { free(cells); check_chi2_free(r); return -1; }
    rng = check_rng_make(op.seed ? op.seed : 1);
    for (i = 0; i < n; ++i) {
        check_sample s;
        double uc = check_rand(&rng), u1 = check_rand(&rng), u2 = check_rand(&rng);
        memset(&s, 0, sizeof s);
        if (m->sample(m->ctx, wo, uc, u1, u2, &s) && !s.delta) {
            double z = check__dot3(s.wi, q.bz);
            double phi = atan2(check__dot3(s.wi, q.by), check__dot3(s.wi, q.bx));
            if (z >= zmin) {
                int iz = (int)((z - zmin) / (1.0 - zmin) * nz), ip;
                if (phi < 0) phi += CHECK__2PI;
                ip = (int)(phi / CHECK__2PI * np);
                iz = iz < 0 ? 0 : iz >= nz ? nz - 1 : iz;
                ip = ip < 0 ? 0 : ip >= np ? np - 1 : ip;
                r->observed[(long)iz * np + ip] += 1;
                continue;
            }
        }
        r->rest_observed++;
    }
    for (i = 0; i < ncell; ++i) {
        int iz = (int)(i / np), ip = (int)(i % np);
        double z0 = zmin + (1 - zmin) * iz / nz, z1 = zmin + (1 - zmin) * (iz + 1) / nz;
        double p0 = CHECK__2PI * ip / np, p1 = CHECK__2PI * (ip + 1) / np;
        double v = 0, tol = 0.02 / n;   /* 0.02 expected samples per bin */
        if (iz == nz - 1) {
            /* the band at the pole: geometric pieces toward z = 1 resolve a peak there */
            double a = z0, h = 1.0 - z0, piece;
            while (h > 1e-12) {
                double b = 1.0 - 0.25 * h;
                piece = check__adapt(&q, a, b, p0, p1, check__gl4(&q, a, b, p0, p1), tol / 20, 6);
                v += piece;
                a = b; h *= 0.25;
                /* the rest is below pdf(pole) x its area when the pdf peaks at the pole;
                   else go on */
                if (h < 1e-3 && piece < tol * 1e-3 &&
                    check__quad_pdf(&q, 1.0, p0) * h * (p1 - p0) < tol * 1e-3)
                    break;
            }
            v += check__adapt(&q, a, 1.0, p0, p1, check__gl4(&q, a, 1.0, p0, p1), tol / 20, 6);
        } else v = check__adapt(&q, z0, z1, p0, p1, check__gl4(&q, z0, z1, p0, p1), tol, 6);
        r->expected[i] = v * n;
        mass += v;
        if (v == 0 && r->observed[i] > 0) r->zero_pdf_hits += (long)r->observed[i];
    }
    r->pdf_mass = mass;
    r->rest_expected = fmax(0.0, 1.0 - mass) * n;
    for (i = 0; i < ncell; ++i) { cells[i].e = r->expected[i]; cells[i].o = r->observed[i]; }
    cells[ncell].e = r->rest_expected; cells[ncell].o = (double)r->rest_observed;
    qsort(cells, (size_t)ncell + 1, sizeof(check__cell), check__cell_cmp);
    for (i = 0; i <= ncell; ++i) {
        if (cells[i].e < 5.0) { pe += cells[i].e; po += cells[i].o; continue; }
        chi2 += (cells[i].o - cells[i].e) * (cells[i].o - cells[i].e) / cells[i].e;
        ++dof;
    }
    if (pe > 0) { chi2 += (po - pe) * (po - pe) / pe; ++dof; }
    free(cells);
    r->chi2 = chi2; r->dof = dof;
    r->p = check_chi2_pvalue(chi2, dof);
    /* samples where the pdf integrates to zero, beyond what the pooled cell allows */
    if (r->zero_pdf_hits > 0 && po > pe + 5.0 * sqrt(pe + 1.0)) r->p = 0.0;
    return 0;
}
void check_chi2_free(check_chi2_result *r)
{
    free(r->observed); free(r->expected);
    r->observed = r->expected = 0;
}

/* ------------------------------------------------------------------------ */
static double check__relerr(double got, double ref)
{
    double d = fabs(got - ref);
    return d == 0 ? 0 : d / fmax(fabs(ref), 1e-30);
}
int check_consistency(const check_model *m, check_vec3 wo, long n, double tol, uint64_t seed,
                      check_consistency_result *r)
{
    check_rng rng = check_rng_make(seed);
    long i;
    memset(r, 0, sizeof *r);
    if (!m->sample) return -1;
    r->n = n;
    for (i = 0; i < n; ++i) {
        check_sample s;
        double ef, ep, wexp, c, rf = 0, rp = 0, rw;
        memset(&s, 0, sizeof s);
        double uc = check_rand(&rng), u1 = check_rand(&rng), u2 = check_rand(&rng); /* in this order */
        if (!m->sample(m->ctx, wo, uc, u1, u2, &s) || s.delta) continue;
        ++r->checked;
        c = m->is_bsdf ? fabs(s.wi.z) : 1.0;
        wexp = s.pdf > 0 ? s.f * c / s.pdf : 0.0;
        rw = check__relerr(s.weight, wexp);
        if (m->eval && !m->eval_is_estimate) {
            ef = m->eval(m->ctx, wo, s.wi);
            rf = check__relerr(s.f, ef);
        }
        if (m->pdf) { ep = m->pdf(m->ctx, wo, s.wi); rp = check__relerr(s.pdf, ep); }
        if (fabs(check__dot3(s.wi, s.wi) - 1.0) > 1e-4 || !(s.pdf > 0)) rw = 1.0;
        if (rf > r->max_rel_f) r->max_rel_f = rf;
        if (rp > r->max_rel_pdf) r->max_rel_pdf = rp;
        if (rw > r->max_rel_weight) r->max_rel_weight = rw;
        if (rf > tol || rp > tol || rw > tol) { if (!r->bad) r->worst_wi = s.wi; ++r->bad; }
    }
    return 0;
}
#endif /* CHECK_IMPLEMENTATION */

/*
   ---------------------------------------------------------------------------
   VERSION HISTORY
   (appear.h's repository) tests/check.h + tests/check.c became this one
        file: the code behind CHECK_IMPLEMENTATION; check_model_make and the
        callback typedefs (check_eval_fn ...) so that C++ builds a model
        without a positional initialiser; private helpers prefixed check__.

   ---------------------------------------------------------------------------
   LICENSE: choose whichever you prefer (the same as appear.h).
   A - MIT License. Copyright (c) 2026 the appear.h authors. Permission is
       hereby granted, free of charge, to any person obtaining a copy of this
       software and associated documentation files (the "Software"), to deal in
       the Software without restriction, including without limitation the
       rights to use, copy, modify, merge, publish, distribute, sublicense,
       and/or sell copies of the Software, and to permit persons to whom the
       Software is furnished to do so, subject to the following conditions:
       The above copyright notice and this permission notice shall be included
       in all copies or substantial portions of the Software. THE SOFTWARE IS
       PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND.
   B - Public Domain (www.unlicense.org). Anyone is free to copy, modify,
       publish, use, compile, sell, or distribute this software, for any
       purpose, commercial or non-commercial, and by any means.
   ---------------------------------------------------------------------------
*/
