/* tests/gen/scan_openpbr_film.c - what the thin film's affine map gives up (appear.h SECTION
   openpbr, "Deviations"): the albedo of a lone OpenPBR specular lobe (base_weight 0) with the film
   carried as F' = a F + b against the same lobe with the film per microfacet (the spec's form:
   F(wo.h) plus the film's change at wo.h), both integrated over a 128 x 128 grid of the lobe's
   visible-normal samples (F = 1 lobe, weight G2 / G1), on alpha 0.05..1, mu 0.05..1 (or from a
   lower bound), thickness 0.1..1 um, film index 1.33..2, base 1.05..2.5, with and without a
   smooth coat (index 1.5):
       cc -O2 -Wall tests/gen/scan_openpbr_film.c -o build/scan_openpbr_film -lm
       ./build/scan_openpbr_film          (all mu; ./build/scan_openpbr_film 0.2: mu >= 0.2)
   Prints the largest and the mean |difference| (split by roughness) and where the largest is.
   About 50 s on one core (the per-microfacet film is appear_thinfilm_rgb at each sample). */
#define APPEAR_IMPLEMENTATION
#include "../../appear.h"
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    static const float alphas[] = { 0.05f, 0.1f, 0.2f, 0.35f, 0.5f, 0.75f, 1.0f };
    static const float mus[] = { 1.0f, 0.8f, 0.6f, 0.4f, 0.2f, 0.1f, 0.05f };
    static const float ds[] = { 0.1f, 0.25f, 0.4f, 0.6f, 1.0f }, nfs[] = { 1.33f, 1.4f, 2.0f };
    static const float iors[] = { 1.05f, 1.5f, 2.5f };
    const int G = 128;
    float mu_min = argc > 1 ? (float)atof(argv[1]) : 0.0f;
    double worst = 0, sum = 0, worst_a[3] = { 0, 0, 0 };
    long cnt = 0;
    char where[300] = "";
    int ia, id, in, ie, coat, im, u, v, k;
    for (ia = 0; ia < 7; ++ia)
        for (id = 0; id < 5; ++id)
            for (in = 0; in < 3; ++in)
                for (ie = 0; ie < 3; ++ie)
                    for (coat = 0; coat < 2; ++coat) {
                        appear_openpbr_params p = appear_openpbr_params_default();
                        appear_openpbr m;
                        p.base_weight = 0.0f;
                        p.specular_roughness = sqrtf(alphas[ia]);
                        p.specular_ior = iors[ie];
                        p.thin_film_weight = 1.0f;
                        p.thin_film_thickness = ds[id];
                        p.thin_film_ior = nfs[in];
                        p.coat_weight = (float)coat;
                        p.coat_roughness = 0.0f;
                        p.coat_ior = 1.5f;
                        m = appear_openpbr_make(&p);
                        for (im = 0; im < 7; ++im) {
                            float mu = mus[im];
                            appear_vec3 wo = appear_vec3_make(sqrtf(1.0f - mu * mu), 0.0f, mu);
                            appear__openpbr_at t;
                            double ee[3] = { 0, 0, 0 }, em[3] = { 0, 0, 0 };
                            if (mu < mu_min) continue;
                            appear__openpbr_at_of(&m, wo, APPEAR__OPENPBR_EVAL, &t);
                            for (u = 0; u < G; ++u)
                                for (v = 0; v < G; ++v) {
                                    appear_bsdf_record r;
                                    appear_spectrum dl;
                                    float c, f;
                                    double w;
                                    if (!appear_conductor_sample(&m.spec_lobe, wo, 0.5f, (u + 0.5f) / G, (v + 0.5f) / G,
                                                                 &r) || r.wi.z <= 0.0f)
                                        continue;
                                    c = appear_dot(wo, appear_normalize(appear_add(wo, r.wi)));
                                    w = r.weight.v[0] / ((double)G * G);
                                    f = appear_fresnel_dielectric(c, m.spec.eta);
                                    dl = appear__openpbr_film_dl(&m, c, appear_spectrum_splat(m.spec.eta),
                                                                 appear_spectrum_splat(0.0f));
                                    for (k = 0; k < 3; ++k) {
                                        ee[k] += w * (f + dl.v[k]);
                                        em[k] += w * (t.fa.v[k] * f + t.fb.v[k]);
                                    }
                                }
                            for (k = 0; k < 3; ++k) {
                                double e = fabs(ee[k] - em[k]);
                                int cl = alphas[ia] <= 0.1f ? 0 : alphas[ia] <= 0.35f ? 1 : 2;
                                sum += e; ++cnt;
                                if (e > worst_a[cl]) worst_a[cl] = e;
                                if (e > worst) {
                                    worst = e;
                                    snprintf(where, sizeof where, "alpha %g mu %g d %g um n_f %g ior %g coat %d ch %d: "
                                             "affine %.4f, per microfacet %.4f", (double)alphas[ia], (double)mu,
                                             (double)ds[id], (double)nfs[in], (double)iors[ie], coat, k, em[k], ee[k]);
                                }
                            }
                        }
                    }
    printf("mu >= %g: max %.4f, mean %.5f over %ld channel values; max by alpha <= 0.1: %.4f, <= 0.35: %.4f, "
           "> 0.35: %.4f; at %s\n", (double)mu_min, worst, sum / (double)cnt, cnt, worst_a[0], worst_a[1], worst_a[2],
           where);
    return 0;
}
