/* tests/harness.c - see harness.h */
#include "harness.h"
/* check.h's code lives here: every test binary links harness.c (build/appear-check
   compiles its own copy in examples/appear_check.c) */
#define CHECK_IMPLEMENTATION
#include "check.h"
#ifndef H_NO_IMAGES
#include "../examples/image_io.h"
#endif
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* ------------------------------------------------------------------------ */
/* Runner                                                                    */
/* ------------------------------------------------------------------------ */

static char g_case[256];
static int g_case_open, g_case_failed, g_case_fail_lines;
static int g_passed, g_failed;

static void close_case(void)
{
    if (!g_case_open) return;
    if (g_case_failed) ++g_failed; else ++g_passed;
    g_case_open = 0;
}

void h_case(const char *fmt, ...)
{
    va_list ap;
    close_case();
    va_start(ap, fmt);
    vsnprintf(g_case, sizeof g_case, fmt, ap);
    va_end(ap);
    g_case_open = 1; g_case_failed = 0; g_case_fail_lines = 0;
}

void h_fail(const char *fmt, ...)
{
    va_list ap;
    if (!g_case_open) h_case("(unnamed)");
    g_case_failed = 1;
    if (++g_case_fail_lines > 5) { if (g_case_fail_lines == 6) printf("FAIL %s: (further failures of this case not shown)\n", g_case); return; }
    printf("FAIL %s: ", g_case);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
    fflush(stdout);
}

int h_quick(void)
{
    const char *q = getenv("APPEAR_TEST_QUICK");
    return q && q[0] == '1';
}

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define H_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) && !defined(H_ASAN)
#define H_ASAN 1
#endif
int h_sanitized(void)
{
#ifdef H_ASAN
    return 1;
#else
    return 0;
#endif
}

long h_n(long full)
{
    long n;
    if (!h_quick()) return full;
    n = full / 16;
    return n < 1000 ? (full < 1000 ? full : 1000) : n;
}

static FILE *g_measures;
static void ensure_out_dir(void) { mkdir("tests/out", 0777); }

void h_measure(const char *what, const char *fmt, ...)
{
    va_list ap;
    char buf[512];
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    printf("measure: %s: %s\n", what, buf);
    if (!g_measures) { ensure_out_dir(); g_measures = fopen(h_quick() ? "tests/out/measures_quick.csv" : "tests/out/measures.csv", "w"); }
    if (g_measures) { fprintf(g_measures, "\"%s\",\"%s\"\n", what, buf); fflush(g_measures); }
}

/* ------------------------------------------------------------------------ */
/* Random numbers: splitmix64                                                */
/* ------------------------------------------------------------------------ */

/* APPEAR_TEST_SEED_OFFSET=k (default 0) is mixed into every seed of the run:
   the statistical rows rerun with independent streams (make check with k = 1, 2, 3 ...) */
static uint64_t seed_offset(void)
{
    static int init;
    static uint64_t off;
    if (!init) { const char *e = getenv("APPEAR_TEST_SEED_OFFSET"); off = e ? strtoull(e, 0, 0) : 0; init = 1; }
    return off;
}
static uint64_t mix64(uint64_t z)
{   /* splitmix64's output function: a bijection whose outputs for nearby inputs are unrelated */
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
/* The state is a hash of the seed (and the offset): a state of seed * gamma + c
   made seed s + 1's stream seed s's shifted by one draw, and s + 3's shifted by one
   three-number sample. Hashed, the states of any two seeds are unrelated, and two
   streams share a value only by chance (2^-64 per pair of draws). */
h_rng h_rng_make(uint64_t seed)
{
    h_rng r;
    r.s = mix64(mix64(seed + 0x632BE59BD9B4E019ull) ^ (seed_offset() * 0xD1B54A32D192ED03ull));
    return r;
}
static uint64_t next64(h_rng *r)
{
    return mix64(r->s += 0x9E3779B97F4A7C15ull);
}
double h_rand(h_rng *r) { return (double)(next64(r) >> 11) * (1.0 / 9007199254740992.0); }
float h_randf(h_rng *r) { return (float)(next64(r) >> 40) * (1.0f / 16777216.0f); }
appear_vec3 h_rand_dir(h_rng *r)
{
    double z = 1.0 - 2.0 * h_rand(r), p = 6.283185307179586 * h_rand(r), s = sqrt(fmax(0.0, 1.0 - z * z));
    return appear_vec3_make((float)(s * cos(p)), (float)(s * sin(p)), (float)z);
}
double h_sample_mean(h_sample_bsdf_fn sample, const void *m, appear_vec3 wo, long n, h_rng *r, int c, double *se,
                     double *nondelta)
{
    double s = 0, s2 = 0, k = 0, mean;
    long i;
    for (i = 0; i < n; ++i) {
        appear_bsdf_record q;
        double w = 0;
        float uc = h_randf(r), u1 = h_randf(r), u2 = h_randf(r);
        if (sample(m, wo, uc, u1, u2, &q)) {
            w = q.weight.v[c];
            k += (q.flags & APPEAR_LOBE_SPECULAR) ? 0.0 : 1.0;
        }
        s += w; s2 += w * w;
    }
    mean = s / n;
    *se = sqrt(fmax(0, s2 / n - mean * mean) / n);
    if (nondelta) *nondelta = k / n;
    return mean;
}
double h_sample_mean_grid(h_sample_bsdf_fn sample, const void *m, appear_vec3 wo, int s, int c)
{
    double sum = 0, uc = 0.5;
    int i, j;
    for (i = 0; i < s; ++i)
        for (j = 0; j < s; ++j) {
            appear_bsdf_record q;
            uc += 0.6180339887498949; /* the golden ratio's fractional part */
            uc -= floor(uc);
            if (sample(m, wo, (float)uc, (float)((i + 0.5) / s), (float)((j + 0.5) / s), &q)) sum += q.weight.v[c];
        }
    return sum / ((double)s * s);
}
appear_vec3 h_dir_mu(double mu, double phi)
{
    double s = sqrt(fmax(0.0, 1.0 - mu * mu));
    return appear_vec3_make((float)(s * cos(phi)), (float)(s * sin(phi)), (float)mu);
}
double h_fresnel_dielectric(double c, double eta)
{
    double s2t, ct, rs, rp;
    if (c < 0) { c = -c; eta = 1.0 / eta; }
    s2t = (1 - c * c) / (eta * eta);
    if (s2t >= 1) return 1;
    ct = sqrt(1 - s2t);
    rs = (c - eta * ct) / (c + eta * ct);
    rp = (eta * c - ct) / (eta * c + ct);
    return 0.5 * (rs * rs + rp * rp);
}

/* ------------------------------------------------------------------------ */
/* Adversarial inputs                                                        */
/* ------------------------------------------------------------------------ */

int h_finite(float x) { return isfinite(x) != 0; }

float h_adv_float(h_rng *r)
{
    static const float special[] = {
        0.0f, -0.0f, 1.0f, -1.0f, 1e-45f, -1e-45f, 1e-38f, 1.17549435e-38f, 1e-30f, 1e-7f, -1e-7f,
        0.5f, 2.0f, 1e7f, -1e7f, 1e30f, -1e30f, 3.4e38f, -3.4e38f, 0.99999994f, 1.0000001f };
    uint64_t k = next64(r) % 8;
    if (k == 0) return NAN;
    if (k == 1) return (next64(r) & 1) ? INFINITY : -INFINITY;
    if (k <= 4) return special[next64(r) % (sizeof special / sizeof special[0])];
    if (k == 5) { uint32_t bits = (uint32_t)next64(r); float f; memcpy(&f, &bits, 4); return f; } /* any bit pattern */
    return (float)(4.0 * h_rand(r) - 2.0);
}

float h_adv_u(h_rng *r)
{
    static const float special[] = { 0.0f, -0.0f, 1.0f, 0.99999994f, 1e-45f, 1e-38f, 5.96e-8f, 0.5f, 0.25f, 0.75f };
    uint64_t k = next64(r) % 16;
    if (k < 10) return h_randf(r);
    if (k < 14) return special[next64(r) % (sizeof special / sizeof special[0])];
    return h_adv_float(r);
}

appear_vec3 h_adv_dir(h_rng *r)
{
    uint64_t k = next64(r) % 12;
    appear_vec3 v = h_rand_dir(r);
    double s;
    switch (k) {
    case 0: case 1: case 2: case 3: return v;                       /* ordinary unit */
    case 4: /* grazing: z exactly +-0 or tiny, renormalised in xy */
        {
            static const float zs[] = { 0.0f, -0.0f, 1e-6f, -1e-6f, 1e-4f, -1e-4f, 1e-38f, 1e-45f };
            float z = zs[next64(r) % 8];
            s = sqrt((double)v.x * v.x + (double)v.y * v.y);
            if (s == 0.0) return appear_vec3_make(1.0f, 0.0f, z);
            s = sqrt(1.0 - (double)z * z) / s;
            return appear_vec3_make((float)(v.x * s), (float)(v.y * s), z);
        }
    case 5: /* poles and axes */
        {
            static const float a[][3] = { {0,0,1}, {0,0,-1}, {1,0,0}, {0,1,0}, {-1,0,0}, {0.6f,0,0.8f} };
            const float *p = a[next64(r) % 6];
            return appear_vec3_make(p[0], p[1], p[2]);
        }
    case 6: return appear_scale(v, (float)(0.5 + 2.0 * h_rand(r)));   /* unnormalised */
    case 7: return appear_vec3_make(0.0f, 0.0f, 0.0f);                /* zero */
    case 8: { float x = h_adv_float(r), y = h_adv_float(r), z = h_adv_float(r); return appear_vec3_make(x, y, z); }
    case 9: v.x = NAN; return v;
    case 10: v.z = (next64(r) & 1) ? INFINITY : -INFINITY; return v;
    default: return appear_scale(v, 1.0f + 1e-4f * (float)(h_rand(r) - 0.5)); /* nearly unit */
    }
}

/* ------------------------------------------------------------------------ */
/* Quadrature on the sphere: adaptive Simpson in (z, phi), dw = dz dphi      */
/* ------------------------------------------------------------------------ */

typedef struct { h_dir_fn fn; void *ctx; double ax[3], bx[3], cz[3]; long evals; } quad_ctx;

static void axis_frame(appear_vec3 axis, double bx[3], double by[3], double bz[3])
{
    double n[3], l, sign, a, b;
    n[0] = axis.x; n[1] = axis.y; n[2] = axis.z;
    l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(l > 0.0)) { n[0] = 0; n[1] = 0; n[2] = 1; l = 1; }
    n[0] /= l; n[1] /= l; n[2] /= l;
    sign = n[2] >= 0 ? 1.0 : -1.0;
    a = -1.0 / (sign + n[2]);
    b = n[0] * n[1] * a;
    bx[0] = 1.0 + sign * n[0] * n[0] * a; bx[1] = sign * b; bx[2] = -sign * n[0];
    by[0] = b; by[1] = sign + n[1] * n[1] * a; by[2] = -n[1];
    bz[0] = n[0]; bz[1] = n[1]; bz[2] = n[2];
}

static double qeval(quad_ctx *q, double z, double phi)
{
    double s = sqrt(fmax(0.0, 1.0 - z * z)), c = cos(phi), sn = sin(phi);
    double d[3];
    int i;
    for (i = 0; i < 3; ++i) d[i] = s * c * q->ax[i] + s * sn * q->bx[i] + z * q->cz[i];
    ++q->evals;
    return q->fn(q->ctx, appear_normalize(appear_vec3_make((float)d[0], (float)d[1], (float)d[2])));
}

/* 3x3 tensor Simpson on [z0,z1]x[p0,p1] from 9 values */
static double simpson9(const double v[9], double dz, double dp)
{
    static const double wt[3] = { 1, 4, 1 };
    double s = 0;
    int i, j;
    for (i = 0; i < 3; ++i) for (j = 0; j < 3; ++j) s += wt[i] * wt[j] * v[i * 3 + j];
    return s * dz * dp / 36.0;
}

/* Witnesses: directions where the sampler put a sample, with the pdf there
   (chi2 only; h_integrate_* has none). A rectangle whose nodes all lie below
   the pdf at one of its witnesses has missed a peak (a thin lobe between its
   nodes): it is subdivided whatever its error estimate says. */
typedef struct { double z, phi, pdf; } witness;

/* puts the witnesses whose z (by_phi 0) or phi (by_phi 1) is below m first; returns how many */
static long wpart(witness *w, long n, int by_phi, double m)
{
    long i = 0, j = n;
    while (i < j) {
        if ((by_phi ? w[i].phi : w[i].z) < m) ++i;
        else { witness t = w[i]; w[i] = w[--j]; w[j] = t; }
    }
    return i;
}

/* depth: levels left under the error estimate's control; min_depth: levels that
   are always subdivided (a cell's estimate never comes from the first 5x5 grid
   alone); prev_ok: the parent level's estimate agreed with its own parent's
   within tolerance. A rectangle is accepted when two successive levels agreed,
   past min_depth, and none of its witnesses shows a missed peak; a missed
   peak is refined to MISSED_DEPTH levels below the error estimate's limit. */
#define MISSED_DEPTH 6
static double adapt(quad_ctx *q, double z0, double z1, double p0, double p1, const double f[25], double whole,
                    double tol, int depth, int min_depth, int prev_ok, witness *w, long nw)
{
    double sub[4], total = 0, g[4][25], fmax_node = 0;
    int k, i, j, ok, missed = 0;
    long part[5];
    double dz = z1 - z0, dp = p1 - p0;
    for (k = 0; k < 4; ++k) {
        int oi = (k >> 1) * 2, oj = (k & 1) * 2;
        double v[9];
        for (i = 0; i < 3; ++i) for (j = 0; j < 3; ++j) v[i * 3 + j] = f[(oi + i) * 5 + (oj + j)];
        sub[k] = simpson9(v, dz / 2, dp / 2);
        total += sub[k];
    }
    for (k = 0; k < 25; ++k) fmax_node = fmax(fmax_node, f[k]);
    for (k = 0; k < nw && !missed; ++k) missed = w[k].pdf > 2.0 * fmax_node;
    ok = fabs(total - whole) <= 15.0 * tol;
    if (depth <= -MISSED_DEPTH || (!missed && (depth <= 0 || (ok && prev_ok && min_depth <= 0))))
        return total + (total - whole) / 15.0;
    /* the witnesses of each quarter: k = 2 * (upper half in z) + (upper half in phi) */
    part[0] = 0; part[4] = nw;
    part[2] = wpart(w, nw, 0, z0 + dz / 2);
    part[1] = wpart(w, part[2], 1, p0 + dp / 2);
    part[3] = part[2] + wpart(w + part[2], nw - part[2], 1, p0 + dp / 2);
    /* refine each quarter: build its 5x5 grid (reuse the 3x3 corners) */
    total = 0;
    for (k = 0; k < 4; ++k) {
        int oi = (k >> 1) * 2, oj = (k & 1) * 2;
        double qz0 = z0 + (k >> 1) * dz / 2, qp0 = p0 + (k & 1) * dp / 2;
        for (i = 0; i < 5; ++i) for (j = 0; j < 5; ++j) {
            if ((i & 1) == 0 && (j & 1) == 0) g[k][i * 5 + j] = f[(oi + i / 2) * 5 + (oj + j / 2)];
            else g[k][i * 5 + j] = qeval(q, qz0 + i * dz / 8, qp0 + j * dp / 8);
        }
        total += adapt(q, qz0, qz0 + dz / 2, qp0, qp0 + dp / 2, g[k], sub[k], tol / 2.0, depth - 1, min_depth - 1,
                       ok, w + part[k], part[k + 1] - part[k]);
    }
    return total;
}

static double integrate_rect_w(quad_ctx *q, double z0, double z1, double p0, double p1, double tol, int depth,
                               int min_depth, witness *w, long nw)
{
    double f[25], v[9];
    int i, j;
    for (i = 0; i < 5; ++i) for (j = 0; j < 5; ++j) f[i * 5 + j] = qeval(q, z0 + i * (z1 - z0) / 4, p0 + j * (p1 - p0) / 4);
    for (i = 0; i < 3; ++i) for (j = 0; j < 3; ++j) v[i * 3 + j] = f[(2 * i) * 5 + 2 * j];
    return adapt(q, z0, z1, p0, p1, f, simpson9(v, z1 - z0, p1 - p0), tol, depth, min_depth, 0, w, nw);
}
/* h_integrate_cap's cells: no witnesses, and a first level may be accepted (its
   cells are many and small, 41 bands of 16; two levels everywhere doubled the
   run time of make check) */
static double integrate_rect(quad_ctx *q, double z0, double z1, double p0, double p1, double tol, int depth)
{
    double f[25], v[9];
    int i, j;
    for (i = 0; i < 5; ++i) for (j = 0; j < 5; ++j) f[i * 5 + j] = qeval(q, z0 + i * (z1 - z0) / 4, p0 + j * (p1 - p0) / 4);
    for (i = 0; i < 3; ++i) for (j = 0; j < 3; ++j) v[i * 3 + j] = f[(2 * i) * 5 + 2 * j];
    return adapt(q, z0, z1, p0, p1, f, simpson9(v, z1 - z0, p1 - p0), tol, depth, 0, 1, NULL, 0);
}

static void quad_init(quad_ctx *q, h_dir_fn fn, void *ctx, appear_vec3 axis)
{
    q->fn = fn; q->ctx = ctx; q->evals = 0;
    axis_frame(axis, q->ax, q->bx, q->cz);
}

/* Bands in t = 1 - z that shrink geometrically toward the pole (down to
   2^-40 of the cap height), so a lobe centred on the axis is resolved however
   narrow it is; 16 phi cells per band; adaptive Simpson inside each cell. */
double h_integrate_cap(h_dir_fn fn, void *ctx, appear_vec3 axis, double zmin, double tol)
{
    quad_ctx q;
    const int NB = 40, NP = 16;
    double sum = 0, height = 1.0 - zmin;
    int i, j;
    quad_init(&q, fn, ctx, axis);
    for (i = 0; i <= NB; ++i) {
        double t1 = height * ldexp(1.0, -i), t0 = i == NB ? 0.0 : height * ldexp(1.0, -i - 1);
        for (j = 0; j < NP; ++j)
            sum += integrate_rect(&q, 1.0 - t1, 1.0 - t0, 6.283185307179586 * j / NP,
                                  6.283185307179586 * (j + 1) / NP, tol / ((NB + 1) * NP), 8);
    }
    return sum;
}

/* Two hemispherical caps, about +axis and -axis, each with bands that shrink
   toward its pole: a peak at either pole is resolved. */
double h_integrate_sphere(h_dir_fn fn, void *ctx, appear_vec3 axis, double tol)
{
    if (axis.x == 0 && axis.y == 0 && axis.z == 0) axis = appear_vec3_make(0, 0, 1);
    return h_integrate_cap(fn, ctx, axis, 0.0, tol / 2) + h_integrate_cap(fn, ctx, appear_neg(axis), 0.0, tol / 2);
}

/* ------------------------------------------------------------------------ */
/* Chi-square                                                                */
/* ------------------------------------------------------------------------ */

/* The p-value is tests/check.h's (one incomplete gamma function for both). */
double h_chi2_pvalue(double chi2, double dof) { return check_chi2_pvalue(chi2, dof); }

typedef struct {
    char name[200], where[600];
    double p;
    int nz, np;
    float *obs, *exp_; /* nz*np each, kept for the EXR on failure */
} chi2_record;
static chi2_record *g_chi2;
static int g_nchi2, g_capchi2;

typedef struct { long idx; double e, o; } cell;
static int cell_cmp(const void *a, const void *b)
{
    double x = ((const cell *)a)->e, y = ((const cell *)b)->e;
    return x < y ? -1 : x > y;
}

/* Pearson statistic with the cells of < 5 expected pooled into one; the
   p-value is 0 when samples landed in a region of zero expected count
   beyond what the pooled cell allows. */
static double pooled_chi2(const double *obs, const double *ex, long ncell, double *chi2_out, int *dof_out, int *zero_hit_out)
{
    cell *cells = (cell *)malloc((size_t)ncell * sizeof(cell));
    double chi2 = 0, pool_e = 0, pool_o = 0, p;
    int dof = -1, zero_hit = 0;
    long i;
    for (i = 0; i < ncell; ++i) { cells[i].idx = i; cells[i].e = ex[i]; cells[i].o = obs[i]; }
    qsort(cells, (size_t)ncell, sizeof(cell), cell_cmp);
    for (i = 0; i < ncell; ++i) {
        if (cells[i].e == 0.0 && cells[i].o > 0.0) zero_hit += (int)cells[i].o;
        if (cells[i].e < 5.0) { pool_e += cells[i].e; pool_o += cells[i].o; continue; }
        chi2 += (cells[i].o - cells[i].e) * (cells[i].o - cells[i].e) / cells[i].e;
        ++dof;
    }
    if (pool_e > 0.0) {
        chi2 += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
        ++dof;
    }
    p = h_chi2_pvalue(chi2, dof);
    if (zero_hit > 0 && pool_o > pool_e + 5.0 * sqrt(pool_e + 1.0)) p = 0.0;
    free(cells);
    *chi2_out = chi2; *dof_out = dof; *zero_hit_out = zero_hit;
    return p;
}

/* Keeps a chi2 result for the Sidak decision in h_finish. */
static void record_chi2(const char *name, const char *where, double p, const double *obs, const double *ex, int nz, int np)
{
    chi2_record *rec;
    long i;
    if (g_nchi2 == g_capchi2) {
        g_capchi2 = g_capchi2 ? 2 * g_capchi2 : 64;
        g_chi2 = (chi2_record *)realloc(g_chi2, (size_t)g_capchi2 * sizeof(chi2_record));
    }
    rec = &g_chi2[g_nchi2++];
    snprintf(rec->name, sizeof rec->name, "%s", name);
    snprintf(rec->where, sizeof rec->where, "%s", where);
    rec->p = p; rec->nz = nz; rec->np = np;
    rec->obs = (float *)malloc(sizeof(float) * nz * np);
    rec->exp_ = (float *)malloc(sizeof(float) * nz * np);
    for (i = 0; i < (long)nz * np; ++i) { rec->obs[i] = (float)obs[i]; rec->exp_[i] = (float)ex[i]; }
}

double h_chi2_counts(const char *name, const double *obs, const double *expected, int n)
{
    double chi2, p, tot_o = 0, tot_e = 0;
    int dof, zero_hit, i;
    char where[600];
    p = pooled_chi2(obs, expected, n, &chi2, &dof, &zero_hit);
    for (i = 0; i < n; ++i) { tot_o += obs[i]; tot_e += expected[i]; }
    snprintf(where, sizeof where, "%s: chi2=%.1f dof=%d observed %.0f expected %.1f zero-pdf hits=%d", g_case, chi2, dof, tot_o, tot_e, zero_hit);
    record_chi2(name, where, p, obs, expected, 1, n);
    return p;
}

double h_chi2(const h_chi2_spec *sp)
{
    int nz = sp->n_z ? sp->n_z : 32, np = sp->n_phi ? sp->n_phi : 64;
    long n = h_n(sp->n_samples ? sp->n_samples : 1000000), s, ncell = (long)nz * np + 1, i;
    double zmin = sp->zmin == 0.0 ? -1.0 : sp->zmin;
    appear_vec3 axis = sp->axis;
    double bx[3], by[3], bz[3], mass = 0, chi2 = 0, p;
    double *obs = (double *)calloc((size_t)ncell, sizeof(double));
    double *ex = (double *)calloc((size_t)ncell, sizeof(double));
    h_rng rng = h_rng_make(sp->seed ? sp->seed : 12345);
    quad_ctx q;
    int dof = -1, zero_hit = 0;
    /* the samples in the bins, with the pdf there: the quadrature's witnesses */
    witness *wit = (witness *)malloc((size_t)(n > 0 ? n : 1) * sizeof(witness)), *wsort;
    long *wcell = (long *)malloc((size_t)(n > 0 ? n : 1) * sizeof(long)), *woff, nwit = 0;

    if (axis.x == 0 && axis.y == 0 && axis.z == 0) axis = appear_vec3_make(0, 0, 1);
    axis_frame(axis, bx, by, bz);
    /* histogram of samples; cell nz*np is the rest: outside the cap or failed */
    for (s = 0; s < n; ++s) {
        appear_vec3 w;
        float uc = h_randf(&rng), u1 = h_randf(&rng), u2 = h_randf(&rng);
        long k = ncell - 1;
        if (sp->sample(sp->ctx, uc, u1, u2, &w)) {
            double z = w.x * bz[0] + w.y * bz[1] + w.z * bz[2];
            double x = w.x * bx[0] + w.y * bx[1] + w.z * bx[2];
            double y = w.x * by[0] + w.y * by[1] + w.z * by[2];
            if (z >= zmin) {
                double phi = atan2(y, x);
                int iz = (int)((z - zmin) / (1.0 - zmin) * nz), ip;
                if (phi < 0) phi += 6.283185307179586;
                ip = (int)(phi / 6.283185307179586 * np);
                iz = iz < 0 ? 0 : iz >= nz ? nz - 1 : iz;
                ip = ip < 0 ? 0 : ip >= np ? np - 1 : ip;
                k = (long)iz * np + ip;
                wit[nwit].z = z; wit[nwit].phi = phi; wit[nwit].pdf = sp->pdf(sp->ctx, w);
                wcell[nwit] = k;
                if (wit[nwit].pdf > 0.0) ++nwit;
            }
        }
        obs[k] += 1;
    }
    /* the witnesses by cell (a counting sort) */
    woff = (long *)calloc((size_t)ncell + 1, sizeof(long));
    wsort = (witness *)malloc((size_t)(nwit > 0 ? nwit : 1) * sizeof(witness));
    for (i = 0; i < nwit; ++i) ++woff[wcell[i] + 1];
    for (i = 0; i < ncell; ++i) woff[i + 1] += woff[i];
    for (i = 0; i < nwit; ++i) wsort[woff[wcell[i]]++] = wit[i];
    for (i = ncell; i > 0; --i) woff[i] = woff[i - 1];
    woff[0] = 0;
    /* expected counts by adaptive quadrature of the pdf per cell: at least two
       levels below the cell (17 x 17 nodes), two successive levels agreeing, and
       a peak that a sample found between the nodes refined until the nodes see it */
    quad_init(&q, sp->pdf, sp->ctx, axis);
    for (i = 0; i < (long)nz * np; ++i) {
        int iz = (int)(i / np), ip = (int)(i % np);
        double m = integrate_rect_w(&q, zmin + (1 - zmin) * iz / nz, zmin + (1 - zmin) * (iz + 1) / nz,
                                    6.283185307179586 * ip / np, 6.283185307179586 * (ip + 1) / np, 1e-9, 8, 2,
                                    wsort + woff[i], woff[i + 1] - woff[i]);
        ex[i] = m * n;
        mass += m;
    }
    ex[ncell - 1] = fmax(0.0, 1.0 - mass) * n;
    p = pooled_chi2(obs, ex, ncell, &chi2, &dof, &zero_hit);
    if (!sp->unrecorded) {
        char where[600];
        snprintf(where, sizeof where, "%s: chi2=%.1f dof=%d n=%ld mass=%.6f rest obs=%.0f exp=%.1f zero-pdf hits=%d",
                 g_case, chi2, dof, n, mass, obs[ncell - 1], ex[ncell - 1], zero_hit);
        record_chi2(sp->name, where, p, obs, ex, nz, np);
    }
    free(obs); free(ex); free(wit); free(wcell); free(woff); free(wsort);
    return p;
}


/* ------------------------------------------------------------------------ */
/* Errors                                                                    */
/* ------------------------------------------------------------------------ */

h_err h_err_make(const char *name)
{
    h_err e;
    e.name = name; e.max_rel = e.max_abs = e.at_ref = e.at_got = 0; e.n = 0;
    return e;
}

void h_err_add(h_err *e, double got, double ref, double abs_floor)
{
    double a = fabs(got - ref), r = a / fmax(fabs(ref), abs_floor);
    ++e->n;
    if (a > e->max_abs) e->max_abs = a;
    if (r > e->max_rel) { e->max_rel = r; e->at_ref = ref; e->at_got = got; }
}

void h_err_report(const h_err *e)
{
    h_measure(e->name, "float vs double over %ld values: max rel err %.3g (ref %.9g got %.9g), max abs err %.3g",
              e->n, e->max_rel, e->at_ref, e->at_got, e->max_abs);
}

int h_write_exr(const char *path, int w, int h, int nch, const char *const *names, const float *data)
{
#ifdef H_NO_IMAGES /* make check: compiler and libm only */
    (void)w; (void)h; (void)nch; (void)names; (void)data;
    printf("(no image output in this build: %s not written; make test writes it)\n", path);
    return -1;
#else
    return img_write_exr(path, w, h, nch, names, data);
#endif
}

/* ------------------------------------------------------------------------ */
/* Finish: Sidak-corrected chi2 decisions, then the closing line             */
/* ------------------------------------------------------------------------ */

int h_finish(void)
{
    int i;
    close_case();
    if (g_nchi2 > 0) {
        double alpha = 1.0 - pow(1.0 - 0.01, 1.0 / g_nchi2), pmin = 1.0;
        int nfail = 0;
        for (i = 0; i < g_nchi2; ++i) {
            chi2_record *r = &g_chi2[i];
            if (r->p < pmin) pmin = r->p;
            if (r->p < alpha) {
                char path[320], clean[200];
                const char *names[3] = { "B", "G", "R" };
                float *img = (float *)malloc(sizeof(float) * 3 * r->nz * r->np);
                int k, j = 0;
                for (k = 0; r->name[k] && j < 190; ++k) clean[j++] = (r->name[k] == ' ' || r->name[k] == '/' || r->name[k] == '=') ? '_' : r->name[k];
                clean[j] = 0;
                ensure_out_dir();
                snprintf(path, sizeof path, "tests/out/chi2_%s.exr", clean);
                /* R = observed, G = expected, B = (obs-exp)/sqrt(exp) */
                for (k = 0; k < r->nz * r->np; ++k) {
                    img[3 * k + 2] = r->obs[k];
                    img[3 * k + 1] = r->exp_[k];
                    img[3 * k + 0] = r->exp_[k] > 0 ? (r->obs[k] - r->exp_[k]) / sqrtf(r->exp_[k]) : r->obs[k];
                }
                h_write_exr(path, r->np, r->nz, 3, names, img);
                free(img);
                printf("FAIL chi2 %s: p=%.3g < %.3g (Sidak over %d tests); %s; histograms in %s (R obs, G exp, B residual)\n",
                       r->name, r->p, alpha, g_nchi2, r->where, path);
                ++nfail;
            }
        }
        if (getenv("APPEAR_TEST_CHI2_LIST"))
            for (i = 0; i < g_nchi2; ++i) printf("chi2 p=%.3g %s\n", g_chi2[i].p, g_chi2[i].name);
        h_measure("chi2 suite", "%d chi-square tests, smallest p = %.3g, per-test threshold %.3g (1%% family-wise, Sidak)",
                  g_nchi2, pmin, alpha);
        g_passed += g_nchi2 - nfail;
        g_failed += nfail;
        for (i = 0; i < g_nchi2; ++i) { free(g_chi2[i].obs); free(g_chi2[i].exp_); }
        free(g_chi2);
    }
    if (g_measures) fclose(g_measures);
    printf("%d passed, %d failed\n", g_passed, g_failed);
    return g_failed ? 1 : 0;
}
