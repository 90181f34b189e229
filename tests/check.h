/* tests/check.h - checks for any BSDF or phase function, yours or appear.h's.

   Four checks that a renderer's own test program can run on its own
   materials through three callbacks (eval, pdf, sample) and a void*
   context. C99, libm only (no appear.h, no image library): compile
   tests/check.c into your test binary. build/appear-check is built on it.

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

   Example (a renderer's Lambertian, albedo 0.8):

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
       check_model m = { "my lambert", 0, 1, 1.0, 0, ev, pd, sa, 0 };
       check_vec3 wo = { 0.6, 0, 0.8 };
       check_furnace_result fr;  check_chi2_result cr;
       check_furnace(&m, wo, 100000, 1, &fr);        // fr.albedo 0.8, fr.se 0
       check_chi2(&m, wo, 0, &cr);                   // cr.p > 0.01: pass
       printf("albedo %.4f +- %.4f  chi2 p %.3f\n", fr.albedo, fr.se, cr.p);
       check_chi2_free(&cr);

   Every function returns 0 on success and -1 when it cannot run (no
   sampler, no pdf where one is needed, out of memory); the verdict is in
   the result (compare to your tolerance: e.g. |albedo - 1| <= 4 se for a
   lossless model, chi2 p above your significance after a Sidak or
   Bonferroni correction over your whole suite).
*/
#ifndef APPEAR_CHECK_H
#define APPEAR_CHECK_H
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

typedef struct check_model {
    const char *name;
    void *ctx;              /* passed to every callback */
    int is_bsdf;            /* 1: BSDF (|wi.z| weighting, sides); 0: phase function */
    double eta;             /* BSDF with refraction: n_inside / n_outside (wo.z < 0 is inside); 1 or 0: none */
    int eval_is_estimate;   /* 1: eval returns a noisy unbiased estimate (random walks): reciprocity averages */
    double (*eval)(void *ctx, check_vec3 wo, check_vec3 wi);              /* f, no cosine */
    double (*pdf)(void *ctx, check_vec3 wo, check_vec3 wi);               /* NULL: none */
    int (*sample)(void *ctx, check_vec3 wo, double uc, double u1, double u2, check_sample *s); /* 1: ok */
    double (*sigma)(void *ctx, check_vec3 w); /* NULL, or the projected area of a micro-flake medium */
} check_model;

/* ---- furnace ---- */
typedef struct check_furnace_result {
    double albedo, se;          /* mean energy weight and its standard error */
    double reflect, transmit;   /* the shares of wi on wo's side / the other side */
    double delta;               /* share carried by delta lobes */
    double failed;              /* fraction of samples that failed */
    double max_weight;          /* largest single weight (a heavy tail shows here) */
    long n;
} check_furnace_result;
int check_furnace(const check_model *m, check_vec3 wo, long n, uint64_t seed, check_furnace_result *r);

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
int check_reciprocity(const check_model *m, long n_pairs, double floor, int repeats, uint64_t seed,
                      check_reciprocity_result *r);

/* ---- chi-square ---- */
typedef struct check_chi2_opts {
    int n_z, n_phi;         /* bins; 0 = 32 x 64 */
    long n_samples;         /* 0 = 200000 */
    check_vec3 axis;        /* pole of the bins; zero = +z for BSDFs, -wo for phase functions */
    double zmin;            /* bins cover cos(angle to axis) in [zmin, 1]; 0 = whole sphere (-1) */
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
    double *observed, *expected; /* n_z * n_phi each, row = z band (band 0 at zmin); free with check_chi2_free */
} check_chi2_result;
int check_chi2(const check_model *m, check_vec3 wo, const check_chi2_opts *o, check_chi2_result *r);
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
#endif
