/* tests/gen/fit_sheen.c - the table of appear.h's LTC sheen (SECTION sheen; its data sits in
   SECTION tables between BEGIN / END GENERATED SHEEN TABLE), from the reference walk of
   tests/gen/gen_sheen.c (tests/gen/sheen_ref.h):

       cc -O2 -I. tests/gen/fit_sheen.c -o build/fit_sheen -lm && ./build/fit_sheen

   prints the block to paste between the BEGIN / END lines of appear.h (see table() below for
   the nodes it fills). Deterministic. The committed table: from the sheen_ref.h of
   ./build/gen_sheen 0.003 20220801 (32 x 40 nodes; see gen_sheen.c).

       ./build/fit_sheen rational

   runs the closed-form attempt that the table replaced and prints its coefficients and
   errors (mean albedo error 4-6 %, max 20-100 % at low roughness and grazing view, or poles
   inside the domain, depending on the degrees: -DEPX=.. -DEPR=.. -DEQX=.. -DEQR=..):

   Three functions of mu = cos(theta_o) and the roughness r, each a product of a fixed factor
   and a ratio of bivariate polynomials P / Q (Q's constant term 1):
       E(mu, r) = P_E / Q_E                               the directional albedo
       a(mu, r) = r P_a / Q_a                             the LTC's scale (a -> 0 with r)
       b(mu, r) = sqrt(1 - mu^2) P_b / Q_b                its shear (0 at normal view: the lobe
                                                          is round there, and b is odd in theta)
   Fitted by weighted least squares, first linearised (Sanathanan-Koerner: P - y Q, reweighted
   by 1 / Q of the previous pass), then Levenberg-Marquardt on the true weighted residual.
   Weights: E, the relative error where E > 0.05, the error / 0.05 below (so the fit is not
   bent toward the noise of nodes that hardly reflect); a and b, nodes with E >= 0.01 and a
   walk fit (nrefl >= 1000), a relative (and b absolute) weighted by min(1, E / 0.05), the
   importance of the lobe.

   Reported: the albedo error on the whole grid (max and mean of |E_fit - E_ref| / E_ref where
   E_ref > 0.05; max absolute elsewhere), and the lobe error: the total variation distance
   between the closed-form LTC and the node's own LTC fit (by quadrature), beside that node's
   own misfit against the walk's histogram (TV - TV0 of sheen_ref.h). Also the forms' sanity
   on a 257 x 257 grid over mu, r in (0, 1]: Q > 0, a > 0, 0 <= E < 1, |b| bounded. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "sheen_ref.h"
#ifndef EPX
#define EPX 2
#define EPR 2
#define EQX 3
#define EQR 2
#define AX 2
#define AR 2
#define BPX 1
#define BQX 2
#define BR 2
#endif

#define MAXP 40
typedef struct {
    int np, nq;           /* numerator terms, denominator terms (without its constant 1) */
    int pi[MAXP], pj[MAXP], qi[MAXP], qj[MAXP]; /* monomials mu^i r^j */
    double c[2 * MAXP];   /* P's then Q's coefficients */
    int pre;              /* 0: 1, 1: r, 2: sqrt(1 - mu^2) */
    int qpos;             /* Q's coefficients are squares of the parameters (Q >= 1: no pole) */
    int ppos;             /* P's too (P >= 0) */
    int expo;             /* the value is exp(-pre P / Q) */
} form;
static int g_xvar = 1;    /* monomials in (x = mu / r, r) */

static double mono(double mu, double r, int i, int j)
{
    double x = g_xvar ? mu / r : mu;
    return pow(x, i) * pow(r, j);
}
static double pre_of(const form *f, double mu, double r)
{
    return f->pre == 1 ? r : (f->pre == 2 ? sqrt(fmax(0.0, 1.0 - mu * mu)) : 1.0);
}
static double eval_pq(const form *f, const double *c, double mu, double r, double *q)
{
    double p = 0.0, qq = 1.0;
    int k;
    for (k = 0; k < f->np; ++k) p += (f->ppos ? c[k] * c[k] : c[k]) * mono(mu, r, f->pi[k], f->pj[k]);
    for (k = 0; k < f->nq; ++k) {
        double cq = f->qpos ? c[f->np + k] * c[f->np + k] : c[f->np + k];
        qq += cq * mono(mu, r, f->qi[k], f->qj[k]);
    }
    if (q) *q = qq;
    return f->expo ? exp(-pre_of(f, mu, r) * p / qq) : pre_of(f, mu, r) * p / qq;
}
static double eval_form(const form *f, double mu, double r) { return eval_pq(f, f->c, mu, r, 0); }

/* terms mu^i r^j with i <= di, j <= dj, i + j <= dt */
static int terms(int *ti, int *tj, int di, int dj, int dt, int skip00)
{
    int i, j, n = 0;
    for (i = 0; i <= di; ++i)
        for (j = 0; j <= dj; ++j)
            if (i + j <= dt && !(skip00 && i == 0 && j == 0)) { ti[n] = i; tj[n] = j; ++n; }
    return n;
}

/* the data: nodes with weight > 0 */
#define ND (SHEEN_REF_NR * SHEEN_REF_NMU)
static double dmu[ND], dr[ND], dy[ND], dw[ND];
static int nd;

/* dense least squares: minimise |A x - y|^2, A n x m (n rows), by normal equations in long
   double with a tiny ridge (m <= 2 MAXP) */
static int lsq(int n, int m, const double *A, const double *y, double lambda, double *x)
{
    static long double N[2 * MAXP][2 * MAXP + 1];
    int i, j, k;
    for (i = 0; i < m; ++i)
        for (j = 0; j <= m; ++j) N[i][j] = 0.0L;
    for (k = 0; k < n; ++k)
        for (i = 0; i < m; ++i) {
            long double ai = A[k * m + i];
            for (j = 0; j < m; ++j) N[i][j] += ai * A[k * m + j];
            N[i][m] += ai * y[k];
        }
    for (i = 0; i < m; ++i) N[i][i] += lambda * (N[i][i] + 1e-30L);
    for (i = 0; i < m; ++i) { /* Gauss-Jordan with partial pivoting */
        int p = i;
        long double t;
        for (k = i + 1; k < m; ++k) if (fabsl(N[k][i]) > fabsl(N[p][i])) p = k;
        if (N[p][i] == 0.0L) return 0;
        for (j = 0; j <= m; ++j) { t = N[i][j]; N[i][j] = N[p][j]; N[p][j] = t; }
        for (k = 0; k < m; ++k) {
            long double f;
            if (k == i) continue;
            f = N[k][i] / N[i][i];
            for (j = i; j <= m; ++j) N[k][j] -= f * N[i][j];
        }
    }
    for (i = 0; i < m; ++i) x[i] = (double)(N[i][m] / N[i][i]);
    return 1;
}

static double cost(const form *f, const double *c)
{
    double s = 0.0, q;
    int k;
    for (k = 0; k < nd; ++k) {
        double v = eval_pq(f, c, dmu[k], dr[k], &q), e = dw[k] * (v - dy[k]);
        if (!(q > 0.0)) e += 1e3 * (1.0 - q); /* keep Q positive on the nodes */
        s += e * e;
    }
    return s;
}

static void fit(form *f)
{
    static double A[ND * 2 * MAXP], y[ND], J[ND * 2 * MAXP], res[ND];
    int m = f->np + f->nq, it, k, i;
    double qprev[ND], lambda = 1e-3, c0;
    int qpos = f->qpos;
    for (k = 0; k < nd; ++k) qprev[k] = 1.0;
    memset(f->c, 0, sizeof f->c);
    f->qpos = 0;
    /* Sanathanan-Koerner: w (pre P - y (Q - 1)) / Qprev = w y / Qprev */
    for (it = 0; it < 12; ++it) {
        for (k = 0; k < nd; ++k) {
            double mu = dmu[k], r = dr[k], pr = pre_of(f, mu, r), w = dw[k] / qprev[k];
            for (i = 0; i < f->np; ++i) A[k * m + i] = w * pr * mono(mu, r, f->pi[i], f->pj[i]);
            for (i = 0; i < f->nq; ++i) A[k * m + f->np + i] = -w * dy[k] * mono(mu, r, f->qi[i], f->qj[i]);
            y[k] = w * dy[k];
        }
        if (!lsq(nd, m, A, y, 1e-12, f->c)) { fprintf(stderr, "singular\n"); exit(1); }
        for (k = 0; k < nd; ++k) {
            double q;
            eval_pq(f, f->c, dmu[k], dr[k], &q);
            qprev[k] = fabs(q) > 0.05 ? fabs(q) : 0.05;
        }
    }
    /* Levenberg-Marquardt (Q's coefficients as squares when qpos: from SK's, negatives 0) */
    f->qpos = qpos;
    if (qpos) { /* SK's Q may have negative terms: start from a flat P / Q instead */
        double mean = 0.0;
        for (k = 0; k < nd; ++k) mean += dy[k] / nd;
        for (i = 0; i < f->np; ++i) f->c[i] = f->ppos ? 0.3 : 0.0;
        f->c[0] = f->expo ? (f->ppos ? sqrt(-log(mean)) : -log(mean)) : mean;
        for (i = 0; i < f->nq; ++i) f->c[f->np + i] = 0.3;
    }
    c0 = cost(f, f->c);
    for (it = 0; it < 300; ++it) {
        double cn[2 * MAXP], d[2 * MAXP], cnew;
        for (k = 0; k < nd; ++k) {
            double v = eval_pq(f, f->c, dmu[k], dr[k], 0);
            res[k] = -dw[k] * (v - dy[k]);
            for (i = 0; i < m; ++i) {
                double h = 1e-7 * (fabs(f->c[i]) + 1e-3), s = f->c[i], v2;
                f->c[i] = s + h;
                v2 = eval_pq(f, f->c, dmu[k], dr[k], 0);
                f->c[i] = s;
                J[k * m + i] = dw[k] * (v2 - v) / h;
            }
        }
        for (;;) {
            if (!lsq(nd, m, J, res, lambda, d)) { lambda *= 10; continue; }
            for (i = 0; i < m; ++i) cn[i] = f->c[i] + d[i];
            cnew = cost(f, cn);
            if (cnew < c0) { memcpy(f->c, cn, sizeof(double) * (size_t)m); lambda = fmax(lambda / 3, 1e-12);
                             break; }
            lambda *= 4;
            if (lambda > 1e8) break;
        }
        if (lambda > 1e8 || fabs(c0 - cnew) < 1e-13 * c0) { if (cnew < c0) c0 = cnew; break; }
        c0 = cnew;
    }
}

static void print_form(const char *name, const form *f)
{
    int k;
    printf("%s = %s P / Q,\n  P:", name, f->pre == 1 ? "r" : (f->pre == 2 ? "sqrt(1 - mu^2)" : "1 *"));
    for (k = 0; k < f->np; ++k) printf(" %+.9g x^%d r^%d", f->ppos ? f->c[k] * f->c[k] : f->c[k], f->pi[k], f->pj[k]);
    printf("\n  Q: 1");
    for (k = 0; k < f->nq; ++k)
        printf(" %+.9g x^%d r^%d", f->qpos ? f->c[f->np + k] * f->c[f->np + k] : f->c[f->np + k], f->qi[k],
               f->qj[k]);
    printf("\n");
}

/* LTC density in the frame of wo */
static double ltc_D(double a, double b, double x, double y, double z)
{
    double px = a * x + b * z, py = a * y, l2 = px * px + py * py + z * z;
    return z > 0.0 ? a * a * z / (M_PI * l2 * l2) : 0.0;
}
/* total variation distance between two LTCs, by midpoint quadrature in (cos^(1/2), phi): the
   lobes near the horizon are resolved */
static double ltc_tv(double a1, double b1, double a2, double b2)
{
    const int nt = 400, np = 200;
    double s = 0.0;
    int i, j;
    for (i = 0; i < nt; ++i) {
        double t = (i + 0.5) / nt, c = t * t, st = sqrt(1.0 - c * c), dc = 2.0 * t / nt;
        for (j = 0; j < np; ++j) {
            double ph = (j + 0.5) * M_PI / np, x = st * cos(ph), y = st * sin(ph);
            s += fabs(ltc_D(a1, b1, x, y, c) - ltc_D(a2, b2, x, y, c)) * dc * (M_PI / np) * 2.0;
        }
    }
    return 0.5 * s;
}

static int rational(void);
static void table(void);
int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "rational") == 0) return rational();
    table();
    return 0;
}

/* The table appear.h holds: per node [r][mu] of sheen_ref.h, (E^(1/4), a, b) (appear.h
   interpolates E^(1/4) in (mu, 1 / r), a and b in (mu, r)). Nodes without a walk fit of the
   lobe (fewer than 1000 reflected paths: E below about 0.01 at the walk's 1e5 paths) take (a, b) of the nearest
   fitted node of their row toward grazing view, or, where a row has none (r = 0.01), of the
   next row with a scaled by r / r_next (a -> 0 with r); b = 0 at mu = 1 (the lobe is round at
   normal view: b is odd in theta), where the walk's fit holds only noise (|b| < 0.02). */
static void table(void)
{
    static double E[SHEEN_REF_NR][SHEEN_REF_NMU], A[SHEEN_REF_NR][SHEEN_REF_NMU], B[SHEEN_REF_NR][SHEEN_REF_NMU];
    int i, j, k, filled = 0;
    for (j = 0; j < SHEEN_REF_NR; ++j)
        for (i = 0; i < SHEEN_REF_NMU; ++i) {
            E[j][i] = sheen_ref[j][i][0]; A[j][i] = sheen_ref[j][i][3]; B[j][i] = sheen_ref[j][i][4];
        }
    for (j = SHEEN_REF_NR - 1; j >= 0; --j)
        for (i = 0; i < SHEEN_REF_NMU; ++i) {
            if (A[j][i] > 0.0) continue;
            ++filled;
            for (k = i - 1; k >= 0 && !(sheen_ref[j][k][3] > 0.0); --k) {}
            if (k >= 0) { A[j][i] = A[j][k]; B[j][i] = B[j][k]; continue; }
            A[j][i] = A[j + 1][i] * sheen_ref_r[j] / sheen_ref_r[j + 1]; B[j][i] = B[j + 1][i];
        }
    for (j = 0; j < SHEEN_REF_NR; ++j) B[j][SHEEN_REF_NMU - 1] = 0.0;
    printf("/* BEGIN GENERATED SHEEN TABLE (tests/gen/fit_sheen.c from tests/gen/sheen_ref.h; do not edit) */\n");
    printf("/* [r][mu] -> E^(1/4), a, b; %d nodes without a lobe fit filled (see fit_sheen.c) */\n", filled);
    printf("#define APPEAR__SHEEN_DATA { \\\n");
    for (j = 0; j < SHEEN_REF_NR; ++j) {
        printf("/* r %.4f */ { \\\n", sheen_ref_r[j]);
        for (i = 0; i < SHEEN_REF_NMU; ++i)
            printf("%s{%.7ff, %.5ff, %.5ff}%s", i % 2 == 0 ? "" : " ", pow(E[j][i], 0.25), A[j][i], B[j][i] == 0.0 ? 0.0 : B[j][i],
                   i + 1 < SHEEN_REF_NMU ? (i % 2 == 1 ? ", \\\n" : ",") : " \\\n");
        printf("}%s \\\n", j + 1 < SHEEN_REF_NR ? "," : "");
    }
    printf("}\n/* END GENERATED SHEEN TABLE */\n");
}

static int rational(void)
{
    form fe, fa, fb;
    int i, j, k;
    double emax = 0, esum = 0, eabs = 0; int ecount = 0; double emax_mu = 0, emax_r = 0;
    memset(&fe, 0, sizeof fe); memset(&fa, 0, sizeof fa); memset(&fb, 0, sizeof fb);

    /* E */
    fe.pre = 0;
    fe.qpos = 1; fe.expo = 1; fe.ppos = 1;
    fe.np = terms(fe.pi, fe.pj, EPX, EPR, 9, 0);
    fe.nq = terms(fe.qi, fe.qj, EQX, EQR, 9, 1);
    nd = 0;
    for (j = 0; j < SHEEN_REF_NR; ++j)
        for (i = 0; i < SHEEN_REF_NMU; ++i) {
            double E = sheen_ref[j][i][0];
            dmu[nd] = sheen_ref_mu[i]; dr[nd] = sheen_ref_r[j]; dy[nd] = E;
            dw[nd] = 1.0 / fmax(E, 0.05);
            ++nd;
        }
    fit(&fe);
    print_form("E", &fe);
    for (j = 0; j < SHEEN_REF_NR; ++j)
        for (i = 0; i < SHEEN_REF_NMU; ++i) {
            double E = sheen_ref[j][i][0], v = eval_form(&fe, sheen_ref_mu[i], sheen_ref_r[j]);
            if (E > 0.05) {
                double e = fabs(v - E) / E;
                esum += e; ++ecount;
                if (e > emax) { emax = e; emax_mu = sheen_ref_mu[i]; emax_r = sheen_ref_r[j]; }
            } else eabs = fmax(eabs, fabs(v - E));
        }
    printf("E error where E_ref > 0.05 (%d nodes): max %.4f (mu %.4f r %.4f), mean %.4f; elsewhere max abs %.4f\n",
           ecount, emax, emax_mu, emax_r, esum / ecount, eabs);

    /* a */
    fa.pre = 1;
    fa.qpos = 1;
    fa.np = terms(fa.pi, fa.pj, AX, AR, 9, 0);
    fa.nq = terms(fa.qi, fa.qj, AX, AR, 9, 1);
    nd = 0;
    for (j = 0; j < SHEEN_REF_NR; ++j)
        for (i = 0; i < SHEEN_REF_NMU; ++i) {
            const double *n = sheen_ref[j][i];
            if (n[0] < 0.01 || n[3] <= 0.0) continue;
            dmu[nd] = sheen_ref_mu[i]; dr[nd] = sheen_ref_r[j]; dy[nd] = n[3];
            dw[nd] = fmin(1.0, n[0] / 0.05) / n[3];
            ++nd;
        }
    fit(&fa);
    print_form("a", &fa);
    /* b */
    fb.pre = 2;
    fb.qpos = 1;
    fb.np = terms(fb.pi, fb.pj, BPX, BR, 9, 0);
    fb.nq = terms(fb.qi, fb.qj, BQX, BR, 9, 1);
    nd = 0;
    for (j = 0; j < SHEEN_REF_NR; ++j)
        for (i = 0; i < SHEEN_REF_NMU; ++i) {
            const double *n = sheen_ref[j][i];
            if (n[0] < 0.01 || n[3] <= 0.0) continue;
            dmu[nd] = sheen_ref_mu[i]; dr[nd] = sheen_ref_r[j]; dy[nd] = n[4];
            dw[nd] = fmin(1.0, n[0] / 0.05) / 0.05;
            ++nd;
        }
    fit(&fb);
    print_form("b", &fb);
    {
        double tvmax = 0, tvsum = 0, own = 0, ownmax = 0, wsum = 0;
        double amax = 0, bmax = 0;
        int cnt = 0;
        for (j = 0; j < SHEEN_REF_NR; ++j)
            for (i = 0; i < SHEEN_REF_NMU; ++i) {
                const double *n = sheen_ref[j][i];
                double mu = sheen_ref_mu[i], r = sheen_ref_r[j], a, b, tv;
                if (n[0] < 0.05 || n[3] <= 0.0) continue;
                a = eval_form(&fa, mu, r); b = eval_form(&fb, mu, r);
                amax = fmax(amax, fabs(a - n[3]) / n[3]); bmax = fmax(bmax, fabs(b - n[4]));
                tv = ltc_tv(a, b, n[3], n[4]);
                tvmax = fmax(tvmax, tv); tvsum += tv; ++cnt;
                own += n[5] - n[6]; ownmax = fmax(ownmax, n[5] - n[6]); wsum += 1;
            }
        printf("lobe (nodes with E_ref > 0.05, %d): a rel err max %.4f, b abs err max %.4f;\n"
               "  TV(closed form, node's LTC) max %.4f mean %.4f; node's LTC misfit TV - TV0 max %.4f mean %.4f\n",
               cnt, amax, bmax, tvmax, tvsum / cnt, ownmax, own / wsum);
    }
    {   /* sanity over the whole domain */
        double qmin = 1e30, amin = 1e30, emn = 1e30, emx = -1e30, bmx = 0;
        const int n = 257;
        for (j = 0; j < n; ++j)
            for (i = 0; i < n; ++i) {
                double mu = (i + 0.0) / (n - 1), r = (j + 1.0) / n, q;
                double E;
                mu = mu < 1e-6 ? 0.0 : mu;
                E = eval_pq(&fe, fe.c, mu, r, &q); qmin = fmin(qmin, q);
                eval_pq(&fa, fa.c, mu, r, &q); qmin = fmin(qmin, q);
                amin = fmin(amin, eval_form(&fa, mu, r) / r);
                eval_pq(&fb, fb.c, mu, r, &q); qmin = fmin(qmin, q);
                bmx = fmax(bmx, fabs(eval_form(&fb, mu, r)));
                emn = fmin(emn, E); emx = fmax(emx, E);
            }
        printf("domain (257 x 257, mu in [0, 1], r in (0, 1]): min Q %.4f, min a/r %.4f, E in [%.5f, %.5f], max |b| %.4f\n",
               qmin, amin, emn, emx, bmx);
    }
    (void)k;
    return 0;
}
