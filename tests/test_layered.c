/* tests/test_layered.c - the layered reference (appear.h SECTION layered, the position-free
   random walk of [Guo18]) against closed forms and against itself:
     - a smooth coat over a Lambertian base with an absorbing slab: the interfaced Lambertian
       [DEon16], F_o + T_o A_o rho t_e / (1 - rho k_a) with the
       internal escape t_e and return k_a integrated in double; the sampler's mean weight
       within 4 se over eta 1.3 .. 2, rho 0.2 .. 1, slab transmittance 1 .. 0.1, 4 angles;
     - a smooth coat over a smooth conductor: the geometric series F + T^2 R A^2 / (1 - F R A^2)
       at the refracted angle (every path is a delta path);
     - a smooth coat over a smooth dielectric base that leads back to air: a thin sheet,
       R = 2F / (1 + F), T = (1 - F) / (1 + F) (appear_thin_dielectric's closed form);
     - eval against the sampler: int eval |cos| (cosine-weighted Monte Carlo) equals the
       sampler's mean weight within 4 combined se, for rough coats, a scattering slab and a
       transmitting base; the pdf integrates to the sampler's success rate and matches its
       histogram over 6 bands of cos theta_i (4 se);
     - reciprocity f(wo, wi) = f(wi, wo) (4 se) where the model is reciprocal;
     - the white furnace: a white Lambert base under a clear smooth coat reflects 1 (4 se), a
       layered material as the base of another one too; nothing exceeds 1 + 1e-3;
     - the same rng state gives the same bits; the generic value gives the direct call's bits;
     - make() rejects bad parts and slabs; every call of an invalid model is 0 / failure. */
#include "harness.h"
#include "../appear.h"
#include <math.h>
#include <string.h>

#define PI_D 3.14159265358979323846

/* smooth coat eta over Lambert rho, absorbing slab of normal optical depth tau, in double */
static double ly_elias(double mu, double eta, double rho, double tau)
{
    int i, n = 20000;
    double te = 0.0, ka = 0.0, fo, mut, ao;
    for (i = 0; i < n; ++i) {          /* midpoint rule in mu = cos inside, weight 2 mu */
        double m = (i + 0.5) / n, a = exp(-tau / m), f = h_fresnel_dielectric(m, 1.0 / eta);
        te += (1.0 - f) * a * 2.0 * m / n;
        ka += f * a * a * 2.0 * m / n;
    }
    fo = h_fresnel_dielectric(mu, eta);
    mut = sqrt(1.0 - (1.0 - mu * mu) / (eta * eta));
    ao = exp(-tau / mut);
    return fo + (1.0 - fo) * ao * rho * te / (1.0 - rho * ka);
}
static appear_bsdf ly_coat(float alpha, float eta)
{
    appear_microfacet d = appear_microfacet_make(APPEAR_GGX, alpha, alpha, APPEAR_SAMPLE_VISIBLE);
    return appear_bsdf_dielectric(appear_dielectric_make(d, eta));
}
static appear_bsdf ly_lambert(float rho)
{ return appear_bsdf_lambert(appear_lambert_make(appear_spectrum_splat(rho))); }
static appear_slab ly_absorber(double T)
{ return appear_slab_from_transmittance(appear_spectrum_splat((float)T), appear_spectrum_splat(0.0f), 0.0f); }

/* the sampler's mean weight (channel 0) and its standard error; *succ: the fraction of
   non-delta successes (what the pdf integrates to) */
static double ly_albedo(const appear_layered *m, appear_vec3 wo, long n, appear_rng *rng, double *se, double *succ)
{
    double s = 0.0, s2 = 0.0, ok = 0.0, mean;
    long i;
    for (i = 0; i < n; ++i) {
        appear_bsdf_record r;
        double w = 0.0;
        if (appear_layered_sample(m, wo, rng, &r)) {
            w = r.weight.v[0];
            ok += (r.flags & APPEAR_LOBE_SPECULAR) ? 0.0 : 1.0;
        }
        s += w; s2 += w * w;
    }
    mean = s / n;
    *se = sqrt(fmax(0.0, s2 / n - mean * mean) / n);
    if (succ) *succ = ok / n;
    return mean;
}
/* int eval |cos| over the sphere by cosine-weighted Monte Carlo on both hemispheres */
static double ly_eval_albedo(const appear_layered *m, appear_vec3 wo, long n, appear_rng *rng, int both, double *se)
{
    double s = 0.0, s2 = 0.0, mean;
    long i;
    for (i = 0; i < n; ++i) {
        float u1 = appear_rng_next(rng), u2 = appear_rng_next(rng), u3 = appear_rng_next(rng);
        appear_vec3 wi = h_dir_mu(sqrt(1.0 - u1), 2.0 * PI_D * u2);
        double v;
        if (both && u3 < 0.5f) wi.z = -wi.z;
        v = appear_layered_eval(m, wo, wi, rng).v[0] * PI_D * (both ? 2.0 : 1.0);
        s += v; s2 += v * v;
    }
    mean = s / n;
    *se = sqrt(fmax(0.0, s2 / n - mean * mean) / n);
    return mean;
}

void suite_layered(void)
{
    appear_rng rng = appear_rng_make(12345u);
    int i, j, k, a;

    h_case("layered: smooth coat over Lambert with an absorbing slab = interfaced Lambertian (4 se)");
    {
        static const float etas[3] = { 1.3f, 1.5f, 2.0f }, rhos[3] = { 0.2f, 0.6f, 1.0f };
        static const double Ts[3] = { 1.0, 0.5, 0.1 }, mus[4] = { 1.0, 0.6, 0.25, 0.08 };
        long n = h_n(1000000); /* issue 32's 10^6 (full mode) */
        double zmax = 0.0, seworst = 0.0;
        for (i = 0; i < 3; ++i)
            for (j = 0; j < 3; ++j)
                for (k = 0; k < 3; ++k) {
                    appear_bsdf top = ly_coat(0.0f, etas[i]), base = ly_lambert(rhos[j]);
                    appear_layered m = appear_layered_make(&top, &base, ly_absorber(Ts[k]), 1, 256);
                    for (a = 0; a < 4; ++a) {
                        double se, v = ly_albedo(&m, h_dir_mu(mus[a], 0.3), n, &rng, &se, APPEAR__NULL);
                        double ref = ly_elias(mus[a], etas[i], rhos[j], -log(Ts[k])), z = fabs(v - ref) / (se + 1e-7);
                        zmax = fmax(zmax, z); seworst = fmax(seworst, se);
                        H_CHECK(fabs(v - ref) < 4.0 * se + 1e-6, "eta %.2f rho %.2f T %.2f mu %.2f: walk %.5f +- %.5f, closed form %.5f",
                                etas[i], rhos[j], Ts[k], mus[a], v, se, ref);
                    }
                }
        h_measure("layered vs interfaced Lambertian", "108 points, %ld walks each: largest |walk - closed "
                  "form| / (se + 1e-7) %.2f (se at most %.2g; white and clear: every weight is 1)", n, zmax, seworst);
    }

    h_case("layered: smooth coat over a smooth conductor = geometric series (delta paths)");
    {
        static const float etas[3] = { 1.3f, 1.5f, 2.0f };
        static const double mus[3] = { 1.0, 0.5, 0.1 }, Ts[2] = { 1.0, 0.3 };
        long n = h_n(1000000);
        appear_microfacet ds = appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f, APPEAR_SAMPLE_VISIBLE);
        appear_bsdf base = appear_bsdf_conductor(appear_conductor_make(ds, appear_spectrum_splat(0.2f),
                                                                       appear_spectrum_splat(3.0f)));
        for (i = 0; i < 3; ++i)
            for (k = 0; k < 2; ++k)
                for (a = 0; a < 3; ++a) {
                    appear_bsdf top = ly_coat(0.0f, etas[i]);
                    appear_layered m = appear_layered_make(&top, &base, ly_absorber(Ts[k]), 1, 256);
                    double mu = mus[a], mut = sqrt(1.0 - (1.0 - mu * mu) / ((double)etas[i] * etas[i]));
                    double F = h_fresnel_dielectric(mu, etas[i]), T = 1.0 - F, A2 = pow(Ts[k], 2.0 / mut);
                    double Rb = appear_fresnel_conductor((float)mut, 0.2f, 3.0f);
                    double ref = F + T * T * Rb * A2 / (1.0 - F * Rb * A2), se;
                    double v = ly_albedo(&m, h_dir_mu(mu, 0.0), n, &rng, &se, APPEAR__NULL);
                    H_CHECK(fabs(v - ref) < 4.0 * se + 1e-5, "eta %.2f T %.2f mu %.2f: walk %.6f +- %.2g, series %.6f",
                            etas[i], Ts[k], mu, v, se, ref);
                }
    }

    h_case("layered: smooth coat over a smooth dielectric back to air = thin sheet, R and T (4 se)");
    {
        static const float etas[2] = { 1.5f, 2.0f };
        static const double mus[3] = { 1.0, 0.5, 0.1 };
        long n = h_n(100000);
        for (i = 0; i < 2; ++i) {
            appear_bsdf top = ly_coat(0.0f, etas[i]), base = ly_coat(0.0f, 1.0f / etas[i]);
            appear_layered m = appear_layered_make(&top, &base, appear_slab_none(), 1, 256);
            for (a = 0; a < 3; ++a) {
                double sr = 0, sr2 = 0, st = 0, st2 = 0, F = h_fresnel_dielectric(mus[a], etas[i]);
                long q;
                for (q = 0; q < n; ++q) {
                    appear_bsdf_record r;
                    double w = appear_layered_sample(&m, h_dir_mu(mus[a], 0.0), &rng, &r) ? r.weight.v[0] : 0.0;
                    if (r.wi.z > 0) { sr += w; sr2 += w * w; } else { st += w; st2 += w * w; }
                }
                sr /= n; st /= n;
                {
                    double ser = sqrt(fmax(0, sr2 / n - sr * sr) / n), sett = sqrt(fmax(0, st2 / n - st * st) / n);
                    H_CHECK(fabs(sr - 2 * F / (1 + F)) < 4 * ser + 1e-5 && fabs(st - (1 - F) / (1 + F)) < 4 * sett + 1e-5,
                            "eta %.1f mu %.2f: R %.5f (sheet %.5f), T %.5f (sheet %.5f)", etas[i], mus[a], sr,
                            2 * F / (1 + F), st, (1 - F) / (1 + F));
                }
            }
        }
    }

    h_case("layered: int eval |cos| = the sampler's mean weight (4 combined se)");
    {
        /* rough coats over Lambert and a rough conductor, a scattering slab, a transmitting base */
        appear_microfacet d3 = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        appear_bsdf cond = appear_bsdf_conductor(appear_conductor_make(d3, appear_spectrum_splat(0.2f),
                                                                       appear_spectrum_splat(3.0f)));
        appear_bsdf top3 = ly_coat(0.3f, 1.5f), top1 = ly_coat(0.1f, 1.5f), tops = ly_coat(0.0f, 1.5f);
        appear_bsdf lam = ly_lambert(0.7f), glass = ly_coat(0.2f, 1.0f / 1.5f);
        appear_slab fog = appear_slab_make(1.0f, appear_spectrum_rgb(1.0f, 0.5f, 2.0f),
                                           appear_spectrum_rgb(0.9f, 0.8f, 0.95f), 0.6f);
        struct { const char *name; const appear_bsdf *top, *base; appear_slab slab; int both; } rows[] = {
            { "rough 0.3 coat / Lambert", &top3, &lam, appear_slab_none(), 0 },
            { "rough 0.1 coat / rough conductor", &top1, &cond, ly_absorber(0.6), 0 },
            { "smooth coat / rough conductor", &tops, &cond, appear_slab_none(), 0 },
            { "smooth coat / Lambert, scattering slab", &tops, &lam, fog, 0 },
            { "rough coat / scattering slab / rough glass", &top3, &glass, fog, 1 },
        };
        static const double mus[3] = { 0.9, 0.45, 0.15 };
        long n = h_n(100000);
        for (i = 0; i < (int)(sizeof rows / sizeof rows[0]); ++i) {
            appear_layered m = appear_layered_make(rows[i].top, rows[i].base, rows[i].slab, 1, 256);
            for (a = 0; a < 3; ++a) {
                appear_vec3 wo = h_dir_mu(mus[a], 0.2);
                double se1, se2, v1 = ly_albedo(&m, wo, n, &rng, &se1, APPEAR__NULL), v2, delta = 0.0;
                /* the smooth coat's delta reflection is in the sampler, not in eval */
                if (rows[i].top == &tops) delta = h_fresnel_dielectric(mus[a], 1.5);
                v2 = ly_eval_albedo(&m, wo, n, &rng, rows[i].both, &se2) + delta;
                H_CHECK(fabs(v1 - v2) < 4.0 * sqrt(se1 * se1 + se2 * se2), "%s, mu %.2f: sampler %.5f +- %.5f, "
                        "int eval %.5f +- %.5f", rows[i].name, mus[a], v1, se1, v2, se2);
            }
        }
    }

    h_case("layered: the pdf estimate integrates to the success rate and matches the histogram (4 se)");
    {
        appear_bsdf top3 = ly_coat(0.3f, 1.5f), tops = ly_coat(0.0f, 1.5f), lam = ly_lambert(0.7f);
        appear_slab fog = appear_slab_make(1.0f, appear_spectrum_splat(1.0f), appear_spectrum_splat(0.9f), 0.6f);
        struct { const char *name; const appear_bsdf *top; appear_slab slab; } rows[] = {
            { "rough coat / Lambert", &top3, appear_slab_none() },
            { "smooth coat / scattering slab / Lambert", &tops, fog },
        };
        long n = h_n(200000);
        for (i = 0; i < 2; ++i) {
            appear_layered m = appear_layered_make(rows[i].top, &lam, rows[i].slab, 1, 256);
            appear_vec3 wo = h_dir_mu(0.6, 0.0);
            double hist[6] = { 0 }, ph[6] = { 0 }, ph2[6] = { 0 };
            long q;
            /* histogram of the non-delta samples over 6 bands of cos theta_i */
            for (q = 0; q < n; ++q) {
                appear_bsdf_record r;
                if (appear_layered_sample(&m, wo, &rng, &r) && !(r.flags & APPEAR_LOBE_SPECULAR))
                    hist[(int)fmin(5.0, r.wi.z * 6.0)] += 1.0 / n;
            }
            /* the pdf over each band, uniform sampling of the band */
            for (q = 0; q < n; ++q) {
                int b = (int)(q % 6);
                double c = (b + appear_rng_next(&rng)) / 6.0, v;
                appear_vec3 wi = h_dir_mu(c, 2.0 * PI_D * appear_rng_next(&rng));
                v = appear_layered_pdf(&m, wo, wi, &rng) * 2.0 * PI_D / 6.0;
                ph[b] += v; ph2[b] += v * v;
            }
            for (j = 0; j < 6; ++j) {
                double nb = (double)n / 6.0, mean = ph[j] / nb, se = sqrt(fmax(0, ph2[j] / nb - mean * mean) / nb);
                double seh = sqrt(hist[j] * (1.0 - hist[j]) / n);
                H_CHECK(fabs(mean - hist[j]) < 4.0 * sqrt(se * se + seh * seh), "%s: cos band %d: int pdf %.5f +- "
                        "%.5f, histogram %.5f +- %.5f", rows[i].name, j, mean, se, hist[j], seh);
            }
        }
    }

    h_case("layered: reciprocity f(wo, wi) = f(wi, wo) (4 se) for a rough coat over Lambert and a slab");
    {
        appear_bsdf top = ly_coat(0.25f, 1.6f), lam = ly_lambert(0.8f);
        appear_slab fog = appear_slab_make(1.0f, appear_spectrum_splat(0.7f), appear_spectrum_splat(0.8f), 0.3f);
        appear_layered m = appear_layered_make(&top, &lam, fog, 1, 256);
        static const double pairs[3][4] = { { 0.9, 0.0, 0.3, 2.0 }, { 0.5, 1.0, 0.2, 1.5 }, { 0.15, 0.0, 0.7, 3.0 } };
        long n = h_n(40000);
        for (i = 0; i < 3; ++i) {
            appear_vec3 u = h_dir_mu(pairs[i][0], pairs[i][1]), v = h_dir_mu(pairs[i][2], pairs[i][3]);
            double s1 = 0, q1 = 0, s2 = 0, q2 = 0, se;
            long q;
            for (q = 0; q < n; ++q) {
                double x = appear_layered_eval(&m, u, v, &rng).v[0], y = appear_layered_eval(&m, v, u, &rng).v[0];
                s1 += x; q1 += x * x; s2 += y; q2 += y * y;
            }
            s1 /= n; s2 /= n;
            se = sqrt((fmax(0, q1 / n - s1 * s1) + fmax(0, q2 / n - s2 * s2)) / n);
            H_CHECK(fabs(s1 - s2) < 4.0 * se, "pair %d: f(wo, wi) %.5f, f(wi, wo) %.5f, se %.2g", i, s1, s2, se);
        }
    }

    h_case("layered: white furnace: clear smooth coat over white Lambert = 1, also nested; rough <= 1 + 1e-3");
    {
        appear_microfacet d6 = appear_microfacet_make(APPEAR_GGX, 0.6f, 0.6f, APPEAR_SAMPLE_VISIBLE);
        appear_bsdf white = ly_lambert(1.0f), smooth = ly_coat(0.0f, 1.5f), rough = ly_coat(0.6f, 1.5f);
        appear_bsdf smooth2 = ly_coat(0.0f, 1.3f);
        appear_bsdf comp = appear_bsdf_dielectric_comp(appear_dielectric_make(d6, 1.5f));
        appear_layered inner = appear_layered_make(&smooth, &white, appear_slab_none(), 1, 256);
        appear_bsdf innerb = appear_bsdf_layered(&inner, &rng);
        appear_layered outer = appear_layered_make(&smooth2, &innerb, appear_slab_none(), 1, 256);
        appear_slab cloud = appear_slab_make(1.0f, appear_spectrum_splat(2.0f), appear_spectrum_splat(1.0f), 0.5f);
        appear_layered sc = appear_layered_make(&smooth, &white, cloud, 1, 256);
        appear_layered ro = appear_layered_make(&rough, &white, appear_slab_none(), 1, 256);
        appear_layered co = appear_layered_make(&comp, &white, appear_slab_none(), 1, 256);
        static const double mus[4] = { 1.0, 0.5, 0.2, 0.05 };
        long n = h_n(50000);
        double lossmax = 0, cdev = 0;
        for (a = 0; a < 4; ++a) {
            appear_vec3 wo = h_dir_mu(mus[a], 0.0);
            double se, v = ly_albedo(&outer, wo, n, &rng, &se, APPEAR__NULL);
            H_CHECK(fabs(v - 1.0) < 4.0 * se + 1e-4, "nested clear coats, mu %.2f: %.5f +- %.2g", mus[a], v, se);
            v = ly_albedo(&sc, wo, n, &rng, &se, APPEAR__NULL);
            H_CHECK(fabs(v - 1.0) < 4.0 * se + 1e-4, "white scattering slab, mu %.2f: %.5f +- %.2g", mus[a], v, se);
            v = ly_albedo(&ro, wo, n, &rng, &se, APPEAR__NULL);
            H_CHECK(v < 1.0 + 1e-3 + 4.0 * se, "rough coat, mu %.2f: %.5f +- %.2g", mus[a], v, se);
            lossmax = fmax(lossmax, 1.0 - v);
            v = ly_albedo(&co, wo, n, &rng, &se, APPEAR__NULL);
            H_CHECK(fabs(v - 1.0) < 1e-2 + 4.0 * se, "compensated rough coat, mu %.2f: %.5f +- %.2g", mus[a], v, se);
            cdev = fmax(cdev, fabs(v - 1.0));
        }
        h_measure("layered furnace", "white Lambert under GGX 0.6, eta 1.5: single-scattering coat loses up to "
                  "%.4f; the compensated coat (_comp) is within %.4f of 1 (its table's error and the walks' noise)",
                  lossmax, cdev);
    }

    h_case("layered: same rng state, same bits; the generic value is the direct call");
    {
        appear_bsdf top = ly_coat(0.3f, 1.5f), lam = ly_lambert(0.5f);
        appear_layered m = appear_layered_make(&top, &lam, ly_absorber(0.5), 4, 64);
        appear_rng r1 = appear_rng_make(99u), r2 = appear_rng_make(99u);
        appear_bsdf g = appear_bsdf_layered(&m, &r2);
        appear_vec3 wo = h_dir_mu(0.7, 0.1), wi = h_dir_mu(0.4, 2.0);
        appear_bsdf_record s1, s2;
        appear_spectrum f1 = appear_layered_eval(&m, wo, wi, &r1), f2 = appear_bsdf_eval(&g, wo, wi);
        float p1 = appear_layered_pdf(&m, wo, wi, &r1), p2 = appear_bsdf_pdf(&g, wo, wi);
        int o1 = appear_layered_sample(&m, wo, &r1, &s1), o2 = appear_bsdf_sample(&g, wo, 0.5f, 0.5f, 0.5f, &s2);
        H_CHECK(memcmp(&f1, &f2, sizeof f1) == 0 && memcmp(&p1, &p2, sizeof p1) == 0 && o1 == o2 &&
                memcmp(&s1, &s2, sizeof s1) == 0 && r1.state == r2.state, "generic differs from direct");
        H_CHECK(appear_bsdf_flags(&g) == (APPEAR_LOBE_REFLECTION | APPEAR_LOBE_GLOSSY | APPEAR_LOBE_DIFFUSE |
                                          APPEAR_MODEL_STOCHASTIC), "flags %#x", appear_bsdf_flags(&g));
    }

    h_case("layered: make() rejects bad parts and slabs; invalid models answer 0 / failure");
    {
        appear_bsdf top = ly_coat(0.3f, 1.5f), lam = ly_lambert(0.5f), bad = ly_lambert(2.0f), none;
        appear_slab s = appear_slab_none();
        float nan = appear__u2f(APPEAR__NAN_BITS);
        appear_slab bads[5];
        appear_layered m;
        appear_bsdf_record r;
        memset(&none, 0, sizeof none);
        for (i = 0; i < 5; ++i) bads[i] = s;
        bads[0].tau.v[1] = -1.0f; bads[1].tau.v[0] = nan; bads[2].albedo.v[2] = 1.5f; bads[3].g = 1.5f;
        bads[4] = appear_slab_from_transmittance(appear_spectrum_splat(0.0f), s.albedo, 0.0f);
        for (i = 0; i < 5; ++i) {
            m = appear_layered_make(&top, &lam, bads[i], 1, 8);
            H_CHECK(!m.valid && appear_layered_flags(&m) == 0u, "bad slab %d accepted", i);
        }
        m = appear_layered_make(&top, &bad, s, 1, 8);
        H_CHECK(!m.valid, "an invalid base accepted");
        m = appear_layered_make(&none, &lam, s, 1, 8);
        H_CHECK(!m.valid, "a zero top accepted");
        H_CHECK(appear_layered_eval(&m, h_dir_mu(0.5, 0), h_dir_mu(0.5, 1), &rng).v[0] == 0.0f &&
                appear_layered_pdf(&m, h_dir_mu(0.5, 0), h_dir_mu(0.5, 1), &rng) == 0.0f &&
                !appear_layered_sample(&m, h_dir_mu(0.5, 0), &rng, &r) && r.flags == 0u, "invalid model answered");
        m = appear_layered_make(&top, &lam, s, 1, 8);
        H_CHECK(m.valid && !appear_layered_sample(&m, h_dir_mu(0.5, 0), APPEAR__NULL, &r) &&
                !appear_bsdf_layered(&m, APPEAR__NULL).flags, "a NULL rng accepted");
    }
}
