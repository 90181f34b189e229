/* tests/gen/gen_materials.c - writes appear.h's material data (SECTION materials, >>materials):
   the named metals' complex index tables, their RGB forms, and the named dielectrics'
   dispersion coefficients, from the measurements of tests/gen/materials_data.h. Double
   precision throughout; a few milliseconds.

       cc -O2 -Wall -I. tests/gen/gen_materials.c -o build/gen_materials -lm
       ./build/gen_materials > build/materials_tables.h      (the accuracy report on stderr)
       python3 tests/gen/splice.py build/materials_tables.h

   splice.py replaces the block between the BEGIN / END GENERATED MATERIALS TABLES lines of
   SECTION tables (>>tables). tests/test_materials.c (suite materials) includes this file
   (GEN_MATERIALS_NO_MAIN), writes the block again and compares it with appear.h's, byte for
   byte, and measures every figure the report prints.

   1. Metals. The table holds n and k at GM_NL nodes, 360, 365, ..., 830 nm: each node is the
      source's piecewise-linear interpolant (the measurement table as published, linear between
      its points, as pbrt-v4 and Mitsuba 3 read theirs) at the node's wavelength, rounded to
      float. appear.h interpolates linearly between the nodes. Its error against the source
      (at the source's own points in 360..830 nm) is printed per metal.
   2. RGB forms, per metal and channel of linear sRGB (IEC 61966-2-1; D65 white):
        F(mu)_rgb = M integral F(mu, lambda) D65(lambda) cmf(lambda) dlambda
                    / integral D65 ybar dlambda,
      F the exact conductor Fresnel reflectance [BW99, Sec. 14.2] (unpolarised) of the table's
      n, k, at 1 nm steps from 360 to 830 nm (cmf: CIE 1931 2 degrees at 1 nm, D65 linear
      between its 5 nm values as CIE 15 prescribes; the sum of the 1 nm samples, a rule exact
      to far below 1e-4 here). M maps XYZ to linear sRGB; it is built from the sRGB primaries
      (0.64, 0.33), (0.30, 0.60), (0.15, 0.06) and the integrated D65 white (not the rounded
      (0.3127, 0.3290)), so that a constant reflectance R maps to (R, R, R) exactly.
      Stored, each clipped into [0, 1] (what appear_conductor_make_f82 accepts; gold's red F0
      integrates to 1.04: its spectrum is more saturated than the sRGB red primary, outside the
      gamut, and the clip is the one loss the tests measure apart): F0 = F(1)_rgb, F82 =
      F(1/7)_rgb (the reflectance at cos = 1/7, about 82 degrees: the F82 of [Kutz21,
      Hoffman19]), tint = F82 / Schlick(1/7, F0) (the tint parameter of
      appear_conductor_make_f82 / appear_fresnel_f82_coef: above 1 where the metal's dip at 82
      degrees is shallower than Schlick's, clipped to 1, Schlick itself), and an RGB (eta, k)
      per channel fitted to the clipped curve: k fixed by eta so that the exact Fresnel
      reflectance at normal incidence is F0 (at most 0.9999),
          k^2 = (F0 (eta + 1)^2 - (eta - 1)^2) / (1 - F0),
      and eta chosen in the range where k^2 >= 0 to minimise the largest |F(mu; eta, k) -
      F(mu)_rgb| over GM_NMU cosines mu = i / (GM_NMU - 1) (a scan, then golden section).
   3. Dielectrics: the sources' Sellmeier coefficients, C in um^2 (a source giving sqrt(C) is
      squared here), and, for ice, the Cauchy form n = A + B / L^2 + C / L^4 (L in um) fitted
      to Warren and Brandt's tabulated n by linear least squares.

   Output: float literals with 9 significant digits (exact float round trip); at most 100
   columns a line. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "materials_data.h"

#define GM_L0 360.0 /* nm, first node */
#define GM_DL 5.0   /* nm between nodes */
#define GM_NL 95    /* nodes: 360..830 */
#define GM_NMU 257  /* cosines of the RGB fit */

static float gm_f(double x) { return (float)x; }

/* the source's own piecewise-linear interpolant (clamped at its ends, which bracket 360..830) */
static void gm_src_nk(const md_metal *m, double l, double *n, double *k)
{
    int i;
    const double *p = m->nk;
    if (l <= p[0]) { *n = p[1]; *k = p[2]; return; }
    for (i = 0; i + 1 < m->n; ++i) {
        const double *a = p + 3 * i, *b = a + 3;
        if (l <= b[0]) {
            double t = (l - a[0]) / (b[0] - a[0]);
            *n = a[1] + t * (b[1] - a[1]);
            *k = a[2] + t * (b[2] - a[2]);
            return;
        }
    }
    *n = p[3 * (m->n - 1) + 1]; *k = p[3 * (m->n - 1) + 2];
}
/* the table's nodes, rounded to float as appear.h stores them */
static void gm_nodes(int id, double eta[GM_NL], double k[GM_NL])
{
    int i;
    for (i = 0; i < GM_NL; ++i) {
        double n, kk;
        gm_src_nk(&md_metals[id], GM_L0 + GM_DL * i, &n, &kk);
        eta[i] = gm_f(n); k[i] = gm_f(kk);
    }
}
/* appear.h's lookup, in double: linear between the nodes, clamped to 360..830 */
static void gm_table_nk(const double eta[GM_NL], const double k[GM_NL], double l, double *n, double *kk)
{
    double t = (l - GM_L0) / GM_DL;
    int i;
    t = t < 0 ? 0 : t > GM_NL - 1 ? GM_NL - 1 : t;
    i = (int)t; i = i < GM_NL - 2 ? i : GM_NL - 2;
    t -= i;
    *n = eta[i] + t * (eta[i + 1] - eta[i]);
    *kk = k[i] + t * (k[i + 1] - k[i]);
}
/* exact unpolarised Fresnel reflectance of a conductor n + ik from a medium of index 1 at
   incidence cosine c [BW99, Sec. 14.2]: with the complex cos_t from Snell,
   r_s = (c - N cos_t) / (c + N cos_t), r_p = (N c - cos_t) / (N c + cos_t); complex arithmetic
   in double */
typedef struct { double re, im; } gm_cpx;
static gm_cpx gm_c(double re, double im) { gm_cpx z; z.re = re; z.im = im; return z; }
static gm_cpx gm_mul(gm_cpx a, gm_cpx b) { return gm_c(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re); }
static gm_cpx gm_div(gm_cpx a, gm_cpx b)
{
    double d = b.re * b.re + b.im * b.im;
    return gm_c((a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d);
}
static gm_cpx gm_sqrt(gm_cpx a)
{
    double m = hypot(a.re, a.im), t = sqrt(0.5 * (m + fabs(a.re)));
    if (t == 0) return gm_c(0, 0);
    return a.re >= 0 ? gm_c(t, 0.5 * a.im / t) : gm_c(fabs(0.5 * a.im / t), a.im < 0 ? -t : t);
}
static double gm_abs2(gm_cpx a) { return a.re * a.re + a.im * a.im; }
static double gm_fresnel(double c, double n, double k)
{
    gm_cpx N = gm_c(n, k), N2 = gm_mul(N, N), ct, nct, rs, rp;
    double s2 = 1.0 - c * c;
    if (c <= 0) return 1.0;
    ct = gm_sqrt(gm_div(gm_c(N2.re - s2, N2.im), N2)); /* cos_t = sqrt(1 - s^2 / N^2) */
    nct = gm_mul(N, ct);
    rs = gm_div(gm_c(c - nct.re, -nct.im), gm_c(c + nct.re, nct.im));
    rp = gm_div(gm_c(N.re * c - ct.re, N.im * c - ct.im), gm_c(N.re * c + ct.re, N.im * c + ct.im));
    return 0.5 * (gm_abs2(rs) + gm_abs2(rp));
}

/* ---- colour: CIE 1931 x D65 at 1 nm, and XYZ -> linear sRGB ---- */
static double gm_d65(int nm) /* nm in 360..830: linear between the 5 nm values */
{
    int i = (nm - 360) / 5, r = (nm - 360) % 5;
    if (r == 0) return md_d65[i];
    return md_d65[i] + (md_d65[i + 1] - md_d65[i]) * r / 5.0;
}
/* the 3x3 inverse (rows of m) */
static void gm_inv3(const double m[3][3], double o[3][3])
{
    double d = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            int a = (j + 1) % 3, b = (j + 2) % 3, c = (i + 1) % 3, e = (i + 2) % 3;
            o[i][j] = (m[a][c] * m[b][e] - m[a][e] * m[b][c]) / d;
        }
}
/* XYZ -> linear sRGB, white = the integrated D65 (see the top) */
static void gm_srgb_matrix(double M[3][3])
{
    static const double xy[3][2] = { { 0.64, 0.33 }, { 0.30, 0.60 }, { 0.15, 0.06 } };
    double P[3][3], Pi[3][3], W[3] = { 0, 0, 0 }, s[3], A[3][3];
    int i, j, l;
    for (l = 360; l <= 830; ++l)
        for (i = 0; i < 3; ++i) W[i] += gm_d65(l) * md_cmf[l - 360][i];
    { double y = W[1]; for (i = 0; i < 3; ++i) W[i] /= y; }
    for (j = 0; j < 3; ++j) { /* columns: the primaries' XYZ at Y = 1 */
        P[0][j] = xy[j][0] / xy[j][1]; P[1][j] = 1.0; P[2][j] = (1.0 - xy[j][0] - xy[j][1]) / xy[j][1];
    }
    gm_inv3(P, Pi);
    for (i = 0; i < 3; ++i) s[i] = Pi[i][0] * W[0] + Pi[i][1] * W[1] + Pi[i][2] * W[2];
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) A[i][j] = P[i][j] * s[j]; /* rgb -> XYZ */
    gm_inv3(A, M);
}
/* linear sRGB of a spectral reflectance given at 1 nm, 360..830 (471 values) */
static void gm_rgb(const double *R, double rgb[3])
{
    static double M[3][3];
    static int made;
    double xyz[3] = { 0, 0, 0 }, ny = 0;
    int l, i;
    if (!made) { gm_srgb_matrix(M); made = 1; }
    for (l = 360; l <= 830; ++l) {
        double w = gm_d65(l);
        for (i = 0; i < 3; ++i) xyz[i] += w * R[l - 360] * md_cmf[l - 360][i];
        ny += w * md_cmf[l - 360][1];
    }
    for (i = 0; i < 3; ++i) rgb[i] = (M[i][0] * xyz[0] + M[i][1] * xyz[1] + M[i][2] * xyz[2]) / ny;
}
/* the spectrally integrated RGB reflectance of metal id at cosine mu */
static void gm_metal_rgb_at(int id, double mu, double rgb[3])
{
    double eta[GM_NL], k[GM_NL], R[MD_CMF_N];
    int l;
    gm_nodes(id, eta, k);
    for (l = 360; l <= 830; ++l) {
        double n, kk;
        gm_table_nk(eta, k, l, &n, &kk);
        R[l - 360] = gm_fresnel(mu, n, kk);
    }
    gm_rgb(R, rgb);
}
static double gm_clip(double x) { return x < 0 ? 0 : x > 1 ? 1 : x; }
static double gm_schlick(double c, double f0) { double m = 1.0 - c; return f0 + (1.0 - f0) * m * m * m * m * m; }

/* ---- the RGB (eta, k) fit of one channel: F(1) = F0 exactly, eta minimising the max error ---- */
static double gm_k_of(double eta, double f0)
{
    double k2 = (f0 * (eta + 1) * (eta + 1) - (eta - 1) * (eta - 1)) / (1.0 - f0);
    return k2 > 0 ? sqrt(k2) : 0.0;
}
static double gm_fit_err(double eta, double f0, const double *target)
{
    double k = gm_k_of(eta, f0), e = 0;
    int j;
    for (j = 0; j < GM_NMU; ++j) {
        double d = fabs(gm_fresnel((double)j / (GM_NMU - 1), eta, k) - target[j]);
        e = d > e ? d : e;
    }
    return e;
}
/* writes eta, k; returns the max error over the cosines */
static double gm_fit_channel(double f0, const double *target, double *eta, double *k)
{
    double s = sqrt(f0 < 0.9999 ? (f0 > 1e-4 ? f0 : 1e-4) : 0.9999);
    double lo = log((1 - s) / (1 + s)), hi = log((1 + s) / (1 - s)), best, be = 1e30, a, b, es[2001];
    int i;
    f0 = s * s;
    for (i = 0; i <= 2000; ++i) { /* log-spaced scan of the admissible eta */
        es[i] = gm_fit_err(exp(lo + (hi - lo) * i / 2000.0), f0, target);
        if (es[i] < be) be = es[i];
    }
    /* the smallest eta whose error is within 1e-5 of the best: where the curve is flat in eta
       (gold's red channel, F0 at the clip) this picks the metal-like small eta, large k */
    for (i = 0; es[i] > be + 1e-5; ++i) {}
    best = lo + (hi - lo) * i / 2000.0;
    a = best - (hi - lo) / 2000.0; b = best + (hi - lo) / 2000.0;
    a = a < lo ? lo : a; b = b > hi ? hi : b;
    for (i = 0; i < 100; ++i) { /* golden section */
        double c = b - (b - a) * 0.6180339887498949, d = a + (b - a) * 0.6180339887498949;
        if (gm_fit_err(exp(c), f0, target) < gm_fit_err(exp(d), f0, target)) b = d; else a = c;
    }
    *eta = gm_f(exp(0.5 * (a + b)));
    *k = gm_f(gm_k_of(*eta, f0));
    return gm_fit_err(*eta, f0, target); /* of the float-rounded pair (k from the rounded eta) */
}

/* per metal: [0] F0, [1] F82, [2] tint, [3] eta, [4] k (rgb), and the fit's max error per channel */
typedef struct { double v[5][3], fit_err[3]; } gm_metal_rgb;
static gm_metal_rgb gm_rgb_forms(int id)
{
    gm_metal_rgb r;
    static double T[3][GM_NMU];
    int j, c;
    for (j = 0; j < GM_NMU; ++j) { /* the target curve, clipped into [0, 1] (see the top) */
        double rgb[3];
        gm_metal_rgb_at(id, (double)j / (GM_NMU - 1), rgb);
        for (c = 0; c < 3; ++c) T[c][j] = gm_clip(rgb[c]);
    }
    {
        double rgb82[3];
        gm_metal_rgb_at(id, 1.0 / 7.0, rgb82);
        for (c = 0; c < 3; ++c) {
            r.v[0][c] = gm_f(T[c][GM_NMU - 1]);
            r.v[1][c] = gm_f(gm_clip(rgb82[c]));
            r.v[2][c] = gm_f(gm_clip(gm_clip(rgb82[c]) / gm_schlick(1.0 / 7.0, T[c][GM_NMU - 1])));
            r.fit_err[c] = gm_fit_channel(T[c][GM_NMU - 1], T[c], &r.v[3][c], &r.v[4][c]);
        }
    }
    return r;
}

/* ---- dielectrics ---- */
/* ice: least squares A + B x + C x^2, x = 1 / L^2 (L in um), over md_ice; writes A, B, C */
static void gm_ice_cauchy(double abc[3])
{
    double N[3][3] = { { 0 } }, y[3] = { 0 }, Ni[3][3];
    int i, a, b;
    for (i = 0; i < MD_N_ICE; ++i) {
        double L = md_ice[2 * i] / 1000.0, x = 1.0 / (L * L), p[3];
        p[0] = 1; p[1] = x; p[2] = x * x;
        for (a = 0; a < 3; ++a) {
            y[a] += p[a] * md_ice[2 * i + 1];
            for (b = 0; b < 3; ++b) N[a][b] += p[a] * p[b];
        }
    }
    gm_inv3(N, Ni);
    for (a = 0; a < 3; ++a) abc[a] = Ni[a][0] * y[0] + Ni[a][1] * y[1] + Ni[a][2] * y[2];
}
/* the header's row: kind, B1..B4, C1..C4 (Cauchy: A, B, C in B1..B3) */
static void gm_dielectric_row(int id, double row[9])
{
    const md_dielectric *d = &md_dielectrics[id];
    int i;
    memset(row, 0, 9 * sizeof(double));
    row[0] = d->kind;
    if (d->kind == 1) {
        double abc[3];
        gm_ice_cauchy(abc);
        for (i = 0; i < 3; ++i) row[1 + i] = gm_f(abc[i]);
        return;
    }
    for (i = 0; i < 4; ++i) {
        row[1 + i] = gm_f(d->b[i]);
        row[5 + i] = gm_f(d->c_squared ? d->c[i] * d->c[i] : d->c[i]);
    }
}

/* ---- output ---- */
static void gm_put(FILE *f, int *col, const char *s)
{
    int n = (int)strlen(s);
    if (*col + n > 96) { fputs(" \\\n", f); *col = 0; }
    fputs(s, f);
    *col += n;
}
static void gm_num(FILE *f, int *col, double v, int last)
{
    char b[40];
    snprintf(b, sizeof b, "%.9gf%s", (double)gm_f(v), last ? "" : ",");
    if (!strchr(b, '.') && !strchr(b, 'e')) { /* an integral value: "1f" is not a literal */
        snprintf(b, sizeof b, "%.1ff%s", (double)gm_f(v), last ? "" : ",");
    }
    gm_put(f, col, b);
}
static void gm_write(FILE *f)
{
    int id, c, i, col;
    fprintf(f, "/* BEGIN GENERATED MATERIALS TABLES (tests/gen/gen_materials.c; do not edit) */\n");
    fprintf(f, "#define APPEAR__METAL_N %d\n#define APPEAR__METAL_NL %d\n", MD_N_METALS, GM_NL);
    fprintf(f, "/* per metal: eta, then k, at lambda = 360 + 5 i nm */\n#define APPEAR__METAL_NK_DATA { \\\n");
    for (id = 0; id < MD_N_METALS; ++id) {
        double eta[GM_NL], k[GM_NL];
        gm_nodes(id, eta, k);
        fprintf(f, "/* %s */ { { \\\n", md_metals[id].symbol);
        for (c = 0; c < 2; ++c) {
            col = 0;
            for (i = 0; i < GM_NL; ++i) gm_num(f, &col, c ? k[i] : eta[i], i == GM_NL - 1);
            fprintf(f, c ? " } }%s \\\n" : " }, { \\\n", id + 1 < MD_N_METALS ? "," : "");
        }
    }
    fprintf(f, "}\n/* per metal: F0, F82, tint, eta, k, each r, g, b (linear sRGB) */\n#define APPEAR__METAL_RGB_DATA { \\\n");
    for (id = 0; id < MD_N_METALS; ++id) {
        gm_metal_rgb r = gm_rgb_forms(id);
        col = 0;
        fprintf(f, "/* %s */ { ", md_metals[id].symbol);
        col = (int)strlen(md_metals[id].symbol) + 9;
        for (i = 0; i < 5; ++i) {
            gm_put(f, &col, "{ ");
            for (c = 0; c < 3; ++c) gm_num(f, &col, r.v[i][c], c == 2);
            gm_put(f, &col, i < 4 ? " }," : " }");
            if (i < 4) gm_put(f, &col, " ");
        }
        fprintf(f, " }%s \\\n", id + 1 < MD_N_METALS ? "," : "");
    }
    fprintf(f, "}\n#define APPEAR__DIELECTRIC_N %d\n", MD_N_DIELECTRICS);
    fprintf(f, "/* per dielectric: kind, B1..B4, C1..C4 (um^2); kind 1: A, B, C of the Cauchy form */\n"
               "#define APPEAR__DIELECTRIC_DATA { \\\n");
    for (id = 0; id < MD_N_DIELECTRICS; ++id) {
        double row[9];
        gm_dielectric_row(id, row);
        col = 0;
        fprintf(f, "/* %s */ { ", md_dielectrics[id].enum_name + 18);
        col = (int)strlen(md_dielectrics[id].enum_name + 18) + 9;
        for (i = 0; i < 9; ++i) gm_num(f, &col, row[i], i == 8);
        fprintf(f, " }%s \\\n", id + 1 < MD_N_DIELECTRICS ? "," : "");
    }
    fprintf(f, "}\n/* END GENERATED MATERIALS TABLES */\n");
}

/* ---- the accuracy report ---- */
/* interpolation error of metal id against its source at the source's points in 360..830 */
typedef struct { double dn, dk, rn, rk, df0; int pts; } gm_interp;
static gm_interp gm_interp_error(int id)
{
    gm_interp e;
    double eta[GM_NL], k[GM_NL];
    const md_metal *m = &md_metals[id];
    int i;
    memset(&e, 0, sizeof e);
    gm_nodes(id, eta, k);
    for (i = 0; i < m->n; ++i) {
        double l = m->nk[3 * i], n0 = m->nk[3 * i + 1], k0 = m->nk[3 * i + 2], n, kk, d;
        if (l < 360 || l > 830) continue;
        gm_table_nk(eta, k, l, &n, &kk);
        e.pts++;
        d = fabs(n - n0); e.dn = d > e.dn ? d : e.dn; d /= n0; e.rn = d > e.rn ? d : e.rn;
        d = fabs(kk - k0); e.dk = d > e.dk ? d : e.dk; d /= k0; e.rk = d > e.rk ? d : e.rk;
        d = fabs(gm_fresnel(1.0, n, kk) - gm_fresnel(1.0, n0, k0)); e.df0 = d > e.df0 ? d : e.df0;
    }
    return e;
}
static void gm_report(FILE *f)
{
    int id, c;
    fprintf(f, "metal  pts  max|dn|  rel     max|dk|  rel     max|dF0|   F0 rgb                   "
               "F82 rgb                  tint                     eta rgb                  k rgb"
               "                    fit max err rgb\n");
    for (id = 0; id < MD_N_METALS; ++id) {
        gm_interp e = gm_interp_error(id);
        gm_metal_rgb r = gm_rgb_forms(id);
        fprintf(f, "%-5s %4d  %.4f  %.4f  %.4f  %.4f  %.2e  ", md_metals[id].symbol, e.pts, e.dn, e.rn, e.dk, e.rk,
                e.df0);
        for (c = 0; c < 5; ++c) fprintf(f, "%.4f %.4f %.4f  ", r.v[c][0], r.v[c][1], r.v[c][2]);
        fprintf(f, "%.4f %.4f %.4f\n", r.fit_err[0], r.fit_err[1], r.fit_err[2]);
    }
}

#ifndef GEN_MATERIALS_NO_MAIN
int main(void)
{
    gm_write(stdout);
    gm_report(stderr);
    return 0;
}
#endif
