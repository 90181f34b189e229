/* tests/test_sheen.c - the LTC sheen (appear.h SECTION sheen, [Zeltner22]) against its own
   reference data (tests/gen/sheen_ref.h, sheen_mid.h: the random walk of tests/gen/gen_sheen.c
   through the volumetric layer) and its contract:
     - the table at its nodes equals the walk's albedo (within 2e-5: it holds E^(1/4) to 7
       decimals), and at the held-out midpoints between the nodes (a second walk, its own
       seed) the lookup's error where E > 0.05 stays under the bound measured when the table
       was made (printed: max, mean, and the walk's noise: se / E, error / se);
     - the lobe: the walk's own LTC fit per node against the walk's histogram (TV minus its
       noise floor, from sheen_ref.h; printed, bounded);
     - the LTC integrates to E (the cosine-weighted f) within 1e-4, and its pdf to 1, by
       quadrature in double over 9 roughnesses x 9 view angles;
     - energy: sheen over a white Lambert base with the layering helper, both modes, albedo
       <= 1 + 1e-3 everywhere (the loss is measured and printed);
     - sampling against pdf: the mean of f |cos| / pdf over the sampler equals the uniform-
       hemisphere estimate of the albedo within 4 se;
     - reciprocity: the LTC is not reciprocal; the largest ratio f(wo, wi) / f(wi, wo) over
       pairs where both directions see E > 0.05 is measured, printed and bounded;
     - make(): roughness outside (0, 1], NaN, Inf, a colour channel NaN or outside [0, 1] give
       valid = 0 and zero / failed calls; the edges 1 and tiny r are accepted. */
#include "harness.h"
#include "../appear.h"
#include "gen/sheen_ref.h"
#include "gen/sheen_mid.h"
#include <math.h>

#define PI_D 3.14159265358979323846
/* the bounds of the held-out check: measured when the table was made (README.md), plus margin */
#define SHEEN_MID_MAX 0.02   /* measured 0.0151 (mu 0.103, r 0.106, E 0.052; walks' noise included) */
#define SHEEN_MID_MEAN 0.004 /* measured 0.0028 */
#define SHEEN_MID_ABS 0.004  /* measured 0.0024 (E <= 0.05 at the walk) */
#define SHEEN_LOBE_MAX 0.25  /* measured 0.220 (mu 0.014, r 0.037: the LTC's shape at low r, grazing) */
#define SHEEN_LOBE_MEAN 0.05 /* measured 0.042 */
#define SHEEN_RECIP_MAX 4.5  /* measured 3.91 (mean 1.12) */

/* int over the hemisphere of g(wi) dw, midpoint rule in (sqrt(cos), phi): resolves lobes
   near the horizon (dw = 2 t dt dphi, cos = t^2) */
typedef double (*sh_fn)(const appear_sheen *m, appear_vec3 wo, appear_vec3 wi);
static double sh_quad(const appear_sheen *m, appear_vec3 wo, sh_fn g, int nt, int np)
{
    double s = 0.0;
    int i, j;
    for (i = 0; i < nt; ++i) {
        double t = (i + 0.5) / nt, c = t * t;
        for (j = 0; j < np; ++j) s += g(m, wo, h_dir_mu(c, (j + 0.5) * 2.0 * PI_D / np)) * 2.0 * t;
    }
    return s / nt * (2.0 * PI_D / np);
}
static double sh_fcos(const appear_sheen *m, appear_vec3 wo, appear_vec3 wi)
{ return appear_spectrum_avg(appear_sheen_eval(m, wo, wi)) * fabs((double)wi.z); }
static double sh_pdf(const appear_sheen *m, appear_vec3 wo, appear_vec3 wi)
{ return appear_sheen_pdf(m, wo, wi); }
/* sheen over a white Lambert: f_layer |cos| */
static int g_mode;
static double sh_layer(const appear_sheen *m, appear_vec3 wo, appear_vec3 wi)
{
    appear_spectrum f = appear_sheen_layer_eval(m, wo, wi, appear_spectrum_splat((float)(1.0 / PI_D)), g_mode);
    return appear_spectrum_avg(f) * fabs((double)wi.z);
}

void suite_sheen(void)
{
    int i, j;
    h_case("sheen: the table at its nodes is the walk's albedo (sheen_ref.h)");
    {
        double worst = 0.0;
        for (j = 0; j < SHEEN_REF_NR; ++j)
            for (i = 0; i < SHEEN_REF_NMU; ++i) {
                appear_sheen m = appear_sheen_make(appear_spectrum_splat(1.0f), (float)sheen_ref_r[j]);
                double e = fabs(appear_sheen_albedo(&m, (float)sheen_ref_mu[i]) - sheen_ref[j][i][0]);
                worst = fmax(worst, e);
            }
        H_CHECK(worst < 2e-5, "largest |E_table - E_walk| at the nodes %.3g", worst);
    }

    h_case("sheen: albedo at the held-out midpoints (sheen_mid.h) within the measured bound");
    {
        double emax = 0, esum = 0, eabs = 0, zmax = 0, mmu = 0, mr = 0, semax = 0;
        int n = 0;
        for (j = 0; j < SHEEN_MID_NR; ++j)
            for (i = 0; i < SHEEN_MID_NMU; ++i) {
                appear_sheen m = appear_sheen_make(appear_spectrum_splat(1.0f), (float)sheen_mid_r[j]);
                double E = sheen_mid[j][i][0], se = sheen_mid[j][i][1];
                double v = appear_sheen_albedo(&m, (float)sheen_mid_mu[i]);
                if (E > 0.05) {
                    double e = fabs(v - E) / E;
                    esum += e; ++n;
                    if (e > emax) { emax = e; mmu = sheen_mid_mu[i]; mr = sheen_mid_r[j]; }
                    zmax = fmax(zmax, fabs(v - E) / se);
                    semax = fmax(semax, se / E);
                } else eabs = fmax(eabs, fabs(v - E));
            }
        /* the error includes the walks' noise: the midpoint's own relative standard error
           (printed: its largest) and the table nodes' (about the same, sheen_ref.h) */
        h_measure("sheen table midpoints", "%d held-out midpoints with E > 0.05: relative error max %.4f "
                  "(mu %.4f, r %.4f), mean %.4f; elsewhere max abs %.4f; largest |error| / walk se %.1f "
                  "(the walk's relative se at most %.4f)", n, emax, mmu, mr, esum / n, eabs, zmax, semax);
        H_CHECK(n > 500 && emax < SHEEN_MID_MAX && esum / n < SHEEN_MID_MEAN && eabs < SHEEN_MID_ABS,
                "max %.4f (bound %g), mean %.4f (bound %g), abs %.4f (bound %g)", emax, SHEEN_MID_MAX,
                esum / n, SHEEN_MID_MEAN, eabs, SHEEN_MID_ABS);
    }

    h_case("sheen: the walk's own LTC fit per node against its histogram (sheen_ref.h)");
    {
        double worst = 0, sum = 0;
        int n = 0;
        for (j = 0; j < SHEEN_REF_NR; ++j)
            for (i = 0; i < SHEEN_REF_NMU; ++i) {
                const double *q = sheen_ref[j][i];
                if (q[0] <= 0.05 || q[3] <= 0) continue;
                worst = fmax(worst, q[5] - q[6]); sum += q[5] - q[6]; ++n;
            }
        h_measure("sheen lobe misfit", "LTC vs walk histogram, total variation above its noise, %d nodes "
                  "with E > 0.05: max %.4f, mean %.4f", n, worst, sum / n);
        H_CHECK(n > 500 && worst < SHEEN_LOBE_MAX && sum / n < SHEEN_LOBE_MEAN, "max %.4f (bound %g), mean %.4f "
                "(bound %g)", worst, SHEEN_LOBE_MAX, sum / n, SHEEN_LOBE_MEAN);
    }

    h_case("sheen: int f |cos| = C E and int pdf = 1 by quadrature (1e-4), 9 r x 9 view angles");
    {
        static const float rs[9] = { 0.02f, 0.05f, 0.1f, 0.2f, 0.35f, 0.5f, 0.65f, 0.8f, 1.0f };
        static const double mus[9] = { 1.0, 0.9, 0.7, 0.5, 0.3, 0.2, 0.1, 0.05, 0.02 };
        double we = 0, wp = 0;
        for (j = 0; j < 9; ++j)
            for (i = 0; i < 9; ++i) {
                appear_sheen m = appear_sheen_make(appear_spectrum_rgb(0.9f, 0.6f, 0.3f), rs[j]);
                appear_vec3 wo = h_dir_mu(mus[i], 0.4);
                double E = appear_sheen_albedo(&m, wo.z) * (0.9 + 0.6 + 0.3) / 3.0;
                double qe = sh_quad(&m, wo, sh_fcos, 1200, 256), qp = sh_quad(&m, wo, sh_pdf, 1200, 256);
                we = fmax(we, fabs(qe - E)); wp = fmax(wp, fabs(qp - 1.0));
            }
        h_measure("sheen normalisation", "largest |int f cos - C E| %.3g, |int pdf - 1| %.3g", we, wp);
        H_CHECK(we < 1e-4 && wp < 1e-4, "|int f cos - C E| %.3g, |int pdf - 1| %.3g", we, wp);
    }

    h_case("sheen: over a white Lambert with the layering helper, albedo <= 1 + 1e-3 (both modes)");
    {
        static const float rs[6] = { 0.03f, 0.1f, 0.3f, 0.5f, 0.75f, 1.0f };
        static const double mus[8] = { 1.0, 0.8, 0.6, 0.4, 0.2, 0.1, 0.03, 0.01 };
        double hi[2] = { 0, 0 }, lo[2] = { 2, 2 };
        int md;
        for (md = 0; md < 2; ++md)
            for (j = 0; j < 6; ++j)
                for (i = 0; i < 8; ++i) {
                    appear_sheen m = appear_sheen_make(appear_spectrum_splat(1.0f), rs[j]);
                    double a;
                    g_mode = md ? APPEAR_SHEEN_LAYER_RECIPROCAL : APPEAR_SHEEN_LAYER_ALBEDO;
                    a = sh_quad(&m, h_dir_mu(mus[i], 0.0), sh_layer, 800, 128);
                    hi[md] = fmax(hi[md], a); lo[md] = fmin(lo[md], a);
                }
        h_measure("sheen over white Lambert", "albedo in [%.5f, %.5f] (albedo scaling), [%.5f, %.5f] "
                  "(reciprocal): largest loss %.2g / %.2g", lo[0], hi[0], lo[1], hi[1], 1 - lo[0], 1 - lo[1]);
        H_CHECK(hi[0] <= 1 + 1e-3 && hi[1] <= 1 + 1e-3 && lo[0] > 0.99 && lo[1] > 0.99,
                "albedo scaling [%.5f, %.5f], reciprocal [%.5f, %.5f]", lo[0], hi[0], lo[1], hi[1]);
    }

    h_case("sheen: the sampler's mean weight against a uniform-hemisphere estimate (4 se)");
    {
        h_rng r = h_rng_make(3131u);
        static const float rs[4] = { 0.1f, 0.3f, 0.6f, 1.0f };
        static const double mus[3] = { 0.9, 0.4, 0.08 };
        long n = h_n(200000), k, bad = 0;
        double worst = 0;
        for (j = 0; j < 4; ++j)
            for (i = 0; i < 3; ++i) {
                appear_sheen m = appear_sheen_make(appear_spectrum_splat(1.0f), rs[j]);
                appear_vec3 wo = h_dir_mu(mus[i], 1.0);
                double sw = 0, su = 0, su2 = 0, mu_, se, z;
                for (k = 0; k < n; ++k) {
                    appear_bsdf_record s;
                    float u1 = h_randf(&r), u2 = h_randf(&r); /* in this order */
                    double c, ph, v;
                    if (appear_sheen_sample(&m, wo, 0.5f, u1, u2, &s)) sw += s.weight.v[0];
                    c = h_randf(&r);
                    ph = 2.0 * PI_D * h_randf(&r);
                    v = sh_fcos(&m, wo, h_dir_mu(c, ph)) * 2.0 * PI_D;
                    su += v; su2 += v * v;
                }
                mu_ = su / n; se = sqrt(fmax(0.0, su2 / n - mu_ * mu_) / n);
                z = fabs(sw / n - mu_) / (se + 1e-12);
                worst = fmax(worst, z); bad += z > 4.0;
            }
        h_measure("sheen sampling", "mean weight vs uniform estimate: largest |difference| / se %.2f", worst);
        H_CHECK(bad == 0, "%ld of 12 configurations beyond 4 se (largest %.2f)", bad, worst);
    }

    h_case("sheen: not reciprocal; the ratio f(wo, wi) / f(wi, wo) measured and bounded");
    {
        h_rng r = h_rng_make(3141u);
        static const float rs[5] = { 0.2f, 0.4f, 0.6f, 0.8f, 1.0f };
        double worst = 1.0, sum = 0;
        long k, n = 20000, cnt = 0;
        for (j = 0; j < 5; ++j) {
            appear_sheen m = appear_sheen_make(appear_spectrum_splat(1.0f), rs[j]);
            for (k = 0; k < n; ++k) {
                double c1 = h_randf(&r), p1 = h_randf(&r), c2 = h_randf(&r), p2 = h_randf(&r);
                appear_vec3 a = h_dir_mu(c1, 2 * PI_D * p1), b = h_dir_mu(c2, 2 * PI_D * p2);
                double fab, fba, q;
                if (appear_sheen_albedo(&m, a.z) < 0.05f || appear_sheen_albedo(&m, b.z) < 0.05f) continue;
                fab = appear_sheen_eval(&m, a, b).v[0]; fba = appear_sheen_eval(&m, b, a).v[0];
                if (!(fab > 0 && fba > 0)) continue;
                q = fab > fba ? fab / fba : fba / fab;
                worst = fmax(worst, q); sum += q; ++cnt;
            }
        }
        h_measure("sheen reciprocity", "f(wo, wi) / f(wi, wo) over %ld pairs with E > 0.05 both ways: "
                  "largest %.3f, mean %.4f", cnt, worst, sum / cnt);
        H_CHECK(cnt > 10000 && worst < SHEEN_RECIP_MAX, "largest ratio %.3f (bound %g)", worst, SHEEN_RECIP_MAX);
    }

    h_case("sheen: make() rejects roughness outside (0, 1], NaN, Inf and bad colours");
    {
        static const float bad_r[6] = { 0.0f, -0.0f, 1.00000012f, -0.5f, INFINITY, NAN };
        static const float bad_c[4] = { NAN, 1.5f, -0.1f, INFINITY };
        appear_vec3 wo = h_dir_mu(0.5, 0.0), wi = h_dir_mu(0.7, 2.0);
        int ok = 1;
        for (i = 0; i < 10; ++i) {
            appear_spectrum c = appear_spectrum_splat(0.5f);
            appear_sheen m;
            appear_bsdf_record s;
            appear_spectrum f;
            if (i >= 6) c.v[1] = bad_c[i - 6];
            m = appear_sheen_make(c, i < 6 ? bad_r[i] : 0.5f);
            f = appear_sheen_eval(&m, wo, wi);
            ok &= !m.valid && f.v[0] == 0 && f.v[1] == 0 && f.v[2] == 0 && appear_sheen_pdf(&m, wo, wi) == 0 &&
                  !appear_sheen_sample(&m, wo, 0.5f, 0.3f, 0.6f, &s) && s.pdf == 0 && appear_sheen_albedo(&m, 0.5f) == 0;
        }
        H_CHECK(ok, "an invalid sheen was accepted or gave a nonzero result");
        H_CHECK(appear_sheen_make(appear_spectrum_splat(1.0f), 1.0f).valid &&
                    appear_sheen_make(appear_spectrum_splat(0.0f), 1e-30f).valid &&
                    appear_sheen_make(appear_spectrum_splat(0.0f), 1e-30f).e_avg < 1e-20f,
                "roughness 1 or 1e-30 rejected, or E not -> 0 below r = 0.01");
    }
}
