/* tests/test_coated.c - the deterministic coat (appear.h SECTION coated) and appear_plastic:
     - exact cases: a smooth coat over a Lambertian base (appear_plastic) is the interfaced
       Lambertian [DEon16], lobe (1e-5 relative) and albedo (5e-5), absorbing coats
       included; a smooth coat over a smooth constant-F0 conductor is the geometric series
       F + T^2 R A^2 / (1 - F R A^2) (1e-5);
     - the pdf is the sampler's: int pdf = the success rate, mean weight = int f |cos| (4 se);
     - reciprocity in the reciprocal mode (the compensated coat lobe excepted: measured);
     - the white furnace: albedo <= 1 + 1e-3 for every coat and base in the grid below, and
       the albedo mode = 1 within 1e-3 over white lossless bases under clear coats;
     - fast against the reference walk (appear_layered with the multiple-scattering coat,
       the same base and absorption): directional albedo over coat roughness, bases (Lambert,
       EON, GGX gold), clear and absorbing coats, view angles, within the measured bounds (the
       1% goal of issue 32 where met); the largest differences printed with where they
       occur (full grid: bench/REPORT.md);
     - make() rejects bad coats, bases and colours; generic value = direct call. */
#include "harness.h"
#include "../appear.h"
#include "coated_grid.h"
#include <math.h>
#include <string.h>

#define PI_D 3.14159265358979323846

/* the interfaced Lambertian in double: f(wo, wi) and the internal round trip k_a */
static double co_ka(double eta, double tau)
{
    int i, n = 200000;
    double k = 0.0;
    for (i = 0; i < n; ++i) {
        double m = (i + 0.5) / n;
        k += h_fresnel_dielectric(m, 1.0 / eta) * exp(-2.0 * tau / m) * 2.0 * m / n;
    }
    return k;
}
static double co_elias_f(double mo, double mi, double eta, double rho, double tau, double ka)
{
    double to = 1.0 - h_fresnel_dielectric(mo, eta), ti = 1.0 - h_fresnel_dielectric(mi, eta);
    double mto = sqrt(1.0 - (1.0 - mo * mo) / (eta * eta)), mti = sqrt(1.0 - (1.0 - mi * mi) / (eta * eta));
    return to * ti * exp(-tau / mto - tau / mti) * rho / (PI_D * eta * eta * (1.0 - rho * ka));
}
/* mean sampler weight (channel c) and its se: h_sample_mean over appear_coated_sample */
static int co_sample(const void *m, appear_vec3 wo, float uc, float u1, float u2, appear_bsdf_record *s)
{
    return appear_coated_sample((const appear_coated *)m, wo, uc, u1, u2, s);
}
static double co_albedo(const appear_coated *m, appear_vec3 wo, long n, h_rng *r, int c, double *se, double *succ)
{
    return h_sample_mean(co_sample, m, wo, n, r, c, se, succ);
}

void suite_coated(void)
{
    h_rng hr = h_rng_make(4242u);
    int i, j, k, a;

    h_case("coated: smooth coat over Lambert = the interfaced Lambertian, lobe (1e-5) and albedo (5e-5)");
    {
        static const float etas[3] = { 1.3f, 1.5f, 2.0f }, rhos[3] = { 0.2f, 0.6f, 1.0f };
        static const double Cs[3] = { 1.0, 0.6, 0.2 };
        appear_microfacet sm = appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f, APPEAR_SAMPLE_VISIBLE);
        double lobe = 0, alb = 0;
        for (i = 0; i < 3; ++i)
            for (k = 0; k < 3; ++k) {
                double tau = -log(Cs[k]), ka = co_ka(etas[i], tau);
                for (j = 0; j < 3; ++j) {
                    appear_coated m = appear_plastic_make(sm, etas[i], appear_spectrum_splat(rhos[j]),
                                                          appear_spectrum_splat((float)Cs[k]));
                    for (a = 0; a < 6; ++a) {
                        double mo = 1.0 - a * 0.19, mi, q = 0;
                        appear_vec3 wo = h_dir_mu(mo, 0.0);
                        int t, u;
                        for (t = 0; t < 5; ++t) {
                            mi = 0.03 + 0.24 * t;
                            {
                                double f = appear_coated_eval(&m, wo, h_dir_mu(mi, 1.0 + t)).v[0];
                                double ref = co_elias_f(mo, mi, etas[i], rhos[j], tau, ka);
                                lobe = fmax(lobe, fabs(f - ref) / ref);
                            }
                        }
                        /* albedo: F + int f cos (midpoint in sqrt(cos): f is smooth) */
                        for (t = 0; t < 400; ++t) {
                            double x = (t + 0.5) / 400, c = x * x;
                            for (u = 0; u < 4; ++u)
                                q += appear_coated_eval(&m, wo, h_dir_mu(c, u * 1.5)).v[0] * c * 2.0 * x / 400 *
                                     2.0 * PI_D / 4;
                        }
                        q += h_fresnel_dielectric(mo, etas[i]);
                        {
                            double mto = sqrt(1.0 - (1.0 - mo * mo) / (etas[i] * etas[i])), te = 0;
                            int z;
                            for (z = 0; z < 20000; ++z) {
                                double mm = (z + 0.5) / 20000;
                                te += (1 - h_fresnel_dielectric(mm, 1.0 / etas[i])) * exp(-tau / mm) * 2 * mm / 20000;
                            }
                            alb = fmax(alb, fabs(q - (h_fresnel_dielectric(mo, etas[i]) + (1 - h_fresnel_dielectric(mo, etas[i])) *
                                                      exp(-tau / mto) * rhos[j] * te / (1 - rhos[j] * ka))));
                        }
                    }
                }
            }
        h_measure("plastic vs interfaced Lambertian", "smooth coat, 27 materials x 6 angles: lobe max relative "
                  "error %.2g, albedo max abs error %.2g", lobe, alb);
        H_CHECK(lobe < 1e-5 && alb < 5e-5, "lobe %.3g (bound 1e-5), albedo %.3g (bound 5e-5)", lobe, alb);
    }

    h_case("coated: smooth coat over a smooth constant-F0 conductor = geometric series (1e-5)");
    {
        appear_microfacet sm = appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f, APPEAR_SAMPLE_VISIBLE);
        static const float etas[3] = { 1.3f, 1.5f, 2.0f }, f0s[2] = { 0.5f, 1.0f };
        static const double Cs[2] = { 1.0, 0.4 };
        double worst = 0;
        for (i = 0; i < 3; ++i)
            for (j = 0; j < 2; ++j)
                for (k = 0; k < 2; ++k) {
                    appear_bsdf base = appear_bsdf_conductor(appear_conductor_make_reflectance(sm,
                                                                                               appear_spectrum_splat(f0s[j])));
                    appear_coated m = appear_coated_make(appear_dielectric_make(sm, etas[i]), &base,
                                                         appear_spectrum_splat((float)Cs[k]), APPEAR_COATED_RECIPROCAL);
                    for (a = 0; a < 5; ++a) {
                        double mu = 1.0 - a * 0.24, F = h_fresnel_dielectric(mu, etas[i]), T = 1 - F;
                        double mut = sqrt(1.0 - (1.0 - mu * mu) / (etas[i] * etas[i])), A2 = pow(Cs[k], 2.0 / mut);
                        double ref = F + T * T * f0s[j] * A2 / (1.0 - F * f0s[j] * A2), v = 0;
                        appear_bsdf_record r1, r2;
                        appear_vec3 wo = h_dir_mu(mu, 0.5);
                        /* both delta lobes: the coat's (uc = 0) and the base's (uc = 1) weighted by their
                           probabilities: the exact expectation of the sampler */
                        if (appear_coated_sample(&m, wo, 0.0f, 0.5f, 0.5f, &r1)) v += r1.weight.v[0] * r1.pdf;
                        if (appear_coated_sample(&m, wo, 1.0f, 0.5f, 0.5f, &r2)) v += r2.weight.v[0] * r2.pdf;
                        worst = fmax(worst, fabs(v - ref));
                        H_CHECK(fabs(v - ref) < 1e-5, "eta %.1f F0 %.1f C %.1f mu %.2f: %.7f, series %.7f", etas[i],
                                f0s[j], Cs[k], mu, v, ref);
                    }
                }
        h_measure("coated vs geometric series", "smooth coat over smooth conductor: max abs error %.2g", worst);
    }

    h_case("coated: int pdf = success rate, mean weight = int f |cos| (4 se), rough and smooth coats");
    {
        appear_microfacet c3 = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        appear_microfacet c0 = appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f, APPEAR_SAMPLE_VISIBLE);
        appear_microfacet b2 = appear_microfacet_make(APPEAR_GGX, 0.2f, 0.2f, APPEAR_SAMPLE_VISIBLE);
        appear_bsdf gold = appear_bsdf_conductor(appear_conductor_make(b2, appear_spectrum_rgb(0.18f, 0.42f, 1.37f),
                                                                       appear_spectrum_rgb(3.4f, 2.35f, 1.77f)));
        appear_bsdf eon = appear_bsdf_eon(appear_eon_make(appear_spectrum_rgb(0.8f, 0.5f, 0.3f), 0.6f));
        appear_coated ms[3];
        long n = h_n(200000);
        ms[0] = appear_coated_make(appear_dielectric_make(c3, 1.5f), &gold, appear_spectrum_splat(1.0f),
                                   APPEAR_COATED_RECIPROCAL);
        ms[1] = appear_coated_make(appear_dielectric_make(c0, 1.5f), &eon, appear_spectrum_rgb(0.9f, 0.7f, 0.5f),
                                   APPEAR_COATED_RECIPROCAL);
        ms[2] = appear_coated_make(appear_dielectric_make(c3, 1.8f), &eon, appear_spectrum_splat(1.0f),
                                   APPEAR_COATED_ALBEDO);
        for (i = 0; i < 3; ++i)
            for (a = 0; a < 3; ++a) {
                appear_vec3 wo = h_dir_mu(0.95 - 0.4 * a, 0.3);
                double se, succ, v = co_albedo(&ms[i], wo, n, &hr, 1, &se, &succ), ip = 0, ip2 = 0, ie = 0, ie2 = 0;
                double delta = ms[i].coat.smooth ? h_fresnel_dielectric(wo.z, 1.5) : 0.0, sp, sf;
                long q;
                for (q = 0; q < n; ++q) {   /* uniform hemisphere */
                    double z = h_rand(&hr), ph = 2 * PI_D * h_rand(&hr), p, f;
                    appear_vec3 wi = h_dir_mu(z, ph);
                    p = appear_coated_pdf(&ms[i], wo, wi) * 2 * PI_D;
                    f = appear_coated_eval(&ms[i], wo, wi).v[1] * z * 2 * PI_D;
                    ip += p; ip2 += p * p; ie += f; ie2 += f * f;
                }
                ip /= n; ie /= n;
                sp = sqrt(fmax(0, ip2 / n - ip * ip) / n);
                sf = sqrt(fmax(0, ie2 / n - ie * ie) / n);
                H_CHECK(fabs(ip - succ) < 4 * sqrt(sp * sp + succ * (1 - succ) / n) + 1e-4,
                        "model %d mu %.2f: int pdf %.5f +- %.2g, non-delta success rate %.5f", i, wo.z, ip, sp, succ);
                H_CHECK(fabs(ie + delta - v) < 4 * sqrt(se * se + sf * sf) + 1e-4,
                        "model %d mu %.2f: int f cos %.5f +- %.2g (+ delta %.4f), mean weight %.5f +- %.2g", i, wo.z,
                        ie, sf, delta, v, se);
            }
    }

    h_case("coated: reciprocity of the reciprocal mode (smooth coat: exact; rough: the coat lobe's measured)");
    {
        appear_microfacet c0 = appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f, APPEAR_SAMPLE_VISIBLE);
        appear_microfacet c3 = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        appear_microfacet b2 = appear_microfacet_make(APPEAR_GGX, 0.2f, 0.2f, APPEAR_SAMPLE_VISIBLE);
        appear_bsdf cond = appear_bsdf_conductor(appear_conductor_make(b2, appear_spectrum_splat(0.2f),
                                                                       appear_spectrum_splat(3.0f)));
        appear_bsdf eon = appear_bsdf_eon(appear_eon_make(appear_spectrum_splat(0.7f), 0.6f));
        appear_coated sm = appear_coated_make(appear_dielectric_make(c0, 1.5f), &cond, appear_spectrum_splat(0.7f),
                                              APPEAR_COATED_RECIPROCAL);
        appear_coated se = appear_coated_make(appear_dielectric_make(c0, 1.5f), &eon, appear_spectrum_splat(0.7f),
                                              APPEAR_COATED_RECIPROCAL);
        appear_coated ro = appear_coated_make(appear_dielectric_make(c3, 1.5f), &cond, appear_spectrum_splat(1.0f),
                                              APPEAR_COATED_RECIPROCAL);
        double worst = 0, rough = 0;
        for (i = 0; i < 2000; ++i) {
            double r1 = h_rand(&hr), r2 = h_rand(&hr), r3 = h_rand(&hr), r4 = h_rand(&hr);
            appear_vec3 u = h_dir_mu(0.02 + 0.98 * r1, 2 * PI_D * r2), v = h_dir_mu(0.02 + 0.98 * r3, 2 * PI_D * r4);
            double x1 = appear_coated_eval(&sm, u, v).v[0], y1 = appear_coated_eval(&sm, v, u).v[0];
            double x2 = appear_coated_eval(&se, u, v).v[0], y2 = appear_coated_eval(&se, v, u).v[0];
            double x3 = appear_coated_eval(&ro, u, v).v[0], y3 = appear_coated_eval(&ro, v, u).v[0];
            if (x1 > 1e-6) worst = fmax(worst, fabs(x1 - y1) / x1);
            if (x2 > 1e-6) worst = fmax(worst, fabs(x2 - y2) / x2);
            if (x3 > 1e-3) rough = fmax(rough, fabs(x3 - y3) / x3);
        }
        h_measure("coated reciprocity", "smooth coat (conductor, EON bases): max |f(wo,wi) - f(wi,wo)| / f %.2g; "
                  "rough coat 0.3 over a conductor: %.3g (the compensated coat lobe's 1 / E(mu_o))", worst, rough);
        H_CHECK(worst < 1e-5, "smooth coat: relative asymmetry %.3g", worst);
    }

    h_case("coated: white furnace: albedo mode = 1 within 1e-3 over every lossless white base (escape tables, "
           "the closed forms); reciprocal mode <= 1 + 1e-3 over Lambert, elsewhere within its measured bound");
    {
        static const float alphas[5] = { 0.0f, 0.05f, 0.2f, 0.5f, 1.0f }, etas[3] = { 1.3f, 1.5f, 2.0f };
        static const float balph[3] = { 0.05f, 0.2f, 0.8f };
        static const char *bname[5] = { "white Lambert", "white EON sigma 1", "white comp conductor 0.05",
                                        "white comp conductor 0.2", "white comp conductor 0.8" };
        double worst[2][5], low[5];
        long n = h_n(20000);
        int b, mode;
        for (mode = 0; mode < 2; ++mode)
            for (b = 0; b < 5; ++b) {
                worst[mode][b] = -1.0;
                low[b] = 2.0;
                for (i = 0; i < 5; ++i)
                    for (j = 0; j < 3; ++j) {
                        appear_microfacet d = appear_microfacet_make(APPEAR_GGX, alphas[i], alphas[i],
                                                                     APPEAR_SAMPLE_VISIBLE);
                        appear_bsdf base;
                        appear_coated m;
                        if (b == 0) base = appear_bsdf_lambert(appear_lambert_make(appear_spectrum_splat(1.0f)));
                        else if (b == 1) base = appear_bsdf_eon(appear_eon_make(appear_spectrum_splat(1.0f), 1.0f));
                        else base = appear_bsdf_conductor_comp(appear_conductor_make_reflectance(
                            appear_microfacet_make(APPEAR_GGX, balph[b - 2], balph[b - 2], APPEAR_SAMPLE_VISIBLE),
                            appear_spectrum_splat(1.0f)));
                        m = appear_coated_make(appear_dielectric_make(d, etas[j]), &base, appear_spectrum_splat(1.0f),
                                               mode ? APPEAR_COATED_ALBEDO : APPEAR_COATED_RECIPROCAL);
                        for (a = 0; a < 9; ++a) {
                            double mu = 1.0 - a * 0.1225, se, v = co_albedo(&m, h_dir_mu(mu, 0.0), n, &hr, 0, &se, NULL);
                            worst[mode][b] = fmax(worst[mode][b], v - 4 * se);
                            if (mode) {
                                /* lossless by construction: a white base under a clear coat keeps all */
                                low[b] = fmin(low[b], v + 4 * se);
                                H_CHECK(v + 4 * se > 1.0 - 1e-3, "albedo mode, %s, coat alpha %.2f eta %.1f, mu %.2f: "
                                        "albedo %.5f +- %.2g below 1 - 1e-3", bname[b], alphas[i], etas[j], mu, v, se);
                            }
                            /* the bounds: 1e-3 where the form conserves energy by construction (the albedo
                               mode; the reciprocal mode over Lambert), else the reciprocal mode's measured
                               excess (white EON 1.0036, glossy bases 1.025: README) plus margin */
                            H_CHECK(v - 4 * se < 1.0 + (mode || b == 0 ? 1e-3 : b == 1 ? 8e-3 : 4e-2),
                                    "%s mode, %s, coat alpha %.2f eta %.1f, mu %.2f: albedo %.5f +- %.2g",
                                    mode ? "albedo" : "reciprocal", bname[b], alphas[i], etas[j], mu, v, se);
                        }
                    }
            }
        for (b = 0; b < 5; ++b)
            h_measure("coated furnace", "%s: largest albedo - 4 se over coat alpha 0 .. 1, eta 1.3 .. 2, 9 angles: "
                      "reciprocal mode %.5f, albedo mode %.5f (smallest + 4 se %.5f)", bname[b], worst[0][b],
                      worst[1][b], low[b]);
    }

    h_case("coated: fast vs the reference walk: directional albedo within the measured bounds (1%% goal: "
           "README)");
    {
        static const float alphas[3] = { 0.0f, 0.2f, 1.0f };
        static const double mus[3] = { 1.0, 0.5, 0.15 };
        /* [category] = clear / absorbing coats over diffuse bases, over gold, over compensated
           gold: the 1% goal of issue 32 (diffuse and gold: the grid's GGX conductors), the
           compensated metal's measured largest plus margin (README "Layered"; the whole grid at
           300000 samples, bench/REPORT.md). Over gold the escape's series ratio k is read at the
           base's reflectance per bounce since 2026-12-06 (one k fitted at 0.8 left 1.5%) */
        static const double bound[6] = { 0.01, 0.01, 0.01, 0.01, 0.025, 0.015 };
        static const char *cat[6] = { "clear coat / diffuse base", "absorbing coat / diffuse base",
                                      "clear coat / gold", "absorbing coat / gold",
                                      "clear coat / compensated gold", "absorbing coat / compensated gold" };
        appear_spectrum colors[2];
        double worst[6] = { 0, 0, 0, 0, 0, 0 }, wl1 = 0;
        char where[6][160];
        long n = h_n(20000);
        int b, c, q;
        colors[0] = appear_spectrum_splat(1.0f);
        colors[1] = appear_spectrum_rgb(0.9f, 0.6f, 0.3f);
        for (q = 0; q < 6; ++q) where[q][0] = 0;
        for (b = 0; b < CG_NBASES; ++b)
            for (i = 0; i < 3; ++i)
                for (c = 0; c < 2; ++c)
                    for (a = 0; a < 3; ++a) {
                        cg_result r = cg_compare(b, alphas[i], 1.5f, colors[c], mus[a], n,
                                                 1000u + (unsigned)(b * 100 + i * 10 + a));
                        double e = fabs(r.fast - r.ref);
                        q = (b >= 2 ? b >= 5 ? 4 : 2 : 0) + c; /* cg_base: 0, 1 diffuse, 2-4 gold, 5, 6 comp */
                        wl1 = fmax(wl1, r.l1);
                        if (e > worst[q]) {
                            worst[q] = e;
                            snprintf(where[q], sizeof where[q], "%s, coat alpha %.2f, mu %.2f: fast %.4f, walk %.4f "
                                     "+- %.4f", cg_base_name(b), alphas[i], mus[a], r.fast, r.ref, r.ref_se);
                        }
                        H_CHECK(e < bound[q] + 3 * r.ref_se, "%s: %s, coat alpha %.2f, mu %.2f: fast %.4f, walk %.4f "
                                "+- %.4f (bound %g)", cat[q], cg_base_name(b), alphas[i], mus[a], r.fast, r.ref,
                                r.ref_se, bound[q]);
                    }
        for (q = 0; q < 6; ++q)
            h_measure("coated vs walk", "%s: largest |albedo fast - walk| %.4f (%s)", cat[q], worst[q], where[q]);
        h_measure("coated vs walk", "largest lobe L1 (16 x 32 histogram of f |cos|, relative) %.3f", wl1);
    }

    h_case("coated: eval's lean path over a Lambertian base (appear__coated_eval_lean) gives the general "
           "path's bits, and the sampler's record holds them");
    {
        /* m->lean 1: the reciprocal mode (appear_plastic) under clear coats; 2: the albedo mode's escape
           (a rough coat); 0: absorbing plastics, a smooth coat in the albedo mode. Channels of R = 0 and
           1, coats smooth to alpha 1, grazing and random directions on both sides. */
        static const struct { float alpha, eta, r0, c; int mode, lean; } rows[] = {
            { 0.1f, 1.5f, 0.8f, 1.0f, APPEAR_COATED_RECIPROCAL, 1 }, { 0.0f, 1.5f, 0.5f, 1.0f, APPEAR_COATED_RECIPROCAL, 1 },
            { 1.0f, 2.0f, 1.0f, 1.0f, APPEAR_COATED_RECIPROCAL, 1 }, { 0.02f, 1.3f, 0.0f, 1.0f, APPEAR_COATED_RECIPROCAL, 1 },
            { 0.1f, 1.5f, 0.8f, 0.6f, APPEAR_COATED_RECIPROCAL, 0 }, { 0.1f, 1.5f, 0.8f, 1.0f, APPEAR_COATED_ALBEDO, 2 },
            { 0.5f, 3.0f, 0.0f, 0.4f, APPEAR_COATED_ALBEDO, 2 },     { 1e-4f, 1.1f, 1.0f, 1.0f, APPEAR_COATED_ALBEDO, 2 },
            { 0.0f, 1.5f, 0.8f, 1.0f, APPEAR_COATED_ALBEDO, 0 } };
        long bad = 0, recs = 0, rbad = 0;
        for (k = 0; k < (int)(sizeof rows / sizeof rows[0]); ++k) {
            appear_microfacet d = appear_microfacet_make(APPEAR_GGX, rows[k].alpha, rows[k].alpha, APPEAR_SAMPLE_VISIBLE);
            appear_bsdf lam = appear_bsdf_lambert(appear_lambert_make(appear_spectrum_rgb(rows[k].r0, 0.3f, 1.0f)));
            appear_coated m = appear_coated_make(appear_dielectric_make(d, rows[k].eta), &lam,
                                                 appear_spectrum_rgb(1.0f, rows[k].c, 1.0f), rows[k].mode);
            appear_coated g = m;
            g.lean = 0; /* the general path */
            H_CHECK(m.valid && m.lean == rows[k].lean, "row %d: lean %d, expected %d", k, m.lean, rows[k].lean);
            for (i = 0; i < h_n(20000); ++i) {
                appear_vec3 wo = i % 7 == 0 ? h_dir_mu(1e-6 * (i % 5), 0.3 * i) : h_rand_dir(&hr), wi = h_rand_dir(&hr);
                appear_spectrum f1 = appear_coated_eval(&m, wo, wi), f2 = appear_coated_eval(&g, wo, wi);
                appear_bsdf_record s;
                float uc = h_randf(&hr), u1 = h_randf(&hr), u2 = h_randf(&hr);
                bad += memcmp(&f1, &f2, sizeof f1) != 0;
                if (appear_coated_sample(&m, wo, uc, u1, u2, &s) &&
                    !(s.flags & APPEAR_LOBE_SPECULAR)) { /* the record's f is the general path's */
                    f1 = appear_coated_eval(&m, wo, s.wi);
                    recs++;
                    rbad += memcmp(&f1, &s.f, sizeof f1) != 0;
                }
            }
        }
        H_CHECK(bad == 0 && rbad == 0, "lean eval differs from the general path at %ld points, from the sampler's "
                "record at %ld of %ld", bad, rbad, recs);
    }

    h_case("coated: make() rejects bad coats, bases, colours; the generic value is the direct call");
    {
        appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.2f, 0.2f, APPEAR_SAMPLE_VISIBLE);
        appear_bsdf lam = cg_base(0), bad = appear_bsdf_lambert(appear_lambert_make(appear_spectrum_splat(-1.0f)));
        appear_spectrum w = appear_spectrum_splat(1.0f), c0 = w, cn = w;
        appear_coated m;
        appear_bsdf g;
        appear_bsdf_record s1, s2;
        appear_vec3 wo = h_dir_mu(0.6, 0.2), wi = h_dir_mu(0.3, 2.0);
        c0.v[1] = 0.0f;
        cn.v[2] = appear__u2f(APPEAR__NAN_BITS);
        H_CHECK(!appear_coated_make(appear_dielectric_make(d, 0.8f), &lam, w, 0).valid, "eta 0.8 accepted");
        H_CHECK(!appear_coated_make(appear_dielectric_make(d, 3.5f), &lam, w, 0).valid, "eta 3.5 accepted");
        H_CHECK(!appear_coated_make(appear_dielectric_make(d, 1.5f), &bad, w, 0).valid, "an invalid base accepted");
        H_CHECK(!appear_coated_make(appear_dielectric_make(d, 1.5f), &lam, c0, 0).valid, "colour 0 accepted");
        m = appear_coated_make(appear_dielectric_make(d, 1.5f), &lam, cn, 0);
        H_CHECK(!m.valid && appear_coated_flags(&m) == 0u && appear_coated_eval(&m, wo, wi).v[0] == 0.0f &&
                appear_coated_pdf(&m, wo, wi) == 0.0f && !appear_coated_sample(&m, wo, 0.5f, 0.5f, 0.5f, &s1) &&
                s1.flags == 0u, "a NaN colour accepted, or an invalid model answered");
        m = appear_coated_make(appear_dielectric_make(d, 1.5f), &lam, appear_spectrum_rgb(0.9f, 0.5f, 0.2f), 0);
        g = appear_bsdf_coated(&m);
        {
            appear_spectrum f1 = appear_coated_eval(&m, wo, wi), f2 = appear_bsdf_eval(&g, wo, wi);
            float p1 = appear_coated_pdf(&m, wo, wi), p2 = appear_bsdf_pdf(&g, wo, wi);
            int o1 = appear_coated_sample(&m, wo, 0.7f, 0.2f, 0.9f, &s1), o2 = appear_bsdf_sample(&g, wo, 0.7f, 0.2f, 0.9f, &s2);
            H_CHECK(memcmp(&f1, &f2, sizeof f1) == 0 && p1 == p2 && o1 == o2 && memcmp(&s1, &s2, sizeof s1) == 0,
                    "generic differs from direct");
            H_CHECK(appear_bsdf_flags(&g) == (APPEAR_LOBE_REFLECTION | APPEAR_LOBE_GLOSSY | APPEAR_LOBE_DIFFUSE),
                    "flags %#x", appear_bsdf_flags(&g));
        }
    }
}
