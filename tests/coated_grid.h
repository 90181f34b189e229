/* tests/coated_grid.h - the fast coat (appear_coated) against the reference walk
   (appear_layered) on one material: shared by tests/test_coated.c (a subset of the grid,
   gated) and bench/bench_layered.c (the whole grid, bench/REPORT.md).
   A material: a coat (GGX alpha, eta, colour C = transmittance at normal incidence) over a
   base appear_bsdf. The reference is the walk with the same coat as its top (rough: the
   multiple-scattering random-walk dielectric, appear_bsdf_dielectric_ms, reciprocal and
   energy-conserving; only the walk's sampler is used, whose weights stay unbiased with it;
   smooth: the smooth dielectric), the same (un-roughened) base and an absorbing slab of the
   same transmittance; the fast form is appear_coated_make in its
   default (albedo) mode. Directional albedo of both by their samplers (the mean weight, channel
   average), and the lobe distance: L1 between the two samplers' histograms of f |cos| over
   16 x 32 (cos theta, phi) bins, relative to the reference albedo. */
#ifndef APPEAR_TEST_COATED_GRID_H
#define APPEAR_TEST_COATED_GRID_H
#include "../appear.h"
#include <math.h>
#include <string.h>

typedef struct cg_result { double fast, ref, ref_se, l1; } cg_result;

static appear_bsdf cg_base(int which)
{
    appear_microfacet d;
    static const float alphas[3] = { 0.05f, 0.2f, 0.8f };
    switch (which) {
    case 0: return appear_bsdf_lambert(appear_lambert_make(appear_spectrum_splat(0.8f)));
    case 1: return appear_bsdf_eon(appear_eon_make(appear_spectrum_splat(0.8f), 0.5f));
    default:
        d = appear_microfacet_make(APPEAR_GGX, alphas[(which - 2) % 3], alphas[(which - 2) % 3], APPEAR_SAMPLE_VISIBLE);
        /* gold-like complex index (RGB); 5, 6: energy-compensated [Turquin19] (its multiple
           scattering: a coloured lobe that under a coat meets the metal many times) */
        if (which >= 5)
            return appear_bsdf_conductor_comp(appear_conductor_make(
                which == 5 ? appear_microfacet_make(APPEAR_GGX, 0.2f, 0.2f, APPEAR_SAMPLE_VISIBLE)
                           : appear_microfacet_make(APPEAR_GGX, 0.8f, 0.8f, APPEAR_SAMPLE_VISIBLE),
                appear_spectrum_rgb(0.18f, 0.42f, 1.37f), appear_spectrum_rgb(3.42f, 2.35f, 1.77f)));
        return appear_bsdf_conductor(appear_conductor_make(d, appear_spectrum_rgb(0.18f, 0.42f, 1.37f),
                                                           appear_spectrum_rgb(3.42f, 2.35f, 1.77f)));
    }
}
static const char *cg_base_name(int which)
{
    static const char *n[7] = { "Lambert 0.8",   "EON 0.8 s0.5",       "gold GGX 0.05",     "gold GGX 0.2",
                                "gold GGX 0.8", "gold GGX 0.2 comp", "gold GGX 0.8 comp" };
    return n[which];
}
#define CG_NBASES 7

static void cg_hist(double *h, appear_vec3 wi, double w, double scale)
{
    /* a mirror direction of wo (in the xz plane) has y = +0 or -0 by the sampler: one phi, pi,
       one bin (atan2 would give +pi or -pi, the two ends of the axis) */
    double ph = atan2(fabs(wi.y) < 1e-9 ? 0.0 : wi.y, wi.x);
    int it = (int)(fabs(wi.z) * 16.0), ip = (int)floor((ph + 3.14159265358979) / (2 * 3.14159265358979) * 32.0);
    if (it > 15) it = 15;
    ip = ((ip % 32) + 32) % 32;
    h[it * 32 + ip] += w * scale;
}

/* one material at one view cosine; n samples of each sampler */
static cg_result cg_compare(int base, float alpha, float eta, appear_spectrum color, double mu, long n, unsigned seed)
{
    static double hf[512], hr[512];
    appear_microfacet d = appear_microfacet_make(APPEAR_GGX, alpha, alpha, APPEAR_SAMPLE_VISIBLE);
    appear_dielectric coat = appear_dielectric_make(d, eta);
    appear_bsdf b = cg_base(base);
    appear_rng trng = appear_rng_make(seed ^ 0x9e3779b9u);
    appear_bsdf top = alpha > 0.0f ? appear_bsdf_dielectric_ms(coat, &trng) : appear_bsdf_dielectric(coat);
    appear_coated fast = appear_coated_make(coat, &b, color, APPEAR_COATED_ALBEDO);
    appear_layered ref = appear_layered_make(&top, &b, appear_slab_from_transmittance(color,
                                             appear_spectrum_splat(0.0f), 0.0f), 1, 256);
    appear_rng rng = appear_rng_make(seed);
    appear_vec3 wo = appear_vec3_make((float)sqrt(1.0 - mu * mu), 0.0f, (float)mu);
    double sf = 0, sr = 0, sr2 = 0, l1 = 0;
    cg_result r;
    long i;
    memset(hf, 0, sizeof hf);
    memset(hr, 0, sizeof hr);
    for (i = 0; i < n; ++i) {
        appear_bsdf_record s;
        double w;
        if (appear_coated_sample(&fast, wo, appear_rng_next(&rng), appear_rng_next(&rng), appear_rng_next(&rng), &s)) {
            w = appear_spectrum_avg(s.weight);
            sf += w;
            cg_hist(hf, s.wi, w, 1.0 / n);
        }
        if (appear_layered_sample(&ref, wo, &rng, &s)) {
            w = appear_spectrum_avg(s.weight);
            sr += w; sr2 += w * w;
            cg_hist(hr, s.wi, w, 1.0 / n);
        }
    }
    r.fast = sf / n;
    r.ref = sr / n;
    r.ref_se = sqrt(fmax(0, sr2 / n - r.ref * r.ref) / n);
    for (i = 0; i < 512; ++i) l1 += fabs(hf[i] - hr[i]);
    r.l1 = r.ref > 0 ? l1 / r.ref : 0;
    return r;
}
#endif
