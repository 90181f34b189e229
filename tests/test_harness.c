/* tests/test_harness.c - the harness tests itself: a test that cannot fail
   proves nothing, so each instrument is shown to fail on wrong input. */
#include "harness.h"
#include <math.h>

typedef struct { float g_sample, g_pdf; appear_vec3 wo; } mis_ctx;
static int mis_sample(void *c, float uc, float u1, float u2, appear_vec3 *wi)
{
    mis_ctx *x = (mis_ctx *)c;
    appear_phase_record s;
    (void)uc;
    *wi = appear_vec3_make(0, 0, 0);
    if (!appear_hg_sample_g(x->g_sample, x->wo, u1, u2, &s)) return 0;
    *wi = s.wi;
    return 1;
}
static double mis_pdf(void *c, appear_vec3 wi) { mis_ctx *x = (mis_ctx *)c; return appear_hg_pdf_g(x->g_pdf, x->wo, wi); }
static double cos2(void *c, appear_vec3 w) { (void)c; return (double)w.z * w.z; }
static double lobe(void *c, appear_vec3 w)
{   /* normalised exp(-k (1 - z)) with k = 1e6: mass 1 within ~1e-3 rad */
    double k = *(double *)c, omz = ((double)w.x * w.x + (double)w.y * w.y) / (1.0 + fabs(w.z));
    return w.z > 0 ? k / (2.0 * 3.141592653589793 * (1.0 - exp(-2.0 * k))) * exp(-k * omz) : 0.0;
}

void suite_harness(void)
{
    mis_ctx c;
    h_chi2_spec sp = { 0 };
    double p, v, k = 1e6;
    c.wo = appear_normalize(appear_vec3_make(0.2f, 0.1f, 0.9f));
    sp.sample = mis_sample; sp.pdf = mis_pdf; sp.ctx = &c; sp.unrecorded = 1; sp.seed = 77;
    sp.n_samples = 400000; /* 25000 in quick mode: the mismatch below is chosen to be caught even then */

    h_case("harness: chi2 rejects a sampler that does not match its pdf (g 0.30 vs 0.36)");
    c.g_sample = 0.30f; c.g_pdf = 0.36f; sp.name = "self-test mismatch";
    p = h_chi2(&sp);
    H_CHECK(p < 1e-5, "p = %.3g for a wrong pdf (the suite rejects below ~1e-4)", p);

    h_case("harness: chi2 accepts a matching sampler");
    c.g_sample = 0.30f; c.g_pdf = 0.30f; sp.name = "self-test match";
    p = h_chi2(&sp);
    H_CHECK(p > 1e-4, "p = %.3g for the right pdf", p);

    h_case("harness: chi2 rejects samples where the pdf is zero");
    c.g_sample = 0.0f; c.g_pdf = 0.0f; sp.name = "self-test cap";
    sp.zmin = 0.5; sp.axis = appear_vec3_make(0, 0, 1);
    p = h_chi2(&sp); /* sampler is uniform on the sphere, bins cover a cap: the rest bin takes the others */
    H_CHECK(p > 1e-4, "p = %.3g with a cap domain", p);

    h_case("harness: p-values against closed forms");
    v = h_chi2_pvalue(3.0, 2.0);
    H_CHECK(fabs(v - exp(-1.5)) < 1e-12, "Q(1, 1.5) = %.15g, want %.15g", v, exp(-1.5));
    v = h_chi2_pvalue(200.0, 150.0);
    H_CHECK(fabs(v - 0.003973185970798) < 1e-12, "chi2 200 with 150 dof: p = %.15g", v); /* reference: series for P(75, 100) in double, independent code */
    v = h_chi2_pvalue(1.0, 1.0);
    H_CHECK(fabs(v - erfc(sqrt(0.5))) < 1e-12, "chi2 1 with 1 dof: p = %.15g", v);

    h_case("harness: sphere quadrature of cos^2 and of a 1e-3-wide lobe");
    v = h_integrate_sphere(cos2, 0, appear_vec3_make(0.3f, 0.4f, 0.866f), 1e-8);
    H_CHECK(fabs(v - 4.0 * 3.141592653589793 / 3.0) < 1e-6, "integral of z^2 = %.9f", v);
    v = h_integrate_sphere(lobe, &k, appear_vec3_make(0, 0, 1), 1e-8);
    H_CHECK(fabs(v - 1.0) < 1e-5, "narrow lobe integral = %.9f", v);
}

static double lobe_down(void *c, appear_vec3 w) { appear_vec3 f = appear_neg(w); return lobe(c, f); }
void suite_harness_poles(void)
{
    double k = 1e6, v;
    h_case("harness: sphere quadrature resolves a narrow peak at -axis too");
    v = h_integrate_sphere(lobe_down, &k, appear_vec3_make(0, 0, 1), 1e-8);
    H_CHECK(fabs(v - 1.0) < 1e-5, "narrow lobe at -axis: integral = %.9f", v);
}
