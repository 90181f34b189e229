/* tests/test_materials.c - SECTION materials (>>materials): the named metals and dielectrics.
   - the generated block of appear.h is what tests/gen/gen_materials.c writes today, byte for
     byte (the generator is compiled in: GEN_MATERIALS_NO_MAIN);
   - the metals' lookup against its source (materials_data.h) at the source's own points:
     the interpolation error, per metal (measured, bounded);
   - the RGB F0 and F82 against the spectral integration of appear.h's own float lookup and
     float Fresnel (<= 1e-3), the tint against F82 / Schlick, and the fitted RGB (eta, k)
     against the integrated curve over all angles (measured per metal, bounded);
   - the dielectrics: n_d and V_d of the SCHOTT glasses against the catalog to its digits, water
     and diamond against OpenPBR's "between 55 and 56", ice against Warren and Brandt's table,
     float against the double formula; the Abbe form's n_d and V_d;
   - bad input: unknown ids, NaN and out-of-range wavelengths, NULL pointers;
   - dispersion (appear_dielectric_dispersive): chi-square of the sampler with each wavelength as
     the hero, reflection weights per wavelength against eval / pdf, the flag and zeroed
     secondaries after a refraction, E[weight_i] = F(eta_i) for the smooth mirror, and one eta
     everywhere = the plain dielectric bit for bit. */
#include "harness.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define GEN_MATERIALS_NO_MAIN
#include "gen/gen_materials.c"

#ifdef APPEAR_HAS_MATERIALS

/* the block between BEGIN and END GENERATED MATERIALS TABLES of the file at path (malloc'd) */
static char *block_of(const char *text)
{
    const char *b = strstr(text, "/* BEGIN GENERATED MATERIALS TABLES"), *e;
    char *r;
    static const char end[] = "/* END GENERATED MATERIALS TABLES */\n";
    if (!b) return NULL;
    e = strstr(b, end);
    if (!e) return NULL;
    e += sizeof end - 1;
    r = (char *)malloc((size_t)(e - b) + 1);
    memcpy(r, b, (size_t)(e - b));
    r[e - b] = 0;
    return r;
}
static char *read_all(FILE *f)
{
    long n;
    char *s;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    s = (char *)malloc((size_t)n + 1);
    n = (long)fread(s, 1, (size_t)n, f);
    s[n] = 0;
    return s;
}

/* linear sRGB of the spectral reflectance R(lambda) at 1 nm (R[0] at 360 nm), the CIE data of
   materials_data.h, the generator's matrix (checked below on white) */
static void srgb_of(const double *R, double rgb[3])
{
    double xyz[3] = { 0, 0, 0 }, ny = 0, M[3][3];
    int l, i;
    gm_srgb_matrix(M);
    for (l = 360; l <= 830; ++l) {
        double w = gm_d65(l);
        for (i = 0; i < 3; ++i) xyz[i] += w * R[l - 360] * md_cmf[l - 360][i];
        ny += w * md_cmf[l - 360][1];
    }
    for (i = 0; i < 3; ++i) rgb[i] = (M[i][0] * xyz[0] + M[i][1] * xyz[1] + M[i][2] * xyz[2]) / ny;
}
/* the RGB reflectance of metal m at cosine mu from appear.h's float lookup and float Fresnel */
static void header_rgb(int m, float mu, double rgb[3])
{
    double R[MD_CMF_N];
    int l;
    for (l = 360; l <= 830; ++l) {
        float e, k;
        appear_metal_eta_k(m, (float)l, &e, &k);
        R[l - 360] = appear_fresnel_conductor(mu, e, k);
    }
    srgb_of(R, rgb);
}
static double clip01(double x) { return x < 0 ? 0 : x > 1 ? 1 : x; }

static void materials_generated(void)
{
    h_case("materials: appear.h's generated block = tests/gen/gen_materials.c's output, byte for byte");
    {
        FILE *g = tmpfile(), *h = fopen("appear.h", "rb");
        char *gen, *hdr, *bh;
        H_CHECK(g && h, "cannot open a temporary file or appear.h (run from the repository root)");
        if (g && h) {
            gm_write(g);
            gen = read_all(g);
            hdr = read_all(h);
            bh = block_of(hdr);
            H_CHECK(bh && strcmp(gen, bh) == 0,
                    "appear.h's MATERIALS block differs from the generator's: regenerate (tests/gen/gen_materials.c)");
            free(gen); free(hdr); free(bh);
        }
        if (g) fclose(g);
        if (h) fclose(h);
    }
    h_case("materials: the ids and the data agree (APPEAR_METAL_COUNT, APPEAR_DIELECTRIC_COUNT)");
    H_CHECK(APPEAR_METAL_COUNT == MD_N_METALS && APPEAR_DIELECTRIC_COUNT == MD_N_DIELECTRICS,
            "header %d metals %d dielectrics, data %d %d", APPEAR_METAL_COUNT, APPEAR_DIELECTRIC_COUNT, MD_N_METALS,
            MD_N_DIELECTRICS);
    H_CHECK(APPEAR_METAL_AU == 2 && strcmp(md_metals[APPEAR_METAL_AU].symbol, "Au") == 0 &&
                strcmp(md_metals[APPEAR_METAL_CUZN].symbol, "CuZn") == 0 &&
                strcmp(md_metals[APPEAR_METAL_ZN].symbol, "Zn") == 0 &&
                strcmp(md_dielectrics[APPEAR_DIELECTRIC_ICE].enum_name, "APPEAR_DIELECTRIC_ICE") == 0 &&
                strcmp(md_dielectrics[APPEAR_DIELECTRIC_N_BK7].enum_name, "APPEAR_DIELECTRIC_N_BK7") == 0,
            "an enum name and its data row disagree");
}

static void materials_metals(void)
{
    int m;
    h_case("metals: the lookup at a node is the node; between nodes, linear (double reference)");
    for (m = 0; m < APPEAR_METAL_COUNT; ++m) {
        double eta[GM_NL], k[GM_NL], worst = 0;
        int i;
        gm_nodes(m, eta, k);
        for (i = 0; i < GM_NL; ++i) {
            float e, kk;
            appear_metal_eta_k(m, 360.0f + 5.0f * (float)i, &e, &kk);
            H_CHECK((double)e == eta[i] && (double)kk == k[i], "%s node %d: %.9g %.9g, generator %.9g %.9g",
                    md_metals[m].symbol, i, (double)e, (double)kk, eta[i], k[i]);
        }
        for (i = 0; i < 470; ++i) {
            double l = 360.5 + i, n, kr;
            float e, kk;
            gm_table_nk(eta, k, l, &n, &kr);
            appear_metal_eta_k(m, (float)l, &e, &kk);
            worst = fmax(worst, fmax(fabs(e - n) / n, fabs(kk - kr) / kr));
        }
        H_CHECK(worst < 1e-6, "%s: float lookup vs double, relative %.3g", md_metals[m].symbol, worst);
    }

    h_case("metals: interpolation error against the source at its own points in 360..830 nm (measured)");
    {
        double all_n = 0, all_f0 = 0;
        for (m = 0; m < APPEAR_METAL_COUNT; ++m) {
            const md_metal *s = &md_metals[m];
            double dn = 0, dk = 0, rn = 0, df0 = 0;
            int i, pts = 0;
            for (i = 0; i < s->n; ++i) {
                double l = s->nk[3 * i], n0 = s->nk[3 * i + 1], k0 = s->nk[3 * i + 2];
                float e, k;
                if (l < 360 || l > 830) continue;
                appear_metal_eta_k(m, (float)l, &e, &k);
                ++pts;
                dn = fmax(dn, fabs(e - n0)); rn = fmax(rn, fabs(e - n0) / n0);
                dk = fmax(dk, fabs(k - k0));
                df0 = fmax(df0, fabs(gm_fresnel(1.0, e, k) - gm_fresnel(1.0, n0, k0)));
            }
            h_measure("metal interpolation", "%-4s %3d source points: max |dn| %.4f (rel %.4f), max |dk| %.4f, "
                      "max |dF0| %.2e", s->symbol, pts, dn, rn, dk, df0);
            /* bound: below the sources' own uncertainty (Johnson and Christy: 0.02 in n
               and k); copper's absorption edge near 580 nm, between two 5 nm nodes, is
               the largest loss (0.013) */
            H_CHECK(dn < 0.02 && dk < 0.02 && df0 < 5e-3 && pts >= 7, "%s: |dn| %.4f |dk| %.4f |dF0| %.3g (%d points)",
                    s->symbol, dn, dk, df0, pts);
            all_n = fmax(all_n, fmax(dn, dk)); all_f0 = fmax(all_f0, df0);
        }
        h_measure("metal interpolation", "all metals: max |dn|, |dk| %.4f, max |dF0| %.2e", all_n, all_f0);
    }

    h_case("metals: table sizes");
    h_measure("metal tables", "spectral %d bytes a metal (%d nodes x eta, k), %d in all; RGB %d bytes a metal, %d in "
              "all; dielectrics %d bytes", (int)sizeof(APPEAR_T(appear__metal_nk)[0]), APPEAR__METAL_NL,
              (int)sizeof(APPEAR_T(appear__metal_nk)), (int)sizeof(APPEAR_T(appear__metal_rgbf)[0]),
              (int)sizeof(APPEAR_T(appear__metal_rgbf)), (int)sizeof(APPEAR_T(appear__diel_coef)));
}

static void materials_rgb(void)
{
    int m, c;
    h_case("rgb: the XYZ -> sRGB matrix maps the integrated D65 white to (1, 1, 1)");
    {
        double R[MD_CMF_N], rgb[3];
        int l;
        for (l = 0; l < MD_CMF_N; ++l) R[l] = 0.5;
        srgb_of(R, rgb);
        H_CHECK(fabs(rgb[0] - 0.5) < 1e-12 && fabs(rgb[1] - 0.5) < 1e-12 && fabs(rgb[2] - 0.5) < 1e-12,
                "grey 0.5 -> %.15f %.15f %.15f", rgb[0], rgb[1], rgb[2]);
    }

    h_case("rgb: F0, F82 = spectral integration of appear.h's own lookup and Fresnel (<= 1e-3), tint = F82 / Schlick");
    {
        double w0 = 0, w82 = 0, gold = 0;
        for (m = 0; m < APPEAR_METAL_COUNT; ++m) {
            appear_metal_rgb r = appear_metal_to_rgb(m);
            double i0[3], i82[3];
            header_rgb(m, 1.0f, i0);
            header_rgb(m, 1.0f / 7.0f, i82);
            H_CHECK(r.valid, "%s: not valid", md_metals[m].symbol);
            for (c = 0; c < 3; ++c) {
                double d0 = fabs(r.f0[c] - clip01(i0[c])), d82 = fabs(r.f82[c] - clip01(i82[c]));
                double s82 = (double)appear_fresnel_schlick(1.0f / 7.0f, r.f0[c]);
                w0 = fmax(w0, d0); w82 = fmax(w82, d82);
                if (m == APPEAR_METAL_AU && c == 0) gold = i0[c];
                H_CHECK(d0 <= 1e-3 && d82 <= 1e-3, "%s channel %d: F0 %.6f vs %.6f, F82 %.6f vs %.6f", md_metals[m].symbol,
                        c, (double)r.f0[c], i0[c], (double)r.f82[c], i82[c]);
                H_CHECK(fabs(r.f82_tint[c] - clip01(r.f82[c] / s82)) < 1e-5, "%s channel %d: tint %.6f, F82 / Schlick %.6f",
                        md_metals[m].symbol, c, (double)r.f82_tint[c], r.f82[c] / s82);
            }
        }
        h_measure("metal rgb", "max |F0 - integrated| %.2e, max |F82 - integrated| %.2e (float lookup and Fresnel "
                  "against the generator's double, after the clip into [0, 1]); gold's red F0 integrates to %.4f "
                  "(outside sRGB: clipped to 1)", w0, w82, gold);
    }

    h_case("rgb: the fitted eta, k against the integrated curve over all angles (measured per metal)");
    for (m = 0; m < APPEAR_METAL_COUNT; ++m) {
        appear_metal_rgb r = appear_metal_to_rgb(m);
        double e[3] = { 0, 0, 0 };
        int j;
        for (j = 0; j <= 90; ++j) { /* every degree, and the cosines' ends */
            float mu = j == 90 ? 0.0f : cosf((float)j * 3.14159265f / 180.0f);
            double ref[3];
            header_rgb(m, mu, ref);
            for (c = 0; c < 3; ++c)
                e[c] = fmax(e[c], fabs(appear_fresnel_conductor(mu, r.eta[c], r.k[c]) - clip01(ref[c])));
        }
        h_measure("metal rgb fit", "%-4s max |F(eta_rgb, k_rgb) - integrated| over angle: %.4f %.4f %.4f "
                  "(eta %.4f %.4f %.4f, k %.4f %.4f %.4f)", md_metals[m].symbol, e[0], e[1], e[2],
                  (double)r.eta[0], (double)r.eta[1], (double)r.eta[2], (double)r.k[0], (double)r.k[1], (double)r.k[2]);
        /* bound: one RGB pair per channel cannot follow a band's spread of indices exactly;
           gold's red channel carries the gamut clip (8.8e-3) */
        H_CHECK(e[0] < 1.2e-2 && e[1] < 1.2e-2 && e[2] < 1.2e-2, "%s: fit error %.4f %.4f %.4f",
                md_metals[m].symbol, e[0], e[1], e[2]);
        for (c = 0; c < 3; ++c)
            H_CHECK(fabs(appear_fresnel_conductor(1.0f, r.eta[c], r.k[c]) - r.f0[c]) < 2e-4,
                    "%s channel %d: F(1; eta, k) %.6f, F0 %.6f", md_metals[m].symbol, c,
                    (double)appear_fresnel_conductor(1.0f, r.eta[c], r.k[c]), (double)r.f0[c]);
    }

#ifdef APPEAR_HAS_MICROFACET
    h_case("rgb: appear_conductor_make_metal = appear_conductor_make with the same eta, k");
    {
        appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        const float lam[3] = { 450.0f, 550.0f, 650.0f };
        appear_vec3 wo = appear_normalize(appear_vec3_make(0.3f, 0.1f, 0.9f));
        appear_vec3 wi = appear_normalize(appear_vec3_make(-0.4f, 0.2f, 0.8f));
        for (m = 0; m < APPEAR_METAL_COUNT; ++m) {
            appear_metal_rgb r = appear_metal_to_rgb(m);
            appear_spectrum e, k, er, kr;
            appear_conductor a, b, cr, dr;
            appear_spectrum fa, fb, fc, fd;
            int i;
            appear_metal_spectrum(m, lam, &e, &k);
            for (i = 0; i < 3; ++i) { er.v[i] = r.eta[i]; kr.v[i] = r.k[i]; }
            a = appear_conductor_make_metal(d, m, lam); b = appear_conductor_make(d, e, k);
            cr = appear_conductor_make_metal(d, m, NULL); dr = appear_conductor_make(d, er, kr);
            fa = appear_conductor_eval(&a, wo, wi); fb = appear_conductor_eval(&b, wo, wi);
            fc = appear_conductor_eval(&cr, wo, wi); fd = appear_conductor_eval(&dr, wo, wi);
            H_CHECK(a.valid && cr.valid && memcmp(&fa, &fb, sizeof fa) == 0 && memcmp(&fc, &fd, sizeof fc) == 0,
                    "%s: make_metal differs from make", md_metals[m].symbol);
        }
        {
            appear_conductor bad = appear_conductor_make_metal(d, APPEAR_METAL_COUNT, lam);
            H_CHECK(!bad.valid, "an unknown metal gives a valid conductor");
        }
    }
#endif
}

/* the double formula of dielectric i from the source's coefficients (materials_data.h) */
static double diel_ref(int i, double l)
{
    const md_dielectric *d = &md_dielectrics[i];
    double L2 = l * l * 1e-6, s = 1;
    int t;
    if (d->kind == 1) {
        double abc[3];
        gm_ice_cauchy(abc);
        return abc[0] + abc[1] / L2 + abc[2] / (L2 * L2);
    }
    for (t = 0; t < 4; ++t) s += d->b[t] * L2 / (L2 - (d->c_squared ? d->c[t] * d->c[t] : d->c[t]));
    return sqrt(s);
}

static void materials_dielectrics(void)
{
    int i;
    h_case("dielectrics: float against the double formula of the source, 360..830 nm");
    for (i = 0; i < APPEAR_DIELECTRIC_COUNT; ++i) {
        double worst = 0;
        int l;
        for (l = 360; l <= 830; ++l)
            worst = fmax(worst, fabs(appear_dielectric_ior(i, (float)l) - diel_ref(i, l)) / diel_ref(i, l));
        H_CHECK(worst < 1e-6, "%s: relative %.3g", md_dielectrics[i].enum_name, worst);
    }

    h_case("dielectrics: n_d, V_d against the catalog (SCHOTT: to its digits); water, diamond: V_d in [55, 56]");
    for (i = 0; i < APPEAR_DIELECTRIC_COUNT; ++i) {
        const md_dielectric *d = &md_dielectrics[i];
        double nd = appear_dielectric_ior(i, APPEAR_LAMBDA_D), nf = appear_dielectric_ior(i, APPEAR_LAMBDA_F);
        double nc = appear_dielectric_ior(i, APPEAR_LAMBDA_C), vd = (nd - 1) / (nf - nc);
        h_measure("dielectric", "%-32s n_d %.5f V_d %.2f (catalog %s) n(400) %.5f n(700) %.5f", d->enum_name, nd, vd,
                  d->nd_tol > 0 ? "yes" : "no ", (double)appear_dielectric_ior(i, 400.0f),
                  (double)appear_dielectric_ior(i, 700.0f));
        /* float: 1.2e-7 of n on top of the catalog's rounding */
        if (d->nd_tol > 0)
            H_CHECK(fabs(nd - d->nd) <= d->nd_tol + 3e-7 && fabs(vd - d->vd) <= d->vd_tol + 1e-3,
                    "%s: n_d %.6f V_d %.3f, catalog %.5f %.2f", d->enum_name, nd, vd, d->nd, d->vd);
        if (i == APPEAR_DIELECTRIC_WATER || i == APPEAR_DIELECTRIC_DIAMOND) /* [OpenPBR11, dispersion] */
            H_CHECK(vd >= 55 && vd <= 56, "%s: V_d %.3f", d->enum_name, vd);
    }

    h_case("dielectrics: ice's Cauchy fit against Warren and Brandt's table in 360..830 nm");
    {
        double worst = 0;
        for (i = 0; i < MD_N_ICE; ++i) {
            double l = md_ice[2 * i];
            if (l < 360 || l > 830) continue;
            worst = fmax(worst, fabs(appear_dielectric_ior(APPEAR_DIELECTRIC_ICE, (float)l) - md_ice[2 * i + 1]));
        }
        h_measure("dielectric ice", "max |n_fit - n_table| %.2e (the table's 4 decimals: 5e-5)", worst);
        H_CHECK(worst < 3e-4, "ice: %.3g", worst);
    }

    h_case("dielectrics: the Abbe form gives n_d at the d line and V_d back [OpenPBR11]");
    {
        static const float nds[4] = { 1.2f, 1.5f, 1.8f, 2.4f }, vds[4] = { 9.0f, 20.0f, 55.0f, 91.0f };
        int a, b;
        for (a = 0; a < 4; ++a)
            for (b = 0; b < 4; ++b) {
                double nd = appear_ior_cauchy_abbe(nds[a], vds[b], APPEAR_LAMBDA_D);
                double nf = appear_ior_cauchy_abbe(nds[a], vds[b], APPEAR_LAMBDA_F);
                double nc = appear_ior_cauchy_abbe(nds[a], vds[b], APPEAR_LAMBDA_C);
                double vd = (nd - 1) / (nf - nc);
                H_CHECK(fabs(nd - nds[a]) < 1e-6 && fabs(vd - vds[b]) / vds[b] < 1e-3 && nf > nd && nd > nc,
                        "n_d %g V_d %g: n(d) %.7f, V %.4f", (double)nds[a], (double)vds[b], nd, vd);
            }
        H_CHECK(appear_ior_cauchy_abbe(1.5f, INFINITY, 400.0f) == 1.5f, "V_d = Inf: no dispersion");
    }
}

static void materials_bad_input(void)
{
    static const float lams[] = { 360.0f, 830.0f, 359.9f, 830.1f, 0.0f, -1.0f, 1e30f, INFINITY, -INFINITY, NAN };
    int ids[] = { -1, APPEAR_METAL_COUNT, 1000000, -2147483647 - 1 };
    int i, j;
    h_case("bad input: unknown ids give eta 1, k 0 (n 1), status 0; wavelengths clamp; NaN reads the d line");
    for (i = 0; i < 4; ++i)
        for (j = 0; j < 10; ++j) {
            float e = -5, k = -5;
            int ok = appear_metal_eta_k(ids[i], lams[j], &e, &k);
            H_CHECK(!ok && e == 1.0f && k == 0.0f, "metal %d lambda %g: %d %g %g", ids[i], (double)lams[j], ok,
                    (double)e, (double)k);
            H_CHECK(appear_dielectric_ior(ids[i], lams[j]) == 1.0f, "dielectric %d", ids[i]);
        }
    {
        float e0, k0, e1, k1, en, kn, ed, kd;
        appear_metal_eta_k(APPEAR_METAL_CU, 360.0f, &e0, &k0);
        appear_metal_eta_k(APPEAR_METAL_CU, -INFINITY, &e1, &k1);
        H_CHECK(e0 == e1 && k0 == k1, "below the range: not the first node");
        appear_metal_eta_k(APPEAR_METAL_CU, 830.0f, &e0, &k0);
        appear_metal_eta_k(APPEAR_METAL_CU, 1e30f, &e1, &k1);
        H_CHECK(e0 == e1 && k0 == k1, "above the range: not the last node");
        appear_metal_eta_k(APPEAR_METAL_CU, NAN, &en, &kn);
        appear_metal_eta_k(APPEAR_METAL_CU, APPEAR_LAMBDA_D, &ed, &kd);
        H_CHECK(en == ed && kn == kd, "NaN: not the d line");
        H_CHECK(appear_metal_eta_k(APPEAR_METAL_CU, 500.0f, NULL, NULL) == 1, "NULL outputs");
        H_CHECK(appear_dielectric_ior(APPEAR_DIELECTRIC_N_BK7, NAN) ==
                    appear_dielectric_ior(APPEAR_DIELECTRIC_N_BK7, APPEAR_LAMBDA_D), "dielectric NaN");
    }
    {
        appear_metal_rgb r = appear_metal_to_rgb(-1);
        appear_spectrum e, k;
        H_CHECK(!r.valid && r.f0[0] == 0.0f && r.eta[1] == 1.0f && r.k[2] == 0.0f && r.f82_tint[0] == 1.0f,
                "unknown metal's RGB forms");
        H_CHECK(appear_metal_spectrum(APPEAR_METAL_AG, NULL, &e, &k) == 1, "NULL wavelengths");
    }
    h_case("bad input: the Abbe form");
    {
        static const float bad[] = { 0.0f, -1.0f, NAN, INFINITY, -INFINITY, 1e-40f };
        for (i = 0; i < 6; ++i)
            for (j = 0; j < 10; ++j) {
                float a = appear_ior_cauchy_abbe(bad[i], 20.0f, lams[j]), b = appear_ior_cauchy_abbe(1.5f, bad[i], lams[j]);
                float c = appear_ior_cauchy_abbe(1.0001f, 1e-30f, lams[j]);
                H_CHECK(h_finite(a) && h_finite(b) && h_finite(c) && a >= 1e-4f && b >= 1e-4f && c >= 1e-4f &&
                            c <= 1e4f, "n_d or V_d %g lambda %g: %g %g %g", (double)bad[i], (double)lams[j], (double)a,
                        (double)b, (double)c);
            }
        H_CHECK(appear_ior_cauchy_abbe(NAN, 20.0f, 500.0f) == 1.0f && appear_ior_cauchy_abbe(1.5f, -3.0f, 400.0f) == 1.5f,
                "bad n_d: 1, bad V_d: n_d");
    }
}

#ifdef APPEAR_HAS_MICROFACET
/* ---- dispersion: appear_dielectric_dispersive ---- */
typedef struct { appear_dielectric_dispersive m; appear_vec3 wo; } disp_ctx;
static int disp_sample(void *c, float uc, float u1, float u2, appear_vec3 *wi)
{
    disp_ctx *x = (disp_ctx *)c;
    appear_bsdf_record s;
    if (!appear_dielectric_dispersive_sample(&x->m, x->wo, uc, u1, u2, &s)) return 0;
    *wi = s.wi;
    return 1;
}
static double disp_pdf(void *c, appear_vec3 wi)
{
    disp_ctx *x = (disp_ctx *)c;
    return appear_dielectric_dispersive_pdf(&x->m, x->wo, wi);
}
/* BK7's eta at the wavelengths lam, channel `hero` first */
static appear_spectrum disp_eta(const float *lam, int hero)
{
    appear_spectrum e;
    int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i)
        e.v[i] = appear_dielectric_ior(APPEAR_DIELECTRIC_N_BK7, lam[(i + hero) % APPEAR_SPECTRUM_SAMPLES]);
    return e;
}
static void materials_dispersion(void)
{
    float lam[APPEAR_SPECTRUM_SAMPLES];
    int i, h, side;
    char name[96];
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) lam[i] = 400.0f + 300.0f * (float)i / (APPEAR_SPECTRUM_SAMPLES - 1);

    h_case("dispersion: chi-square of the sampler at each wavelength as the hero (rough BK7, wo outside and inside)");
    for (h = 0; h < APPEAR_SPECTRUM_SAMPLES; ++h)
        for (side = 0; side < 2; ++side) {
            disp_ctx x;
            h_chi2_spec sp;
            appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
            x.m = appear_dielectric_make_dispersive(d, disp_eta(lam, h));
            x.wo = appear_normalize(appear_vec3_make(0.6f, 0.1f, side ? -0.7f : 0.7f));
            memset(&sp, 0, sizeof sp);
            snprintf(name, sizeof name, "dispersive_bk7_%dnm_%s", (int)lam[h], side ? "inside" : "outside");
            sp.name = name; sp.sample = disp_sample; sp.pdf = disp_pdf; sp.ctx = &x;
            sp.n_samples = 400000; sp.seed = 3500u + (uint64_t)(2 * h + side);
            H_CHECK(x.m.valid && x.m.dispersive, "not a dispersive model");
            (void)h_chi2(&sp);
        }

    h_case("dispersion: reflection weights every wavelength by its own f; refraction keeps the hero and flags");
    {
        h_rng r = h_rng_make(35);
        appear_microfacet rough = appear_microfacet_make(APPEAR_GGX, 0.2f, 0.2f, APPEAR_SAMPLE_VISIBLE);
        appear_dielectric_dispersive m = appear_dielectric_make_dispersive(rough, disp_eta(lam, 0));
        appear_dielectric hero = appear_dielectric_make(rough, m.eta.v[0]);
        long n = h_n(200000), k, refl = 0, tr = 0;
        double worst = 0;
        for (k = 0; k < n; ++k) {
            appear_vec3 wo = h_rand_dir(&r);
            float uc = h_randf(&r), u1 = h_randf(&r), u2 = h_randf(&r);
            appear_bsdf_record s, t;
            int ok = appear_dielectric_dispersive_sample(&m, wo, uc, u1, u2, &s);
            int ok0 = appear_dielectric_sample(&hero, wo, uc, u1, u2, &t);
            H_CHECK(ok == ok0 && (!ok || (memcmp(&s.wi, &t.wi, sizeof s.wi) == 0 && s.pdf == t.pdf &&
                                         s.f.v[0] == t.f.v[0] && s.weight.v[0] == t.weight.v[0])),
                    "the hero's record differs from the plain dielectric's");
            if (!ok) continue;
            if (s.flags & APPEAR_LOBE_TRANSMISSION) {
                ++tr;
                H_CHECK((s.flags & APPEAR_SAMPLE_TERMINATE_SECONDARY) && s.weight.v[1] == 0.0f && s.f.v[1] == 0.0f,
                        "a refraction without the flag or with secondary weight");
            } else {
                appear_spectrum f = appear_dielectric_dispersive_eval(&m, wo, s.wi);
                ++refl;
                H_CHECK(!(s.flags & APPEAR_SAMPLE_TERMINATE_SECONDARY), "a reflection with the flag");
                for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) {
                    double w = (double)f.v[i] * fabs(s.wi.z) / s.pdf;
                    if (w > 1e-3) worst = fmax(worst, fabs(s.weight.v[i] - w) / w);
                }
            }
        }
        h_measure("dispersion", "%ld reflections (weight_i = eval_i |cos| / pdf: max relative %.2g), %ld refractions "
                  "(flagged)", refl, worst, tr);
        H_CHECK(worst < 1e-4 && refl > n / 20 && tr > n / 4, "relative %.3g, %ld reflections %ld refractions", worst,
                refl, tr);
    }

    h_case("dispersion: smooth reflection, E[weight_i] over reflections = F(eta_i) at each wavelength");
    {
        appear_microfacet smooth = appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f, APPEAR_SAMPLE_VISIBLE);
        appear_dielectric_dispersive m = appear_dielectric_make_dispersive(smooth, disp_eta(lam, 0));
        appear_vec3 wo = appear_normalize(appear_vec3_make(0.8f, 0.0f, 0.3f));
        double sum[APPEAR_SPECTRUM_SAMPLES] = { 0 }, sum2[APPEAR_SPECTRUM_SAMPLES] = { 0 };
        long n = h_n(400000), k;
        h_rng r = h_rng_make(36);
        for (k = 0; k < n; ++k) {
            appear_bsdf_record s;
            float uc = h_randf(&r);
            if (appear_dielectric_dispersive_sample(&m, wo, uc, 0.5f, 0.5f, &s) && (s.flags & APPEAR_LOBE_REFLECTION))
                for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) { sum[i] += s.weight.v[i]; sum2[i] += s.weight.v[i] * s.weight.v[i]; }
        }
        for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) {
            double mean = sum[i] / n, se = sqrt(fmax(sum2[i] / n - mean * mean, 0.0) / n);
            double F = h_fresnel_dielectric(wo.z, m.eta.v[i]);
            H_CHECK(fabs(mean - F) < 4 * se + 1e-9, "channel %d (%.0f nm): E[weight] %.6f +- %.6f, F %.6f", i,
                    (double)lam[i], mean, se, F);
        }
    }

    h_case("dispersion: one eta in every channel = the plain dielectric, bit for bit, never flagged");
    {
        h_rng r = h_rng_make(37);
        long n = h_n(100000), k;
        for (k = 0; k < n; ++k) {
            float a = k % 3 == 0 ? 0.0f : 0.5f * h_randf(&r), e = 0.5f + 2.0f * h_randf(&r);
            appear_microfacet d = appear_microfacet_make(APPEAR_GGX, a, a, APPEAR_SAMPLE_VISIBLE);
            appear_dielectric p = appear_dielectric_make(d, e);
            appear_dielectric_dispersive m = appear_dielectric_make_dispersive(d, appear_spectrum_splat(e));
            appear_vec3 wo = h_rand_dir(&r), wi = h_rand_dir(&r);
            float uc = h_randf(&r), u1 = h_randf(&r), u2 = h_randf(&r);
            appear_bsdf_record s, t;
            appear_spectrum f0 = appear_dielectric_eval(&p, wo, wi), f1 = appear_dielectric_dispersive_eval(&m, wo, wi);
            int o0 = appear_dielectric_sample(&p, wo, uc, u1, u2, &t), o1 = appear_dielectric_dispersive_sample(&m, wo, uc, u1, u2, &s);
            float p0 = appear_dielectric_pdf(&p, wo, wi), p1 = appear_dielectric_dispersive_pdf(&m, wo, wi);
            H_CHECK(!m.dispersive && memcmp(&f0, &f1, sizeof f0) == 0 && memcmp(&p0, &p1, sizeof p0) == 0 && o0 == o1 &&
                        memcmp(&s, &t, sizeof s) == 0, "differs at eta %g alpha %g", (double)e, (double)a);
        }
    }
    h_case("dispersion: bad input gives an invalid model, zero values, failed samples");
    {
        appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        appear_spectrum e = disp_eta(lam, 0);
        appear_dielectric_dispersive m;
        appear_bsdf_record s;
        appear_vec3 wo = appear_vec3_make(0, 0, 1), wi = appear_vec3_make(0, 0, -1);
        e.v[APPEAR_SPECTRUM_SAMPLES - 1] = NAN;
        m = appear_dielectric_make_dispersive(d, e);
        H_CHECK(!m.valid && appear_dielectric_dispersive_eval(&m, wo, wi).v[0] == 0.0f &&
                    appear_dielectric_dispersive_pdf(&m, wo, wi) == 0.0f &&
                    !appear_dielectric_dispersive_sample(&m, wo, 0.5f, 0.5f, 0.5f, &s) && s.flags == 0u,
                "a NaN eta");
    }
}
#endif

/* (its own suite: ./build/test_unit materials) */
void suite_materials(void)
{
    materials_generated();
    materials_metals();
    materials_rgb();
    materials_dielectrics();
    materials_bad_input();
#ifdef APPEAR_HAS_MICROFACET
    materials_dispersion();
#endif
    if (0) gm_report(stdout); /* the generator's report: ./build/gen_materials (stderr) */
}
#else
void suite_materials(void) {}
#endif
