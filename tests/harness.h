/* tests/harness.h - the validation harness every model's tests reuse.
 *
 * Runner:   one test case = h_case("name ..."); checks inside it call h_fail
 *           (via H_CHECK) with the values that failed; h_finish() prints
 *           "N passed, M failed". Each suite is a function
 *           `void suite_<name>(void)` in tests/test_<name>.c; the Makefile
 *           collects them (grep '^void suite_').
 * Chi2:     h_chi2() tests a direction sampler against its pdf on equal-area
 *           (phi, cos theta) bins around any axis, optionally restricted to a
 *           cap that resolves a narrow lobe; expected counts by adaptive
 *           quadrature in double; cells under 5 expected pooled; p-value
 *           from the regularised incomplete gamma function. The decision is
 *           taken in h_finish() with the Sidak correction over every chi2
 *           test of the run (1% family-wise); failures write the observed
 *           and expected histograms to tests/out/chi2_<name>.exr.
 * Quadrature: h_integrate_sphere() integrates a function of direction.
 * Adversarial inputs: h_adv_float/h_adv_u/h_adv_dir.
 * Errors:   h_err accumulates float-vs-double error and h_err_report prints
 *           a "measure:" line and appends to tests/out/measures.csv.
 */
#ifndef APPEAR_TEST_HARNESS_H
#define APPEAR_TEST_HARNESS_H
#include "../appear.h"
#include <stdint.h>
#include <stdio.h>

/* ---- runner ---- */
void h_case(const char *fmt, ...);            /* starts a test case */
void h_fail(const char *fmt, ...);            /* marks the current case failed, prints a line */
#define H_CHECK(cond, ...) do { if (!(cond)) h_fail(__VA_ARGS__); } while (0)
int  h_finish(void);                          /* returns the process exit code */
int  h_quick(void);                           /* 1 under APPEAR_TEST_QUICK=1 (sanitizer runs) */
long h_n(long full);                          /* full, or full/16 (>= 1000) in quick mode */
int  h_sanitized(void);                       /* 1 in a build with AddressSanitizer (a third of the
                                                 slowest grids there: the code paths, not the noise) */
void h_measure(const char *what, const char *fmt, ...); /* prints "measure: what: ..." and logs CSV */

/* ---- random numbers (splitmix64 / xoshiro-like, deterministic) ---- */
typedef struct { uint64_t s; } h_rng;
h_rng  h_rng_make(uint64_t seed);
double h_rand(h_rng *r);                      /* uniform in [0,1), 53 bits */
float  h_randf(h_rng *r);                     /* uniform in [0,1), float */
appear_vec3 h_rand_dir(h_rng *r);             /* uniform on the sphere */
/* the unit direction of cosine mu (in [-1, 1]) at azimuth phi, computed in double */
appear_vec3 h_dir_mu(double mu, double phi);
/* a BSDF's sampler behind one shape (m: the model) */
typedef int (*h_sample_bsdf_fn)(const void *m, appear_vec3 wo, float uc, float u1, float u2, appear_bsdf_record *s);
/* the mean sample weight of channel c over n samples (uc, u1, u2 drawn in this order; a failed
   sample weighs 0): the directional albedo; *se its standard error, *nondelta (may be NULL) the
   rate of successful samples off the delta lobes */
double h_sample_mean(h_sample_bsdf_fn sample, const void *m, appear_vec3 wo, long n, h_rng *r, int c, double *se,
                     double *nondelta);
/* the same mean over an s x s grid of cell centres in (u1, u2), uc from the golden ratio's
   additive recurrence (the lobe choice, equidistributed): deterministic, and where the weight
   is smooth over the square its error falls much faster than a random mean's se (OpenPBR's
   strong-anisotropy glass: within 3e-4 of 800^2 at 400^2) */
double h_sample_mean_grid(h_sample_bsdf_fn sample, const void *m, appear_vec3 wo, int s, int c);
/* unpolarised dielectric Fresnel in double: cosine c to the normal (c < 0: seen from the other
   side, eta inverted), eta = n_t / n_i; total internal reflection: 1 */
double h_fresnel_dielectric(double c, double eta);

/* ---- adversarial inputs for the stability sweep ---- */
float       h_adv_float(h_rng *r);            /* NaN, +-Inf, denormals, +-0, huge, tiny, ordinary */
float       h_adv_u(h_rng *r);                /* mostly [0,1), plus 0, 1, 1-ulp, NaN, -0, out of range */
appear_vec3 h_adv_dir(h_rng *r);              /* unit (incl. grazing z = +-0, 1e-6), unnormalised, zero, NaN, Inf */
int         h_finite(float x);
#define H_OK_VALUE(x) (h_finite(x) && (x) >= 0.0f)

/* ---- double-precision directions on the sphere ---- */
typedef double (*h_dir_fn)(void *ctx, appear_vec3 w);
/* Integral of fn over the whole sphere, adaptive, absolute tolerance tol,
   as two hemispheres about +axis and -axis whose (phi, cos theta) bands
   shrink geometrically toward the poles: put a narrow peak on +-axis. */
double h_integrate_sphere(h_dir_fn fn, void *ctx, appear_vec3 axis, double tol);
/* Integral over the cap cos(angle to axis) in [zmin, 1]. */
double h_integrate_cap(h_dir_fn fn, void *ctx, appear_vec3 axis, double zmin, double tol);

/* ---- chi-square goodness of fit ---- */
/* sample: 1 and a unit *wi on success, 0 when the sampler failed or took a
   delta lobe that the pdf does not describe (counted in the "rest" bin). */
typedef int (*h_sample_fn)(void *ctx, float uc, float u1, float u2, appear_vec3 *wi);
typedef struct {
    const char *name;          /* used in messages and the EXR file name */
    h_sample_fn sample;
    h_dir_fn pdf;              /* solid-angle pdf in double */
    void *ctx;
    appear_vec3 axis;          /* pole of the bins; zero vector = +z */
    double zmin;               /* bins cover cos(angle to axis) in [zmin, 1]; 0 = -1 (sphere) */
    int n_z, n_phi;            /* bins; 0 = 32 x 64 */
    long n_samples;            /* 0 = 1,000,000 (scaled by h_n) */
    uint64_t seed;
    int unrecorded;            /* 1: return the p-value only (harness self-tests) */
} h_chi2_spec;
/* Runs the test, records its p-value, returns the p-value (the pass/fail
   decision is taken in h_finish with the Sidak correction). */
double h_chi2(const h_chi2_spec *spec);
double h_chi2_pvalue(double chi2, double dof); /* Q(dof/2, chi2/2) */
/* Any binned test (1D distances, tables): observed and expected counts of n
   bins that partition every outcome (their totals should agree); cells under
   5 expected are pooled; the p-value joins the Sidak family like h_chi2's. */
double h_chi2_counts(const char *name, const double *obs, const double *expected, int n);

/* (the checks every BSDF and phase function passes, through one adapter per
   family: tests/battery.h and tests/adapters.h) */

/* ---- float vs double error accounting ---- */
typedef struct { const char *name; double max_rel, max_abs; double at_ref, at_got; long n; } h_err;
h_err h_err_make(const char *name);
void h_err_add(h_err *e, double got, double ref, double abs_floor);
void h_err_report(const h_err *e);

/* ---- EXR output (OpenEXRCore) ---- */
/* data: w*h*nch floats, interleaved per pixel; names: nch channel names. */
int h_write_exr(const char *path, int w, int h, int nch, const char *const *names, const float *data);

#endif
