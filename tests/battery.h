/* tests/battery.h - the model battery: one function runs a row of a table of
   model instances (tests/test_models.c) through the checks every BSDF and
   phase function of appear.h must pass (the design notes, "How we validate"):

     consistency  sample() agrees with eval() and pdf() at the sampled wi
                  (every channel, relative tol), weight = f |cos| / pdf,
                  wi unit, the lobe flags name the side wi is on
     chi2         sample() against pdf() on equal-area bins (tests/harness.h
                  h_chi2: Sidak-corrected over the run, histograms written on
                  failure); bins about the +z axis, the mirror direction,
                  -wo, wo, a lobe axis, or found from a pilot run that also
                  magnifies a narrow lobe (AUTO); optionally one side only
     pdf          the integral of pdf(wo, .) over the sphere (quadrature) is 1
                  (lossless sampling) or the sampler's success rate
     furnace      the sampler's mean energy weight (tests/check.h
                  check_furnace: transmission x e^2) against 1 (lossless),
                  against the quadrature of f |cos| (lossy: the reference),
                  or bounded by 1; optionally also the quadrature against 1,
                  a uniform-sphere estimate, and the largest weight
     reciprocity  f(wo, wi) = f(wi, wo) on every channel; refraction:
                  n_i^2 f(wo, wi) = n_o^2 f(wi, wo); micro-flakes:
                  sigma(wo) f(wo, wi) = sigma(wi) f(wi, wo); stochastic evals:
                  means of many estimates agree within their errors
     adversarial  NaN, Inf, denormals, +-0, unnormalised and grazing
                  directions, u = 0, 1 or out of range: eval and pdf finite and
                  >= 0, a sample is either good or cleanly failed

   A check is on when its n (or mode) is set. Sample counts are scaled by
   h_n (APPEAR_TEST_QUICK). Each check of a row is one test case named
   "<row>: <check>"; a failure prints the row, the check, wo (and alpha for
   sweeps), the values and the bound. A row stands for several instances
   when it lists alphas (a roughness sweep) and several wo. */
#ifndef APPEAR_TEST_BATTERY_H
#define APPEAR_TEST_BATTERY_H
#include "harness.h"
#include "adapters.h"

#define BT_MAX_WO 10
#define BT_MAX_ALPHA 12

/* where bins and quadrature put their pole */
enum {
    BT_AXIS_Z,        /* +z (the default) */
    BT_AXIS_MIRROR,   /* (-wo.x, -wo.y, wo.z) */
    BT_AXIS_FORWARD,  /* -wo */
    BT_AXIS_BACKWARD, /* wo */
    BT_AXIS_LOBE,     /* micro-flakes: wo mirrored about the flakes' main axis */
    BT_AXIS_AUTO,     /* the mean sampled direction of a pilot run (chi2: magnified when narrow) */
    BT_AXIS_V         /* the row's vector v */
};
enum { BT_ONE = 1, BT_RATE, BT_QUAD, BT_BOUND };       /* pdf and furnace modes */
/* reciprocity pairs: uniform on the sphere; (wo of the row, wi sampled); uniform, both z > 0 */
enum { BT_PAIRS_UNIFORM = 0, BT_PAIRS_SAMPLED = 1, BT_PAIRS_UPPER = 2 };
enum { BT_FLIP_PARITY = 1 };                            /* wo sign pattern of a sweep */
/* chi2, pdf side: wo's side (+1), the other side (-1), both (0), each side separately */
enum { BT_SIDE_EACH = 2 };

typedef struct bt_cons {
    long n;          /* samples per wo */
    double tol;      /* f, pdf, weight: relative */
    int no_f;        /* f not compared with eval (stochastic evals) */
    int pdf_exact;   /* the sample's pdf must equal pdf() bit for bit */
    int unit_weight; /* weight exactly 1 and f == pdf (phase functions sampled exactly) */
    double min_ok;   /* at least this fraction of the samples succeeds */
    int random_wo;   /* a fresh wo uniform on the sphere for every sample (n in all, not per wo) */
    int pdf_estimate; /* the record's pdf and pdf() are independent noisy estimates (layered): not
                         compared; the record's pdf may be 0 (then f must be 0) */
} bt_cons;
typedef struct bt_chi2 {
    long n;          /* samples (before h_n); 0: no chi2 */
    int axis;        /* BT_AXIS_* */
    double cap;      /* bins cover the cap of this half-angle (radians) about the axis; 0: sphere */
    int nz, nphi;    /* bins; 0: 32 x 64 */
    int side;        /* BSDF: +1 only wi on wo's side, -1 only the other, 0 both, BT_SIDE_EACH */
    int quick_every; /* quick mode: only every k-th chi2 of the checks with this set */
    uint64_t seed;   /* the samples' seed (0: derived from the row's) */
} bt_chi2;
typedef struct bt_pdf {
    int mode;        /* BT_ONE: |I - 1| <= tol; BT_RATE: |I - r| <= k sigma + tol, r the rate */
    double tol, quad_tol, k;
    long n;          /* BT_RATE: samples estimating the success rate r */
    int axis, side;  /* the quadrature's pole; one side only (as chi2) */
    int floor;       /* BT_RATE: sigma^2 >= 1/n^2 (the rate's variance floored) */
    int quick_every;
} bt_pdf;
typedef struct bt_fur {
    int mode;        /* BT_ONE: ref 1; BT_QUAD: ref = quadrature of f |cos| (x e^2 across);
                        BT_BOUND: mean <= 1 + k se + abs */
    long n;          /* sampler estimates (0 with BT_QUAD: the quadrature checks alone) */
    double k, abs, rel; /* |mean - ref| <= k se + abs + rel ref */
    double quad_tol; int axis;
    double one_tol;  /* BT_QUAD: also |ref - 1| <= one_tol (lossless by quadrature) */
    double bound_quad; /* BT_QUAD: also ref <= 1 + bound_quad (set: > 0) */
    double max_w;    /* the largest weight <= max_w (set: > 0) */
    double uniform_k; /* a uniform-sphere estimate of the albedo within uniform_k of its se */
    int measure;     /* print a "measure:" line: the largest |E - 1| and |mean - ref| */
    int quick_every;
} bt_fur;
typedef struct bt_rec {
    long n;          /* pairs (BT_PAIRS_SAMPLED: per wo) */
    int pairs;
    double rel, abs; /* |a - b| <= rel min(a, b), or |a - b| <= abs; every channel */
    int refr;        /* transmitted pairs: rel + the float conditioning of the refraction */
    long repeats;    /* stochastic eval: estimates averaged per side, then */
    double z;        /* |ma - mb| <= z se + rel (ma + mb) */
} bt_rec;
typedef struct bt_adv { long n; } bt_adv;

typedef struct bt_row {
    const char *name;
    int family;
    ad_params p;
    int n_wo; float wo[BT_MAX_WO][3];   /* directions, normalised in double */
    int n_cos; float cos[BT_MAX_WO];    /* or cos theta at azimuth phi */
    float phi;
    int flip;                           /* BT_FLIP_PARITY */
    int n_alpha; float alpha[BT_MAX_ALPHA][2]; /* a sweep: one instance per (ax, ay) */
    float v[3];                         /* BT_AXIS_V */
    uint64_t seed;
    bt_cons cons;
    bt_chi2 chi2;
    bt_pdf pdf;
    bt_fur fur;
    bt_rec rec;
    bt_adv adv;
} bt_row;

/* initialiser helpers: WO(x, y, z)...; COS(c...); ALPHAS({ax, ay}...); RGB(r, g, b); SPL(v) */
#define BT_NARGS_F(...) ((int)(sizeof((float[]){ __VA_ARGS__ }) / sizeof(float)))
#define BT_NARGS_V(...) ((int)(sizeof((float[][3]){ __VA_ARGS__ }) / sizeof(float[3])))
#define BT_NARGS_A(...) ((int)(sizeof((float[][2]){ __VA_ARGS__ }) / sizeof(float[2])))
#define WO(...) .wo = { __VA_ARGS__ }, .n_wo = BT_NARGS_V(__VA_ARGS__)
#define COS(...) .cos = { __VA_ARGS__ }, .n_cos = BT_NARGS_F(__VA_ARGS__)
#define ALPHAS(...) .alpha = { __VA_ARGS__ }, .n_alpha = BT_NARGS_A(__VA_ARGS__)
#define RGB(r, g, b) { r, g, b }
#define SPL(v) { v, v, v }

/* The chi2 of BT_AXIS_AUTO for any direction sampler and its pdf (e.g. a microfacet
   normal sampler): bins about the mean sampled direction of a pilot run, the lobe
   magnified when it is narrow; skipped (with a "measure:" line) when the sampler
   almost always fails. quick_every as bt_chi2's. */
void bt_chi2_domain(const char *name, h_sample_fn sample, h_dir_fn pdf, void *ctx, long n, int nz,
                    int nphi, uint64_t seed, int quick_every);
/* Runs every check of the row (each a test case). */
void bt_run(const bt_row *row);
/* bt_run for each of n rows */
void bt_run_table(const bt_row *rows, int n);

#endif
