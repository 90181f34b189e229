/* tests/check.c - see check.h */
#include "check.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CK_PI 3.14159265358979323846
#define CK_2PI 6.28318530717958647692

check_rng check_rng_make(uint64_t seed)
{
    check_rng r;
    r.s = seed * 0x9e3779b97f4a7c15ull + 0x632be59bd9b4e019ull;
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
check_vec3 check_vec3_make(double x, double y, double z) { check_vec3 v; v.x = x; v.y = y; v.z = z; return v; }
check_vec3 check_dir_theta_phi(double theta_deg, double phi_deg)
{
    double t = theta_deg * CK_PI / 180.0, p = phi_deg * CK_PI / 180.0;
    return check_vec3_make(sin(t) * cos(p), sin(t) * sin(p), cos(t));
}
static double dot3(check_vec3 a, check_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static check_vec3 neg3(check_vec3 a) { return check_vec3_make(-a.x, -a.y, -a.z); }
static check_vec3 rand_dir(check_rng *r)
{
    double z = 1.0 - 2.0 * check_rand(r), p = CK_2PI * check_rand(r), s = sqrt(fmax(0.0, 1.0 - z * z));
    return check_vec3_make(s * cos(p), s * sin(p), z);
}
/* e = n(wi side) / n(wo side) for a BSDF with refraction, else 1 */
static double rel_eta(const check_model *m, check_vec3 wo, check_vec3 wi)
{
    double eta = m->eta > 0 ? m->eta : 1.0;
    if (!m->is_bsdf || eta == 1.0 || (wo.z > 0) == (wi.z > 0)) return 1.0;
    return wo.z > 0 ? eta : 1.0 / eta;
}

/* ------------------------------------------------------------------------ */
int check_furnace(const check_model *m, check_vec3 wo, long n, uint64_t seed, check_furnace_result *r)
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
            double e = rel_eta(m, wo, s.wi);
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
static double eval_avg(const check_model *m, check_vec3 a, check_vec3 b, int k, double *se)
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
        check_vec3 wo = rand_dir(&rng), wi = rand_dir(&rng);
        double a, b, sa, sb, e, rel, z = 0, big;
        if (m->is_bsdf && wo.z < 0 && (i & 2)) wo.z = -wo.z; /* most pairs from outside */
        if ((i & 1) && m->sample) { /* half the pairs in the lobe */
            check_sample s;
            memset(&s, 0, sizeof s);
            if (!m->sample(m->ctx, wo, check_rand(&rng), check_rand(&rng), check_rand(&rng), &s) || s.delta) continue;
            wi = s.wi;
        }
        ++r->pairs;
        a = eval_avg(m, wo, wi, repeats, &sa);
        b = eval_avg(m, wi, wo, repeats, &sb);
        e = rel_eta(m, wo, wi);      /* n_i / n_o: n_i^2 f(wo,wi) = n_o^2 f(wi,wo) */
        a *= e * e; sa *= e * e;
        if (m->sigma) { double so = m->sigma(m->ctx, wo), si = m->sigma(m->ctx, wi); a *= so; sa *= so; b *= si; sb *= si; }
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
static double gamma_q(double a, double x)
{
    double gln = lgamma(a);
    int i;
    if (x <= 0) return 1.0;
    if (x < a + 1.0) {
        double ap = a, sum = 1.0 / a, del = sum;
        for (i = 0; i < 10000; ++i) { ap += 1; del *= x / ap; sum += del; if (fabs(del) < fabs(sum) * 1e-15) break; }
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
double check_chi2_pvalue(double chi2, double dof) { return dof > 0 ? gamma_q(dof / 2.0, chi2 / 2.0) : 1.0; }

typedef struct { const check_model *m; check_vec3 wo, bx, by, bz; long evals; } quad_ctx;
static double quad_pdf(quad_ctx *q, double z, double phi)
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
static double gl4(quad_ctx *q, double z0, double z1, double p0, double p1)
{
    static const double x[4] = { -0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526 };
    static const double w[4] = { 0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538 };
    double zm = 0.5 * (z0 + z1), zh = 0.5 * (z1 - z0), pm = 0.5 * (p0 + p1), ph = 0.5 * (p1 - p0), s = 0;
    int i, j;
    for (i = 0; i < 4; ++i)
        for (j = 0; j < 4; ++j) s += w[i] * w[j] * quad_pdf(q, zm + zh * x[i], pm + ph * x[j]);
    return s * zh * ph;
}
static double adapt(quad_ctx *q, double z0, double z1, double p0, double p1, double whole, double tol, int depth)
{
    double zm = 0.5 * (z0 + z1), pm = 0.5 * (p0 + p1);
    double a = gl4(q, z0, zm, p0, pm), b = gl4(q, zm, z1, p0, pm), c = gl4(q, z0, zm, pm, p1), d = gl4(q, zm, z1, pm, p1);
    double sum = a + b + c + d;
    if (depth <= 0 || fabs(sum - whole) <= tol) return sum;
    return adapt(q, z0, zm, p0, pm, a, tol / 2, depth - 1) + adapt(q, zm, z1, p0, pm, b, tol / 2, depth - 1) +
           adapt(q, z0, zm, pm, p1, c, tol / 2, depth - 1) + adapt(q, zm, z1, pm, p1, d, tol / 2, depth - 1);
}
static void basis(check_vec3 n, check_vec3 *b1, check_vec3 *b2)
{   /* Duff et al. 2017 */
    double sign = n.z >= 0 ? 1.0 : -1.0, a = -1.0 / (sign + n.z), b = n.x * n.y * a;
    *b1 = check_vec3_make(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    *b2 = check_vec3_make(b, sign + n.y * n.y * a, -n.y);
}
typedef struct { double e, o; } cellv;
static int cell_cmp(const void *a, const void *b)
{
    double x = ((const cellv *)a)->e, y = ((const cellv *)b)->e;
    return x < y ? -1 : x > y;
}
int check_chi2(const check_model *m, check_vec3 wo, const check_chi2_opts *o, check_chi2_result *r)
{
    check_chi2_opts op;
    quad_ctx q;
    check_rng rng;
    long i, ncell, n;
    double zmin, len, mass = 0, chi2 = 0, pe = 0, po = 0;
    int nz, np, dof = -1;
    cellv *cells;
    memset(r, 0, sizeof *r);
    if (!m->sample || !m->pdf) return -1;
    if (o) op = *o; else memset(&op, 0, sizeof op);
    nz = op.n_z > 0 ? op.n_z : 32; np = op.n_phi > 0 ? op.n_phi : 64;
    n = op.n_samples > 0 ? op.n_samples : 200000;
    zmin = op.zmin == 0.0 ? -1.0 : op.zmin;
    len = sqrt(dot3(op.axis, op.axis));
    if (len == 0) { op.axis = m->is_bsdf ? check_vec3_make(0, 0, 1) : neg3(wo); len = 1; }
    q.m = m; q.wo = wo; q.evals = 0;
    q.bz = check_vec3_make(op.axis.x / len, op.axis.y / len, op.axis.z / len);
    basis(q.bz, &q.bx, &q.by);
    ncell = (long)nz * np;
    r->n_z = nz; r->n_phi = np; r->n = n;
    r->observed = (double *)calloc((size_t)ncell, sizeof(double));
    r->expected = (double *)calloc((size_t)ncell, sizeof(double));
    cells = (cellv *)malloc((size_t)(ncell + 1) * sizeof(cellv));
    if (!r->observed || !r->expected || !cells) { free(cells); check_chi2_free(r); return -1; }
    rng = check_rng_make(op.seed ? op.seed : 1);
    for (i = 0; i < n; ++i) {
        check_sample s;
        double uc = check_rand(&rng), u1 = check_rand(&rng), u2 = check_rand(&rng);
        memset(&s, 0, sizeof s);
        if (m->sample(m->ctx, wo, uc, u1, u2, &s) && !s.delta) {
            double z = dot3(s.wi, q.bz), phi = atan2(dot3(s.wi, q.by), dot3(s.wi, q.bx));
            if (z >= zmin) {
                int iz = (int)((z - zmin) / (1.0 - zmin) * nz), ip;
                if (phi < 0) phi += CK_2PI;
                ip = (int)(phi / CK_2PI * np);
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
        double p0 = CK_2PI * ip / np, p1 = CK_2PI * (ip + 1) / np;
        double v = 0, tol = 0.02 / n;   /* 0.02 expected samples per bin */
        if (iz == nz - 1) {   /* the band at the pole: geometric pieces toward z = 1 resolve a peak there */
            double a = z0, h = 1.0 - z0, piece;
            while (h > 1e-12) {
                double b = 1.0 - 0.25 * h;
                v += piece = adapt(&q, a, b, p0, p1, gl4(&q, a, b, p0, p1), tol / 20, 6);
                a = b; h *= 0.25;
                /* the rest is below pdf(pole) x its area when the pdf peaks at the pole; else go on */
                if (h < 1e-3 && piece < tol * 1e-3 && quad_pdf(&q, 1.0, p0) * h * (p1 - p0) < tol * 1e-3) break;
            }
            v += adapt(&q, a, 1.0, p0, p1, gl4(&q, a, 1.0, p0, p1), tol / 20, 6);
        } else v = adapt(&q, z0, z1, p0, p1, gl4(&q, z0, z1, p0, p1), tol, 6);
        r->expected[i] = v * n;
        mass += v;
        if (v == 0 && r->observed[i] > 0) r->zero_pdf_hits += (long)r->observed[i];
    }
    r->pdf_mass = mass;
    r->rest_expected = fmax(0.0, 1.0 - mass) * n;
    for (i = 0; i < ncell; ++i) { cells[i].e = r->expected[i]; cells[i].o = r->observed[i]; }
    cells[ncell].e = r->rest_expected; cells[ncell].o = (double)r->rest_observed;
    qsort(cells, (size_t)ncell + 1, sizeof(cellv), cell_cmp);
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
static double relerr(double got, double ref)
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
        if (!m->sample(m->ctx, wo, check_rand(&rng), check_rand(&rng), check_rand(&rng), &s) || s.delta) continue;
        ++r->checked;
        c = m->is_bsdf ? fabs(s.wi.z) : 1.0;
        wexp = s.pdf > 0 ? s.f * c / s.pdf : 0.0;
        rw = relerr(s.weight, wexp);
        if (m->eval && !m->eval_is_estimate) { ef = m->eval(m->ctx, wo, s.wi); rf = relerr(s.f, ef); }
        if (m->pdf) { ep = m->pdf(m->ctx, wo, s.wi); rp = relerr(s.pdf, ep); }
        if (fabs(dot3(s.wi, s.wi) - 1.0) > 1e-4 || !(s.pdf > 0)) rw = 1.0;
        if (rf > r->max_rel_f) r->max_rel_f = rf;
        if (rp > r->max_rel_pdf) r->max_rel_pdf = rp;
        if (rw > r->max_rel_weight) r->max_rel_weight = rw;
        if (rf > tol || rp > tol || rw > tol) { if (!r->bad) r->worst_wi = s.wi; ++r->bad; }
    }
    return 0;
}
