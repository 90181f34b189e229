/* tests/test_openpbr.c - OpenPBR Surface (appear.h SECTION openpbr):
     - the spec's white-furnace list [OpenPBR11, "White furnace testing"]: white metal, white
       diffuse base, the translucent base (transmission 1) and its half mix with the diffuse
       one, their mixes, with a white coat and a white fuzz, over roughness {0, 0.3, 1},
       anisotropy {0, 0.5}, IOR {1.5, 3}, weights {0, 0.5, 1} and 9 view angles down to 89
       degrees; the albedo (energy: a refraction's weight times eta^2) measured two ways, by
       quadrature of eval (rough lobes) and by the mean sample weight (every case, delta lobes
       included), agree within 4.5 se; opaque isotropic: within 3e-3 of 1 and never above 1 +
       1e-3; translucent: held to what is measured (E_T = E - R from two tables); anisotropic:
       held to what is measured (anisotropy 0.5 within 1e-2; 0.9 and 1 at roughness 0.8 and 1:
       the metal and the dielectric over diffuse within 2e-2, the glass, both sides, 0.94 .. 1.05;
       their albedo tables are anisotropic, the dielectric's interpolated corrections); from inside
       the dielectric: never above 1 + 2e-3 (the coat and fuzz lose what they reflect back);
     - closed-form corners: each lobe alone is its standalone model to the bit; a smooth glass
       is the smooth dielectric (its records' coefficients F and (1 - F) / eta^2); a coat or fuzz
       of weight 0 gives the bits of no coat / no fuzz; the diffuse base at roughness 0 and
       specular weight 0 is Lambert;
     - the mixture pdf: its integral is the rate of non-delta samples, the sample records are
       pdf() and eval() at their directions, chi-square of the sampler against pdf();
     - the interior medium: mu_t = -ln(colour) / depth, mu_s = scatter / depth, the grey shift;
     - bad input: NaN / Inf parameters make the model invalid (so does a thin film without
       SECTION thinfilm), finite out-of-range values are clamped;
     - the thin film ("Thin-film iridescence"): weight or thickness 0 give the bits of no film;
       thickness -> 0 is the bare Fresnel; the film's change against a second form (the spectral
       Airy sum in absolute indices, double) for bare and coated dielectric bases and a metal;
       the white furnace with the film on; the affine map's albedo against the per-microfacet
       film's (measured);
     - a tinted coat over EON and a clear and a tinted coat over gold against the layered
       reference walk through the same coat over the same base (the darkening's a_K: the trapped
       light's round trip through the tinted layer; the coated metal's escape; with the spec's
       Delta these points miss by 0.09-0.11 and 0.05-0.08). */
#include "harness.h"
#include "../appear.h"
#include <complex.h>
#include <math.h>
#include <string.h>
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#ifdef APPEAR_HAS_OPENPBR

/* three numbers in a fixed order, as a colour */
static appear_spectrum op_rgb(h_rng *r)
{
    float a = h_randf(r), b = h_randf(r), c = h_randf(r);
    return appear_spectrum_rgb(a, b, c);
}
/* a direction in the upper hemisphere, uniform in solid angle */
static appear_vec3 op_upper(h_rng *r)
{
    appear_vec3 w = h_rand_dir(r);
    w.z = fabsf(w.z);
    return w;
}

/* white configurations: base (0 diffuse, 1 metal, 2 half mix, 3 translucent, 4 half translucent
   half diffuse; thin-walled: 5 a glass sheet, 6 a subsurface sheet of anisotropy 0.3), coat,
   fuzz, roughness, ...; coat_aniso 0 and coat_ior 0: the coat's defaults (isotropic, IOR 1.6) */
typedef struct { int base; float coat, fuzz, rough, aniso, ior, coat_rough, diff_rough, coat_aniso, coat_ior; } op_white;
static appear_openpbr_params op_white_params(const op_white *w)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    p.base_color = appear_spectrum_splat(1.0f);
    p.base_metalness = w->base == 1 ? 1.0f : w->base == 2 ? 0.5f : 0.0f;
    p.transmission_weight = w->base == 3 || w->base == 5 ? 1.0f : w->base == 4 ? 0.5f : 0.0f;
    p.geometry_thin_walled = w->base >= 5;
    p.subsurface_weight = w->base == 6 ? 1.0f : 0.0f;
    p.subsurface_color = appear_spectrum_splat(1.0f);
    p.subsurface_scatter_anisotropy = 0.3f;
    p.base_diffuse_roughness = w->diff_rough;
    p.specular_roughness = w->rough;
    p.specular_roughness_anisotropy = w->aniso;
    p.specular_ior = w->ior;
    p.coat_weight = w->coat;
    p.coat_roughness = w->coat_rough;
    p.coat_roughness_anisotropy = w->coat_aniso;
    if (w->coat_ior > 0.0f) p.coat_ior = w->coat_ior;
    p.fuzz_weight = w->fuzz;
    return p;
}

typedef struct { const appear_openpbr *m; appear_vec3 wo; int c; int what; } op_ctx;
/* the energy of a refraction: its radiance times eta^2 (eta = n_wi / n_wo; a thin wall: 1) */
static double op_energy(const appear_openpbr *m, appear_vec3 wo, appear_vec3 wi)
{
    double e = m->thin ? 1.0 : wo.z > 0.0f ? m->glass.eta : 1.0 / m->glass.eta;
    return wo.z * wi.z < 0.0f ? e * e : 1.0;
}
static double op_integrand(void *ctx, appear_vec3 wi)
{
    const op_ctx *c = (const op_ctx *)ctx;
    if (c->what == 1) return appear_openpbr_pdf(c->m, c->wo, wi);
    return (double)appear_openpbr_eval(c->m, c->wo, wi).v[c->c] * fabs(wi.z) * op_energy(c->m, c->wo, wi);
}
static double op_quad_tol(const appear_openpbr *m, appear_vec3 wo, int c, int what, double tol)
{
    op_ctx x;
    x.m = m; x.wo = wo; x.c = c; x.what = what;
    return h_integrate_sphere(op_integrand, &x, appear_vec3_make(-wo.x, -wo.y, wo.z), tol);
}
static double op_quad(const appear_openpbr *m, appear_vec3 wo, int c, int what)
{
    return op_quad_tol(m, wo, c, what, what ? 2e-6 : 1e-5);
}
/* mean sample energy of channel c (a refraction's weight times eta^2), its se, and the rate of
   non-delta samples */
static int op_sample(const void *m, appear_vec3 wo, float uc, float u1, float u2, appear_bsdf_record *s)
{
    int ok = appear_openpbr_sample((const appear_openpbr *)m, wo, uc, u1, u2, s), i;
    if (ok && (s->flags & APPEAR_LOBE_TRANSMISSION))
        for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) s->weight.v[i] *= s->eta * s->eta;
    return ok;
}
static double op_mean(const appear_openpbr *m, appear_vec3 wo, long n, h_rng *r, int c, double *se, double *nd)
{
    return h_sample_mean(op_sample, m, wo, n, r, c, se, nd);
}

void suite_openpbr_furnace(void)
{
    static const float weights[] = { 0.0f, 0.5f, 1.0f }, roughs[] = { 0.0f, 0.3f, 1.0f };
    static const float mus[] = { 1.0f, 0.9f, 0.7f, 0.5f, 0.3f, 0.15f, 0.08f, 0.03f, 0.017452f }; /* to 89 deg */
    static const char *const cls[3] = { "opaque, isotropic", "anisotropy 0.5",
                                        "translucent and thin-walled, isotropic" };
    /* [0]: opaque isotropic, [1]: anisotropy 0.5 (its albedos are approximations), [2]: the
       translucent bases, isotropic (f_T / E_T, E_T from two tables) */
    double worst_q[3] = { 0, 0, 0 }, worst_s[3] = { 0, 0, 0 }, worst_z = 0, worst_up[3] = { 0, 0, 0 };
    double in_up = 0, in_clear = 0, in_low = 1;
    char where_q[3][160] = { "", "", "" }, where_s[3][160] = { "", "", "" }, where_in[160] = "-", where_z[160] = "";
    char where_up[3][160] = { "-", "-", "-" };
    long n = h_n(40000), points = 0, pick = 0;
    h_rng r = h_rng_make(33);
    int b, ci, fi, ri, ai, ii, k;
    h_case("openpbr: white furnace [OpenPBR11]: metal, diffuse, translucent, mixes, with coat and fuzz; "
           "opaque isotropic: quadrature within 1 +- 1e-3, mean sample weight within 3e-3, agree within 5 se");
    for (b = 0; b < 7; ++b)
        for (ci = 0; ci < 3; ++ci)
            for (fi = 0; fi < 3; ++fi)
                for (ri = 0; ri < 3; ++ri)
                    for (ai = 0; ai < 2; ++ai)
                        for (ii = 0; ii < 2; ++ii) {
                            op_white w;
                            appear_openpbr_params p;
                            appear_openpbr m;
                            int cl = ai ? 1 : b >= 3 ? 2 : 0;
                            /* half the grid (a third quick); the translucent bases a quarter (a sixth);
                               sanitized, every third of the quick set */
                            if ((ci + fi + ri + ai + ii) % ((h_quick() ? 3 : 2) * (b >= 3 ? 2 : 1)) != 0) continue;
                            if (h_sanitized() && pick++ % 3 != 0) continue;
                            w.base = b; w.coat = weights[ci]; w.fuzz = weights[fi];
                            w.rough = roughs[ri]; w.aniso = ai ? 0.5f : 0.0f; w.ior = ii ? 3.0f : 1.5f;
                            w.coat_rough = roughs[(ri + ci) % 3]; w.diff_rough = roughs[(ri + fi) % 3];
                            w.coat_aniso = 0.0f; w.coat_ior = 0.0f;
                            p = op_white_params(&w);
                            m = appear_openpbr_make(&p);
                            H_CHECK(m.valid, "white config base %d coat %g fuzz %g invalid", w.base, w.coat,
                                    w.fuzz);
                            for (k = 0; k < 9; ++k) {
                                double st = sqrt(1.0 - (double)mus[k] * mus[k]), se, nd, mean, q = -1.0;
                                appear_vec3 wo = appear_vec3_make((float)(st * 0.8), (float)(st * 0.6), mus[k]);
                                int rough = w.rough >= 0.3f && w.coat_rough >= 0.3f;
                                mean = op_mean(&m, wo, n, &r, 1, &se, &nd);
                                if (fabs(mean - 1.0) - 4.0 * se > worst_s[cl]) {
                                    worst_s[cl] = fabs(mean - 1.0) - 4.0 * se;
                                    snprintf(where_s[cl], sizeof where_s[cl], "base %d coat %g fuzz %g r %g a %g ior %g "
                                             "mu %g: %.5f (se %.1g)", w.base, w.coat, w.fuzz, w.rough, w.aniso,
                                             w.ior, mus[k], mean, se);
                                }
                                if (rough && k % 2 == 0) {
                                    q = op_quad(&m, wo, 1, 0);
                                    if (fabs(q - 1.0) > worst_q[cl]) {
                                        worst_q[cl] = fabs(q - 1.0);
                                        snprintf(where_q[cl], sizeof where_q[cl], "base %d coat %g fuzz %g r %g a %g "
                                                 "ior %g mu %g: %.5f", w.base, w.coat, w.fuzz, w.rough, w.aniso,
                                                 w.ior, mus[k], q);
                                    }
                                    if (q - 1.0 > worst_up[cl]) {
                                        worst_up[cl] = q - 1.0;
                                        snprintf(where_up[cl], sizeof where_up[cl], "base %d coat %g fuzz %g r %g a "
                                                 "%g ior %g mu %g", w.base, w.coat, w.fuzz, w.rough, w.aniso, w.ior,
                                                 mus[k]);
                                    }
                                    if (fabs(q - mean) / fmax(se, 1e-12) > worst_z) {
                                        worst_z = fabs(q - mean) / se;
                                        snprintf(where_z, sizeof where_z, "base %d coat %g fuzz %g r %g a %g ior %g "
                                                 "mu %g: %.5f vs %.5f (se %.1g)", w.base, w.coat, w.fuzz, w.rough,
                                                 w.aniso, w.ior, mus[k], q, mean, se);
                                    }
                                }
                                if ((b == 3 || b == 4) && k % 4 == 1) { /* from inside the dielectric */
                                    wo.z = -wo.z;
                                    mean = op_mean(&m, wo, n, &r, 1, &se, &nd);
                                    in_low = fmin(in_low, mean);
                                    if (!ai && mean - 1.0 - 4.0 * se > in_up) {
                                        in_up = mean - 1.0 - 4.0 * se;
                                        snprintf(where_in, sizeof where_in, "base %d coat %g fuzz %g r %g a %g ior %g "
                                                 "mu -%g: %.5f (se %.1g)", w.base, w.coat, w.fuzz, w.rough, w.aniso,
                                                 w.ior, mus[k], mean, se);
                                    }
                                    if (w.coat == 0.0f && w.fuzz == 0.0f && !ai &&
                                        fabs(mean - 1.0) - 4.0 * se > in_clear)
                                        in_clear = fabs(mean - 1.0) - 4.0 * se;
                                }
                                points++;
                            }
                        }
    for (ai = 0; ai < 3; ++ai)
        h_measure("openpbr white furnace", "%s: quadrature max |E - 1| %.2g at %s (max above 1: %.2g at %s); mean "
                  "weight max |E - 1| - 4 se %.2g at %s", cls[ai], worst_q[ai], where_q[ai], worst_up[ai],
                  where_up[ai], worst_s[ai], where_s[ai]);
    h_measure("openpbr white furnace", "from inside, isotropic: max E - 1 - 4 se %.2g at %s; without coat and fuzz max "
              "|E - 1| - 4 se %.2g; lowest E (the coat and fuzz's reflection back, lost) %.3f", in_up, where_in,
              in_clear, in_low);
    h_measure("openpbr white furnace", "%ld points; quadrature vs mean weight max %.2f se at %s", points, worst_z,
              where_z);
    /* opaque isotropic: 1 within 1e-3 by quadrature (the bound; measured 7.7e-4, a
       dielectric over diffuse at r 0.3, IOR 3, cos 0.08; 2.2e-3 for the metal at alpha 0.09 and cos
       0.08 before the conductor's albedo table was bicubic on axes of its own), never above 1 +
       1e-3; the mean weight within 3e-3 (the agreement below is its test) */
    /* (the agreement over ~2500 comparisons: 5 se, P(|z| > 5) = 6e-7 each; the quick mode's 2500
       samples estimate the se of skewed weights low: a rough anisotropic sheet under a coat, 3000
       repetitions of its 2500 samples, reach 4.5 se, and the quick run meets 5.04 there) */
    H_CHECK(worst_q[0] <= 1e-3 && worst_up[0] <= 1e-3 && worst_s[0] <= 3e-3 && worst_z <= (h_quick() ? 5.5 : 5.0),
            "furnace, opaque isotropic: quadrature %.3g (bound 1e-3, above 1: %.3g, bound 1e-3) at %s; mean weight "
            "%.3g (bound 3e-3) at %s; agreement %.2f se (bound 5, quick 5.5)", worst_q[0], worst_up[0], where_q[0],
            worst_s[0], where_s[0], worst_z);
    /* anisotropy 0.5: within 1e-3 of 1 by quadrature and never above 1 + 1e-3 (the bounds;
       measured 7.1e-4, a glass at r 1, IOR 3, cos 0.017, and 2.8e-4 above 1, a dielectric over
       diffuse at r 0.3, cos 0.08, since the anisotropic dielectric's table has 5 outside e and 7
       alpha nodes, twenty-fifth session; with 4 and 6, 1.3e-3 below 1, a glass under fuzz at 89
       degrees, and 8.1e-4 above, a coated glass at r 0.3, IOR 3, cos 0.7; 1.7e-3 above, a metal
       under a half coat, before the metal's compensation read its lobe's slice of the anisotropic
       table, cubic in all four axes, 2026-12-07); the mean weight to 5e-3 (measured 2e-5 beyond 4
       se, the quick mode 2.6e-3 where its 2500 samples estimate a skewed se low; 3.1e-3 and
       4.6e-2 with earlier tables) */
    H_CHECK(worst_q[1] <= 1e-3 && worst_up[1] <= 1e-3 && worst_s[1] <= 5e-3,
            "furnace, anisotropy 0.5: quadrature %.3g (bound 1e-3, above 1: %.3g, bound 1e-3) at %s; mean "
            "weight %.3g (bound 5e-3) at %s", worst_q[1], worst_up[1], where_q[1], worst_s[1], where_s[1]);
    /* translucent: the bound as opaque (measured 4.6e-4, a coated sheet at r 1, IOR 1.5, cos
       0.3, above 1 by as much; 2.7e-3 and 1.4e-3 above 1, a glass under fuzz at r 0.3, IOR 3, cos
       0.08, before the dielectric's table from outside was bicubic on the conductor's axes) */
    H_CHECK(worst_q[2] <= 1e-3 && worst_up[2] <= 1e-3 && worst_s[2] <= 3e-3,
            "furnace, translucent: quadrature %.3g (bound 1e-3, above 1: %.3g, bound 1e-3) at %s; mean weight "
            "%.3g (bound 3e-3) at %s", worst_q[2], worst_up[2], where_q[2], worst_s[2], where_s[2]);
    /* from inside: the compensated dielectric's E table at e < 1 (its hard region: SECTION
       multiscatter) and the layers' albedos at wi */
    H_CHECK(in_up <= 1e-2 && in_clear <= 1e-2, "furnace from inside: above 1 by %.3g (bound 1e-2) at %s; "
            "without coat and fuzz |E - 1| %.3g (bound 1e-2)", in_up, where_in, in_clear);
    /* the anisotropic metal alone, white, by quadrature over the roughnesses between the grid's
       (its lobe reads its slice of the anisotropic table, cubic in all four axes): within the
       issue's 1e-3 (measured 2.8e-4 at anisotropy 0.5, 5.0e-4 at 0.9, r 1, mu 0.3; the stretched
       table's quadrilinear read 2.0e-3 and 2.2e-3 at r 0.7, 2026-12-07) */
    {
        static const float qmus[4] = { 1.0f, 0.7f, 0.3f, 0.08f };
        double worst = 0.0;
        char at[120] = "";
        int ri2, an;
        for (ri2 = 3; ri2 <= 10; ri2 += h_quick() || h_sanitized() ? 2 : 1)
            for (an = 0; an < 2; ++an)
                for (k = 0; k < 4; ++k) {
                    appear_openpbr_params p = appear_openpbr_params_default();
                    appear_openpbr m;
                    double st = sqrt(1.0 - (double)qmus[k] * qmus[k]), q;
                    p.base_color = appear_spectrum_splat(1.0f);
                    p.base_metalness = 1.0f;
                    p.specular_roughness = 0.1f * (float)ri2;
                    p.specular_roughness_anisotropy = an ? 0.9f : 0.5f;
                    m = appear_openpbr_make(&p);
                    q = op_quad_tol(&m, appear_vec3_make((float)(st * 0.8), (float)(st * 0.6), qmus[k]), 1, 0, 1e-6);
                    if (fabs(q - 1.0) > worst) {
                        worst = fabs(q - 1.0);
                        snprintf(at, sizeof at, "r %.1f a %g mu %g: %.5f", 0.1 * ri2, an ? 0.9 : 0.5, (double)qmus[k], q);
                    }
                }
        h_measure("openpbr white furnace", "the anisotropic metal alone (anisotropy 0.5, 0.9; roughness 0.3 .. 1): "
                  "quadrature max |E - 1| %.2g at %s", worst, at);
        H_CHECK(worst <= 1e-3, "the anisotropic metal alone: furnace %.3g (bound 1e-3) at %s", worst, at);
    }
    /* the anisotropic glass alone off the grid's view azimuth and IORs (the grid's wo lies 37
       degrees from the rougher axis, and its IORs 1.5 and 3 are nodes of the anisotropic
       dielectric table's e axis): anisotropy 0.5, IOR 1.33 and 2, wo 74 degrees from the rougher
       axis, both sides, by quadrature; held to what is measured, twenty-sixth session: 8.2e-3
       below 1 at IOR 1.33 from inside, r 1, mu 0.7, 1.5e-3 above 1 (9.9e-3 and 1.7e-3 before the
       inside base's groove index ratio; 7.8e-3 with the table's 6 alpha nodes, by a throwaway's
       stratified mean weight): outside the 1e-3, open in issue 33) */
    {
        static const float gmus[6] = { 1.0f, 0.7f, 0.3f, 0.08f, -0.7f, -0.3f }, giors[2] = { 1.33f, 2.0f };
        double worst = 0.0, up = 0.0;
        char at[120] = "";
        int ri2, ii;
        for (ri2 = 0; ri2 < 3; ++ri2)
            for (ii = 0; ii < 2; ++ii)
                for (k = 0; k < 6; ++k) {
                    /* the white glass (base 3) of the grid's configurations, no coat, no fuzz */
                    op_white w = { 3, 0.0f, 0.0f, 0.3f, 0.5f, 1.33f, 0.0f, 0.0f, 0.0f, 0.0f };
                    appear_openpbr_params p;
                    appear_openpbr m;
                    double st = sqrt(1.0 - (double)gmus[k] * gmus[k]), q;
                    if ((h_quick() && (ri2 + k) % 2) || (h_sanitized() && (ri2 != 2 || k % 2))) continue;
                    w.rough = ri2 == 0 ? 0.3f : ri2 == 1 ? 0.6f : 1.0f;
                    w.ior = giors[ii];
                    p = op_white_params(&w);
                    m = appear_openpbr_make(&p);
                    q = op_quad(&m, appear_vec3_make((float)(st * 0.2675), (float)(st * 0.9636), gmus[k]), 1, 0);
                    up = fmax(up, q - 1.0);
                    if (fabs(q - 1.0) > worst) {
                        worst = fabs(q - 1.0);
                        snprintf(at, sizeof at, "r %g ior %g mu %g: %.5f", (double)w.rough, (double)w.ior,
                                 (double)gmus[k], q);
                    }
                }
        h_measure("openpbr white furnace", "the anisotropic glass alone off the grid's azimuth and IORs (anisotropy "
                  "0.5, IOR 1.33 and 2, 74 degrees): quadrature max |E - 1| %.2g at %s, above 1 %.2g", worst, at, up);
        H_CHECK(worst <= 1e-2 && up <= 2e-3, "the anisotropic glass off the grid: furnace %.3g (bound 1e-2), above "
                "1 %.3g (bound 2e-3) at %s", worst, up, at);
    }
    /* strong anisotropy (0.9 and 1, the corner) at roughness 0.3, 0.8 and 1 and IOR 1.5 and 3
       (the coat's: its default 1.6, and 3; until the twenty-seventh session IOR 1.5 and roughness
       0.8 and 1), wo along either axis and between, and the glass from inside at 84 degrees (where
       the isotropic table read 1.385 before the dielectric's own): the metal's compensation reads
       the anisotropic table
       (appear_conductor_albedo_aniso), the dielectric's R, E and E_T = E - R theirs
       (appear_dielectric_albedo_aniso, _reflect_albedo_aniso; an interpolated correction over the
       isotropic tables): measured, held so that it cannot get worse unseen. Per base: 0 metal, 1
       a dielectric over a white diffuse, 2 glass (both sides), 3 a white diffuse under a white coat of
       that roughness and anisotropy (its R from the dielectric's table) */
    {
        static const float amus[5] = { 1.0f, 0.7f, 0.3f, -0.7f, -0.1f }, aphi[3] = { 0.0f, 0.7853982f, 1.5707963f };
        static const float srough[3] = { 0.3f, 0.8f, 1.0f };
        double low[4] = { 2, 2, 2, 2 }, high[4] = { 0, 0, 0, 0 };
        char where_l[4][120] = { "", "", "", "" }, where_h[4][120] = { "", "", "", "" }, at[120];
        int ri2, an, ph, io;
        for (b = 0; b < 4; ++b)
            for (io = 0; io < 2; ++io) /* IOR 1.5 (the coat's default 1.6), and 3 */
                for (ri2 = 0; ri2 < 3; ++ri2)
                    for (an = 0; an < 2; ++an)
                        for (k = 0; k < 5; ++k)
                            for (ph = 0; ph < 3; ++ph) {
                                /* op_white's bases: 1 metal, 0 diffuse, 3 translucent; the coat's turn
                                   (b 3): the specular lobe at its default roughness 0.3 */
                                op_white w = { 0, 0.0f, 0.0f, 0.0f, 0.0f, 1.5f, 0.0f, 0.0f, 0.0f, 0.0f };
                                appear_openpbr_params p;
                                appear_openpbr m;
                                double st = sqrt(1.0 - (double)amus[k] * amus[k]), mean;
                                appear_vec3 wo = appear_vec3_make((float)(st * cos(aphi[ph])),
                                                                  (float)(st * sin(aphi[ph])), amus[k]);
                                float rough = srough[ri2], aniso = an ? 1.0f : 0.9f, ior = io ? 3.0f : 1.5f;
                                if (b != 2 && k >= 3) continue; /* opaque: two-sided */
                                if (h_quick() && (io + ri2 + an + k + ph) % 2) continue;
                                w.base = b == 0 ? 1 : b == 2 ? 3 : 0;
                                if (b == 3) {
                                    w.coat = 1.0f; w.coat_rough = rough; w.coat_aniso = aniso;
                                    w.coat_ior = io ? 3.0f : 0.0f; w.rough = 0.3f;
                                } else {
                                    w.rough = rough; w.aniso = aniso; w.ior = ior;
                                }
                                p = op_white_params(&w);
                                m = appear_openpbr_make(&p);
                                /* (on a grid of 400^2 samples, 100^2 in quick mode: a random mean's
                                   se, 0.002 at 40000 samples, hid these extremes' distance from 1;
                                   200^2 read the dielectric over diffuse at r 1 a 0.9 mu 0.3 along
                                   the smoother axis 0.9981, where quadrature and 400^2 read 0.9995) */
                                mean = h_sample_mean_grid(op_sample, &m, wo, h_quick() ? 100 : 400, 1);
                                snprintf(at, sizeof at, "ior %g r %g a %g mu %g phi %d: %.5f", (double)ior,
                                         (double)rough, (double)aniso, (double)amus[k], 45 * ph, mean);
                                if (mean < low[b]) { low[b] = mean; strcpy(where_l[b], at); }
                                if (mean > high[b]) { high[b] = mean; strcpy(where_h[b], at); }
                            }
        for (b = 0; b < 4; ++b)
            h_measure("openpbr white furnace", "anisotropy 0.9 and 1, roughness 0.3, 0.8 and 1, IOR 1.5 and 3, %s: "
                      "lowest %s, highest %s "
                      "(the mean weight on a grid of %d^2 samples)",
                      b == 0 ? "metal" : b == 1 ? "dielectric over diffuse" : b == 2 ? "glass, both sides"
                                                                                    : "coat over diffuse",
                      where_l[b], where_h[b], h_quick() ? 100 : 400);
        /* (measured, the mean weight on the grid, full mode (quick): metal 0.99989 .. 1.00068 (0.99982
           .. 1.00062); dielectric over diffuse 0.99753 .. 1.00078 (0.99786 .. 1.00299), the lowest at
           IOR 3, r 1, anisotropy 0.9, mu 0.3 along the smoother axis (R 2.5e-3 high there: the alpha
           and b / a interpolation, each about half), the highest at IOR 1.5, r 1, anisotropy 1, mu 0.3
           along that axis; glass 0.99177 .. 1.00833 (0.99136 .. 1.00837), the lowest at IOR 1.5, r 1,
           anisotropy 0.9, mu -0.1 along the rougher axis, the highest at IOR 3 there between the
           axes; coat over diffuse 0.99751 .. 1.00066 (0.99788 .. 1.00185), the lowest where the
           dielectric's. Twenty-seventh session: R's block of the anisotropic dielectric's table has 7
           rho and 12 mu nodes of its own and a cubic read along mu; the dielectric over diffuse read
           1.0018 (quadrature 1.0018, R 1.8e-3 low) at IOR 1.5, r 0.8, anisotropy 0.9, mu 0.3 along the
           smoother axis, now 1.0005; at IOR 3, r 1, anisotropy 0.9 R was 1.8e-3 high before. At IOR 1.5
           and r 0.8 and 1 alone, on 200^2 cells, before: metal 0.9999 .. 1.0007; dielectric over
           diffuse 0.9992 .. 1.0018; glass 0.9930 .. 1.0072 (800^2: 0.9924 .. 1.0078); coat over
           diffuse 0.9987 .. 1.0012. Twenty-sixth session: the anisotropic dielectric's inside base
           reads a groove surface's index ratio and its inside azimuth has a knee; by the random mean
           (40000 samples, the extremes by mean -+ 4 se, se 0.002) the glass read 0.994 .. 1.007, and
           1.029 at mu -0.1 at 45 degrees before; 0.983 .. 1.032 with 4 outside e and 6 alpha nodes,
           0.961 .. 1.033 before the inside table's base carried the F = 1 ratio, 2026-12-07; with the
           isotropic dielectric tables carried over by the F = 1 lobe's anisotropic ratio: dielectric
           0.990 .. 1.004, glass 0.823 .. 1.027 without the grazing inside point, where it read 1.385;
           before the anisotropic table the metal read down to 0.65 at anisotropy 0.9 and roughness
           0.8) */
        /* (the 1 -+ 1e-3 holds for the metal and above 1 for the dielectric over diffuse and
           the coat; below, and for the glass, the measured extremes are held; quick mode's 100^2
           cells err by up to 2e-3 on the peaked lobes) */
        {
            int q = h_quick();
            H_CHECK(low[0] >= 0.999 && high[0] <= 1.001, "strong anisotropy, metal: furnace %.5g .. %.5g (bounds "
                    "0.999, 1.001)", low[0], high[0]);
            H_CHECK(low[1] >= (q ? 0.996 : 0.997) && high[1] <= (q ? 1.004 : 1.001), "strong anisotropy, "
                    "dielectric: furnace %.5g .. %.5g (bounds %.3f, %.3f)", low[1], high[1], q ? 0.996 : 0.997,
                    q ? 1.004 : 1.001);
            H_CHECK(low[2] >= 0.99 && high[2] <= 1.01, "strong anisotropy, glass: furnace %.5g .. %.5g (bounds "
                    "0.99, 1.01)", low[2], high[2]);
            H_CHECK(low[3] >= (q ? 0.996 : 0.997) && high[3] <= (q ? 1.004 : 1.001), "strong anisotropy, coat "
                    "over diffuse: furnace %.5g .. %.5g (bounds %.3f, %.3f)", low[3], high[3], q ? 0.996 : 0.997,
                    q ? 1.004 : 1.001);
        }
    }
}

static int op_same_bits(appear_spectrum a, appear_spectrum b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

void suite_openpbr_corners(void)
{
    h_rng r = h_rng_make(7);
    int i, bad_metal = 0, bad_coat0 = 0, bad_fuzz0 = 0, bad_lambert = 0, bad_fuzz = 0, bad_coat = 0;
    double slice_free = 0.0;
    h_case("openpbr: corners to the bit: metal = F82 compensated conductor, coat/fuzz weight 0 = none, "
           "diffuse at roughness 0 = Lambert, fuzz alone = sheen, coat alone = the coat's reflection");
    for (i = 0; i < 2000; ++i) {
        appear_vec3 wo = op_upper(&r), wi = op_upper(&r);
        appear_openpbr_params p = appear_openpbr_params_default(), q;
        appear_openpbr m, n;
        p.base_color = op_rgb(&r);
        p.specular_color = op_rgb(&r);
        p.specular_roughness = 0.05f + 0.95f * h_randf(&r);
        p.specular_roughness_anisotropy = h_randf(&r);
        p.base_diffuse_roughness = h_randf(&r);
        /* metal alone, isotropic and anisotropic (the compensation's E from the anisotropic table
           through the lobe's slice, the conductor's through the free function: they differ by
           the read alone, measured below) */
        q = p; q.base_metalness = 1.0f;
        if (i & 1) q.specular_roughness_anisotropy = 0.0f;
        m = appear_openpbr_make(&q);
        {
            float at = q.specular_roughness * q.specular_roughness *
                       sqrtf(2.0f / (1.0f + (1.0f - q.specular_roughness_anisotropy) *
                                               (1.0f - q.specular_roughness_anisotropy)));
            appear_microfacet d = appear_microfacet_make(APPEAR_GGX, fminf(at, 1.0f),
                                                         fminf((1.0f - q.specular_roughness_anisotropy) * at, 1.0f),
                                                         APPEAR_SAMPLE_VISIBLE);
            appear_conductor c = appear_conductor_make_f82(d, q.base_color, q.specular_color);
            appear_spectrum want = appear_conductor_comp_eval(&c, wo, wi);
            if (d.ax != d.ay) { /* the material's lobe reads E from its slice (appear.h SECTION tables):
                                   the same table, bicubic in c where the free function is linear */
                appear__aniso_slice s = appear__aniso_slice_make(d.ax, d.ay);
                float es = appear__aniso_slice_read(&s, wo), ef = appear_conductor_albedo_aniso(d.ax, d.ay, wo);
                want = appear__spectrum_mul_capped(appear_conductor_eval(&c, wo, wi),
                                                   appear__comp_factor(appear__conductor_F(&c, 1.0f), es));
                slice_free = fmax(slice_free, fabs(es / ef - 1.0));
            }
            bad_metal += !op_same_bits(appear_openpbr_eval(&m, wo, wi), want);
        }
        /* coat and fuzz of weight 0, whatever their other parameters */
        q = p; q.coat_roughness = h_randf(&r); q.coat_ior = 1.2f + h_randf(&r); q.coat_color = q.base_color;
        q.coat_darkening = h_randf(&r);
        m = appear_openpbr_make(&p); n = appear_openpbr_make(&q);
        bad_coat0 += !op_same_bits(appear_openpbr_eval(&m, wo, wi), appear_openpbr_eval(&n, wo, wi));
        q = p; q.fuzz_roughness = h_randf(&r); q.fuzz_color = q.base_color;
        n = appear_openpbr_make(&q);
        bad_fuzz0 += !op_same_bits(appear_openpbr_eval(&m, wo, wi), appear_openpbr_eval(&n, wo, wi));
        /* the diffuse base alone at roughness 0: Lambert */
        q = p; q.specular_weight = 0.0f; q.base_diffuse_roughness = 0.0f;
        m = appear_openpbr_make(&q);
        {
            appear_lambert l = appear_lambert_make(q.base_color);
            bad_lambert += !op_same_bits(appear_openpbr_eval(&m, wo, wi), appear_lambert_eval(&l, wo, wi));
        }
        /* the fuzz alone (no base below it), the coat alone */
        q = p; q.base_weight = 0.0f; q.specular_weight = 0.0f; q.fuzz_weight = 1.0f;
        q.fuzz_color = p.base_color; q.fuzz_roughness = 0.05f + 0.95f * h_randf(&r);
        m = appear_openpbr_make(&q);
        {
            appear_sheen s = appear_sheen_make(q.fuzz_color, q.fuzz_roughness);
            bad_fuzz += !op_same_bits(appear_openpbr_eval(&m, wo, wi), appear_sheen_eval(&s, wo, wi));
        }
        q = p; q.base_weight = 0.0f; q.specular_weight = 0.0f; q.coat_weight = 1.0f;
        q.coat_roughness = 0.2f + 0.8f * h_randf(&r); q.coat_ior = 1.1f + 1.5f * h_randf(&r);
        m = appear_openpbr_make(&q);
        {
            float a = q.coat_roughness * q.coat_roughness;
            appear_dielectric e = appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, a, a,
                                                                                APPEAR_SAMPLE_VISIBLE), q.coat_ior);
            appear_spectrum f = appear_openpbr_eval(&m, wo, wi), g = appear_dielectric_eval(&e, wo, wi);
            bad_coat += !(f.v[0] == g.v[0] && f.v[1] == g.v[0] && f.v[2] == g.v[0]);
        }
    }
    {   /* the glass alone (transmission 1, no coat): its reflection side is the dielectric's
           reflection (to 1e-5: the modulated IOR is rebuilt from its F_s); smooth, its records are the smooth dielectric's coefficients, F
           reflected and (1 - F) / eta^2 refracted, from outside and from inside */
        double worst = 0;
        int bad_refl = 0;
        for (i = 0; i < 500; ++i) {
            appear_openpbr_params q = appear_openpbr_params_default();
            appear_openpbr m;
            appear_bsdf_record s;
            appear_vec3 wo = op_upper(&r), wi = op_upper(&r);
            float e, uc, u1, u2;
            q.transmission_weight = 1.0f;
            q.specular_ior = 1.1f + 1.9f * h_randf(&r);
            q.specular_roughness = 0.2f + 0.8f * h_randf(&r);
            m = appear_openpbr_make(&q);
            {
                float a = q.specular_roughness * q.specular_roughness;
                appear_dielectric d = appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, a, a,
                                                                                    APPEAR_SAMPLE_VISIBLE),
                                                             q.specular_ior);
                double f = appear_openpbr_eval(&m, wo, wi).v[1], g = appear_dielectric_eval(&d, wo, wi).v[0];
                bad_refl += fabs(f - g) > 1e-5 * g; /* eta rebuilt from F_s: a few ulp */
            }
            q.specular_roughness = 0.0f;
            m = appear_openpbr_make(&q);
            if (i % 2) wo.z = -wo.z;
            e = wo.z > 0.0f ? q.specular_ior : 1.0f / q.specular_ior;
            uc = h_randf(&r); u1 = h_randf(&r); u2 = h_randf(&r);
            if (appear_openpbr_sample(&m, wo, uc, u1, u2, &s)) {
                double F = h_fresnel_dielectric(fabs(wo.z), e);
                double want = (s.flags & APPEAR_LOBE_TRANSMISSION) ? (1.0 - F) / ((double)e * e) : F;
                double got = (double)s.weight.v[0] * s.pdf;
                if (fabs(got - want) / want > worst) worst = fabs(got - want) / want;
            }
        }
        /* the thin-walled smooth sheet ("Thin-walled mode", the reduction's form): F reflected,
           1 - F straight through (wi = -wo), from either side */
        for (i = 0; i < 500; ++i) {
            appear_openpbr_params q = appear_openpbr_params_default();
            appear_openpbr m;
            appear_bsdf_record s;
            appear_vec3 wo = op_upper(&r);
            float uc, u1, u2;
            q.transmission_weight = 1.0f;
            q.geometry_thin_walled = 1;
            q.specular_ior = 1.1f + 1.9f * h_randf(&r);
            q.specular_roughness = 0.0f;
            m = appear_openpbr_make(&q);
            if (i % 2) wo.z = -wo.z;
            uc = h_randf(&r); u1 = h_randf(&r); u2 = h_randf(&r);
            if (appear_openpbr_sample(&m, wo, uc, u1, u2, &s)) {
                double F = h_fresnel_dielectric(fabs(wo.z), q.specular_ior);
                int through = (s.flags & APPEAR_LOBE_TRANSMISSION) != 0;
                double want = through ? 1.0 - F : F, got = (double)s.weight.v[0] * s.pdf;
                if (fabs(got - want) / want > worst) worst = fabs(got - want) / want;
                bad_refl += through && !(s.wi.x == -wo.x && s.wi.y == -wo.y && s.wi.z == -wo.z);
            }
        }
        h_measure("openpbr smooth glass", "records' coefficients vs the smooth dielectric's and the thin sheet's: max "
                  "rel %.2g", worst);
        H_CHECK(!bad_refl && worst < 1e-5, "glass alone: %d of 500 reflections differ from the dielectric's by > 1e-5; "
                "smooth coefficients max rel %.3g (bound 1e-5)", bad_refl, worst);
    }
    h_measure("openpbr corners", "anisotropic metal: the lobe's slice against the free read of the same table, "
              "max relative %.2g", slice_free);
    H_CHECK(!bad_metal && !bad_coat0 && !bad_fuzz0 && !bad_lambert && !bad_fuzz && !bad_coat,
            "of 2000: metal %d, coat weight 0 %d, fuzz weight 0 %d, Lambert %d, fuzz alone %d, coat alone %d "
            "differ", bad_metal, bad_coat0, bad_fuzz0, bad_lambert, bad_fuzz, bad_coat);
    /* (each within its own error of the double integration: tests/test_multiscatter.c) */
    H_CHECK(slice_free < 3e-3, "anisotropic metal: slice and free read differ by %.3g (bound 3e-3)", slice_free);
}

void suite_openpbr_pdf(void)
{
    h_rng r = h_rng_make(11);
    double worst_int = 0, worst_rec = 0;
    int t, k, bad_side = 0;
    h_case("openpbr: int pdf = rate of non-delta samples (4 se), records = pdf() and eval() (1e-5)");
    for (t = 0; t < 24; ++t) { /* t >= 16: translucent, wo outside and inside; t >= 20 thin-walled */
        appear_openpbr_params p = appear_openpbr_params_default();
        appear_openpbr m;
        p.base_color = op_rgb(&r);
        p.base_metalness = (t % 3) * 0.5f;
        p.specular_roughness = 0.3f + 0.7f * h_randf(&r);
        p.specular_roughness_anisotropy = (t % 2) * h_randf(&r);
        p.coat_weight = (t % 4) * 0.33f;
        p.coat_roughness = (t % 5 == 0) ? 0.0f : 0.3f + 0.7f * h_randf(&r);
        p.coat_color = appear_spectrum_rgb(0.5f + 0.5f * h_randf(&r), 0.9f, 1.0f);
        p.fuzz_weight = (t % 3 == 1) ? h_randf(&r) : 0.0f;
        p.transmission_weight = t >= 16 ? 0.3f + 0.7f * h_randf(&r) : 0.0f;
        p.transmission_color = op_rgb(&r);
        p.geometry_thin_walled = t >= 20; /* a sheet: glass and a subsurface sheet */
        p.subsurface_weight = t >= 20 ? 1.0f : 0.0f;
        p.subsurface_scatter_anisotropy = 0.5f * (float)(t - 21);
        m = appear_openpbr_make(&p);
        for (k = 0; k < (t >= 16 ? 5 : 3); ++k) {
            float mu = k == 0 ? 0.9f : k == 1 ? 0.4f : k == 2 ? 0.05f : k == 3 ? -0.8f : -0.3f;
            double st = sqrt(1.0 - (double)mu * mu), se, nd, integ;
            appear_vec3 wo = appear_vec3_make((float)st, 0.0f, mu);
            long i, n = h_n(20000);
            if (h_sanitized() && (t + k) % 3 != 0) continue; /* a third of the directions there */
            (void)op_mean(&m, wo, n, &r, 0, &se, &nd);
            integ = op_quad(&m, wo, 0, 1);
            /* in se of the rate, plus the quadrature's own tolerance */
            if (fabs(integ - nd) / (sqrt(nd * (1.0 - nd) / n) + 1e-4) > worst_int)
                worst_int = fabs(integ - nd) / (sqrt(nd * (1.0 - nd) / n) + 1e-4);
            for (i = 0; i < 2000; ++i) {
                appear_bsdf_record q;
                float uc = h_randf(&r), u1 = h_randf(&r), u2 = h_randf(&r);
                if (!appear_openpbr_sample(&m, wo, uc, u1, u2, &q)) continue;
                bad_side += t < 16 && q.wi.z <= 0.0f; /* opaque: never across */
                if (!(q.flags & APPEAR_LOBE_SPECULAR)) {
                    double pp = appear_openpbr_pdf(&m, wo, q.wi), ff = appear_openpbr_eval(&m, wo, q.wi).v[0];
                    double e = fmax(fabs(pp - q.pdf) / fmax(pp, 1e-30), fabs(ff - q.f.v[0]) / fmax(ff, 1e-30));
                    if (e > worst_rec) worst_rec = e;
                }
            }
        }
    }
    h_measure("openpbr pdf", "int pdf vs non-delta rate max %.2f se; records vs pdf()/eval() max rel %.2g",
              worst_int, worst_rec);
    H_CHECK(worst_int < 4.0 && worst_rec < 1e-5 && !bad_side, "int pdf %.2f se (bound 4), records %.3g "
            "(bound 1e-5), %d samples below the surface", worst_int, worst_rec, bad_side);
}

/* chi-square of the sampler against pdf() (non-delta lobes) */
typedef struct { const appear_openpbr *m; appear_vec3 wo; } op_chi;
static int op_chi_sample(void *ctx, float uc, float u1, float u2, appear_vec3 *wi)
{
    const op_chi *c = (const op_chi *)ctx;
    appear_bsdf_record q;
    if (!appear_openpbr_sample(c->m, c->wo, uc, u1, u2, &q) || (q.flags & APPEAR_LOBE_SPECULAR)) return 0;
    *wi = q.wi;
    return 1;
}
static double op_chi_pdf(void *ctx, appear_vec3 wi)
{
    const op_chi *c = (const op_chi *)ctx;
    return appear_openpbr_pdf(c->m, c->wo, wi);
}
void suite_openpbr_chi2(void)
{
    static const float mus[] = { 0.8f, 0.3f };
    int t, k;
    for (t = 0; t < 5; ++t)
        for (k = 0; k < 2; ++k) {
            appear_openpbr_params p = appear_openpbr_params_default();
            appear_openpbr m;
            op_chi c;
            h_chi2_spec s;
            char name[96];
            double st = sqrt(1.0 - (double)mus[k] * mus[k]);
            p.base_metalness = t == 1 ? 0.6f : 0.0f;
            p.specular_roughness = 0.4f;
            p.coat_weight = t >= 1 ? 0.7f : 0.0f;
            p.coat_roughness = 0.3f;
            p.fuzz_weight = t == 2 ? 0.5f : 0.0f;
            p.transmission_weight = t == 3 ? 0.8f : t == 4 ? 0.3f : 0.0f; /* a frosted glass, both sides */
            p.geometry_thin_walled = t == 4; /* paper: a subsurface sheet with some glass */
            p.subsurface_weight = t == 4 ? 1.0f : 0.0f;
            p.subsurface_scatter_anisotropy = t == 4 ? 0.2f : 0.0f;
            m = appear_openpbr_make(&p);
            c.m = &m; c.wo = appear_vec3_make((float)st, 0.0f, t >= 3 && k == 1 ? -mus[k] : mus[k]);
            snprintf(name, sizeof name, "openpbr_%s_mu%.1f",
                     t == 0 ? "plastic" : t == 1 ? "coated_metal" : t == 2 ? "fuzz" : t == 3 ? "glass" : "paper",
                     (double)c.wo.z);
            memset(&s, 0, sizeof s);
            s.name = name; s.sample = op_chi_sample; s.pdf = op_chi_pdf; s.ctx = &c;
            s.axis = appear_vec3_make(-c.wo.x, -c.wo.y, c.wo.z); /* zmin 0: the whole sphere */
            s.seed = 100u + (unsigned)(t * 2 + k);
            h_case("openpbr: chi-square %s", name);
            h_chi2(&s);
        }
}

/* the interior medium of the translucent base ("Translucent base"): mu_t = -ln(T) / depth, mu_s =
   S / depth, mu_a = mu_t - mu_s shifted by grey where negative; none at depth 0 */
void suite_openpbr_medium(void)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    appear_openpbr m;
    appear_spectrum sig, alb;
    float g;
    double worst = 0;
    int has, k;
    h_case("openpbr: interior medium: mu_t = -ln(colour) / depth, albedo = mu_s / mu_t, grey shift; none at depth 0");
    p.transmission_weight = 1.0f;
    p.transmission_color = appear_spectrum_rgb(0.5f, 0.8f, 0.9f);
    p.transmission_scatter = appear_spectrum_rgb(0.2f, 0.1f, 0.9f);
    p.transmission_scatter_anisotropy = 0.4f;
    p.transmission_depth = 2.0f;
    m = appear_openpbr_make(&p);
    has = appear_openpbr_medium(&m, &sig, &alb, &g);
    {   /* mu_a = (ln 2 - 0.2, -ln 0.8 - 0.1, -ln 0.9 - 0.9) / 2: the blue one negative, shifted */
        double mut[3] = { -log(0.5) / 2, -log(0.8) / 2, -log(0.9) / 2 }, mus[3] = { 0.1, 0.05, 0.45 }, mua[3], lo = 0;
        for (k = 0; k < 3; ++k) { mua[k] = mut[k] - mus[k]; lo = fmin(lo, mua[k]); }
        for (k = 0; k < 3 && k < APPEAR_SPECTRUM_SAMPLES; ++k) {
            double t = mua[k] - lo + mus[k];
            worst = fmax(worst, fabs(sig.v[k] - t) / t);
            worst = fmax(worst, fabs(alb.v[k] - mus[k] / t) / (mus[k] / t));
        }
    }
    H_CHECK(has && worst < 1e-5 && g == 0.4f, "medium: has %d, max rel error %.3g (bound 1e-5), g %g", has, worst,
            (double)g);
    p.transmission_depth = 0.0f;
    m = appear_openpbr_make(&p);
    H_CHECK(!appear_openpbr_medium(&m, &sig, &alb, &g) && sig.v[0] == 0.0f && m.ttint.v[0] == 0.5f,
            "depth 0: a medium reported, or the BTDF not tinted by transmission_color");
    /* the subsurface medium: van de Hulst's C(albedo) [OpenPBR11, "Subsurface"] applied to the
       returned albedo gives subsurface_color back; sigma_t = 1 / (radius radius_scale) */
    h_case("openpbr: subsurface medium: van de Hulst's C(albedo) = subsurface_color, sigma_t = 1 / mfp");
    {
        static const float cs[] = { 0.0f, 0.05f, 0.3f, 0.8f, 0.99f, 1.0f }, gs[] = { -0.7f, 0.0f, 0.9f };
        int ci, gi;
        worst = 0;
        for (ci = 0; ci < 6; ++ci)
            for (gi = 0; gi < 3; ++gi) {
                double a, sv, c;
                p = appear_openpbr_params_default();
                p.subsurface_weight = 1.0f;
                p.subsurface_color = appear_spectrum_splat(cs[ci]);
                p.subsurface_scatter_anisotropy = gs[gi];
                p.subsurface_radius = 0.5f;
                m = appear_openpbr_make(&p);
                has = appear_openpbr_subsurface(&m, &sig, &alb, &g);
                a = alb.v[0];
                sv = sqrt((1.0 - a) / (1.0 - a * gs[gi]));
                c = (1.0 - sv) * (1.0 - 0.139 * sv) / (1.0 + 1.17 * sv);
                worst = fmax(worst, fabs(c - cs[ci]));
                H_CHECK(has && fabs(sig.v[0] - 2.0) < 1e-6 && fabs(sig.v[2] - 8.0) < 1e-5 && g == gs[gi],
                        "C %g g %g: has %d, sigma_t %g %g (want 2, 8), g %g", (double)cs[ci], (double)gs[gi], has,
                        (double)sig.v[0], (double)sig.v[2], (double)g);
            }
        h_measure("openpbr subsurface", "van de Hulst round trip: max |C(albedo) - colour| %.2g", worst);
        H_CHECK(worst < 2e-3, "van de Hulst round trip %.3g (bound 2e-3)", worst);
        p = appear_openpbr_params_default();
        m = appear_openpbr_make(&p);
        H_CHECK(!appear_openpbr_subsurface(&m, &sig, &alb, &g), "subsurface_weight 0: a medium reported");
    }
}

void suite_openpbr_bad(void)
{
    appear_openpbr_params p = appear_openpbr_params_default(), q;
    appear_openpbr m, n;
    appear_vec3 wo = appear_vec3_make(0.0f, 0.6f, 0.8f), wi = appear_vec3_make(0.6f, 0.0f, 0.8f);
    appear_bsdf_record s;
    volatile float zero = 0.0f;
    float nan = zero / zero, inf = 1.0f / zero;
    h_case("openpbr: NaN / Inf parameters invalid (a film without SECTION thinfilm too); out-of-range values clamped");
    q = p; q.coat_ior = nan; m = appear_openpbr_make(&q);
    H_CHECK(!m.valid && appear_openpbr_eval(&m, wo, wi).v[0] == 0.0f && appear_openpbr_pdf(&m, wo, wi) == 0.0f &&
                !appear_openpbr_sample(&m, wo, 0.5f, 0.5f, 0.5f, &s) && s.flags == 0u,
            "NaN coat_ior: valid %d", m.valid);
    q = p; q.base_color.v[1] = inf; m = appear_openpbr_make(&q);
    H_CHECK(!m.valid, "Inf base_color: valid %d", m.valid);
    q = p; q.transmission_weight = 0.5f; q.transmission_depth = nan; m = appear_openpbr_make(&q);
    H_CHECK(!m.valid, "NaN transmission_depth: valid %d", m.valid);
#ifdef APPEAR_HAS_THINFILM
    /* the film's parameters: NaN or infinite invalid (whatever the weight); out of range clamped
       (thickness >= 0: a negative one is no film; thin_film_ior > 0: into [1e-3, 100]) */
    q = p; q.thin_film_thickness = nan; m = appear_openpbr_make(&q);
    H_CHECK(!m.valid, "NaN thin_film_thickness: valid %d", m.valid);
    q = p; q.thin_film_weight = 1.0f; q.thin_film_ior = nan; m = appear_openpbr_make(&q);
    H_CHECK(!m.valid, "NaN thin_film_ior: valid %d", m.valid);
    q = p; q.thin_film_weight = 1.0f; q.thin_film_thickness = inf; m = appear_openpbr_make(&q);
    H_CHECK(!m.valid, "Inf thin_film_thickness: valid %d", m.valid);
    q = p; q.thin_film_weight = 1.0f; m = appear_openpbr_make(&q);
    H_CHECK(m.valid && m.film, "thin_film_weight 1: valid %d, film %d", m.valid, m.film);
    q = p; q.thin_film_weight = 1.0f; q.thin_film_thickness = -2.0f; m = appear_openpbr_make(&q);
    n = appear_openpbr_make(&p);
    H_CHECK(m.valid && !m.film && op_same_bits(appear_openpbr_eval(&m, wo, wi), appear_openpbr_eval(&n, wo, wi)),
            "thin_film_thickness -2: not clamped to 0 (no film): valid %d, film %d", m.valid, m.film);
    q = p; q.thin_film_weight = 3.0f; q.thin_film_ior = -1.0f; q.thin_film_thickness = 50.0f;
    m = appear_openpbr_make(&q);
    q.thin_film_weight = 1.0f; q.thin_film_ior = 1e-3f; q.thin_film_thickness = 30.0f;
    n = appear_openpbr_make(&q);
    H_CHECK(m.valid && m.film && op_same_bits(appear_openpbr_eval(&m, wo, wi), appear_openpbr_eval(&n, wo, wi)),
            "thin_film_weight 3 / _ior -1 / _thickness 50 not clamped to 1 / 1e-3 / 30");
#else
    q = p; q.thin_film_weight = 1.0f; m = appear_openpbr_make(&q);
    H_CHECK(!m.valid, "thin_film_weight 1 without SECTION thinfilm: valid %d", m.valid);
#endif
    q = p; q.geometry_thin_walled = 1; q.subsurface_radius = inf; m = appear_openpbr_make(&q);
    H_CHECK(!m.valid, "Inf subsurface_radius: valid %d", m.valid);
    q = p; q.base_color = appear_spectrum_splat(7.0f); q.specular_roughness = -3.0f;
    m = appear_openpbr_make(&q);
    q.base_color = appear_spectrum_splat(1.0f); q.specular_roughness = 0.0f;
    n = appear_openpbr_make(&q);
    H_CHECK(m.valid && op_same_bits(appear_openpbr_eval(&m, wo, wi), appear_openpbr_eval(&n, wo, wi)),
            "base_color 7 / specular_roughness -3 not clamped to 1 / 0");
}

/* the bits of eval, pdf and a sample record of two models at a few directions */
static int op_same_model(const appear_openpbr *a, const appear_openpbr *b, h_rng *r)
{
    int k, same = 1;
    for (k = 0; k < 8; ++k) {
        appear_vec3 wo = h_rand_dir(r), wi = h_rand_dir(r);
        float uc = h_randf(r), u1 = h_randf(r), u2 = h_randf(r);
        appear_bsdf_record sa, sb;
        float pa = appear_openpbr_pdf(a, wo, wi), pb = appear_openpbr_pdf(b, wo, wi);
        int oa = appear_openpbr_sample(a, wo, uc, u1, u2, &sa), ob = appear_openpbr_sample(b, wo, uc, u1, u2, &sb);
        same &= op_same_bits(appear_openpbr_eval(a, wo, wi), appear_openpbr_eval(b, wo, wi));
        same &= memcmp(&pa, &pb, sizeof pa) == 0 && oa == ob && memcmp(&sa, &sb, sizeof sa) == 0;
    }
    return same;
}

/* a plain model (no coat, fuzz, film or thin walls) takes the cheap path (appear__openpbr_f_plain,
   the solo lobe's density, no state at wo; the diffuse lobe alone, diffuse_only, its eval, pdf
   and sample directly): the same bits as the general path, reached by clearing the flags; wo and
   wi over the sphere (a glass's refraction, its inside) */
void suite_openpbr_plain(void)
{
    static const float metals[4] = { 0.0f, 0.5f, 1.0f, -1.0f }, sws[3] = { 0.0f, 1.0f, -1.0f };
    static const float rough[4] = { 0.0f, 0.3f, 1.0f, -1.0f }, trans[3] = { 0.0f, 1.0f, -1.0f };
    h_rng r = h_rng_make(41);
    int a, b, c, k, bad = 0, plain = 0, solo = 0, dif = 0, n = 0;
    h_case("openpbr: a plain model's cheap path = the general path, to the bit (eval, pdf, sample)");
    for (a = 0; a < 4; ++a)
        for (b = 0; b < 3; ++b)
            for (c = 0; c < 4; ++c)
                for (k = 0; k < 18; ++k) {
                    appear_openpbr_params p = appear_openpbr_params_default();
                    appear_openpbr m, g;
                    p.base_color = op_rgb(&r);
                    p.specular_color = k == 5 ? appear_spectrum_splat(1.0f) : op_rgb(&r);
                    p.base_metalness = metals[a] < 0.0f ? h_randf(&r) : metals[a];
                    p.specular_weight = sws[b] < 0.0f ? h_randf(&r) : sws[b];
                    p.specular_roughness = rough[c] < 0.0f ? h_randf(&r) : rough[c];
                    p.specular_roughness_anisotropy = k & 1 ? h_randf(&r) : 0.0f;
                    p.base_diffuse_roughness = k & 2 ? h_randf(&r) : 0.0f;
                    p.specular_ior = 1.0f + 2.0f * h_randf(&r);
                    p.transmission_weight = trans[k / 6] < 0.0f ? h_randf(&r) : trans[k / 6];
                    p.transmission_color = op_rgb(&r);
                    m = appear_openpbr_make(&p);
                    g = m;
                    g.plain = 0;
                    g.solo = 0u;
                    g.diffuse_only = 0;
                    plain += m.plain;
                    solo += m.solo != 0u;
                    dif += m.diffuse_only;
                    n++;
                    bad += !op_same_model(&m, &g, &r);
                }
    H_CHECK(bad == 0 && plain == n && solo > 0 && solo < n && dif > 0 && dif < solo,
            "%d of %d models differ (%d plain, %d solo, %d diffuse alone)", bad, n, plain, solo, dif);
    {   /* with a coat, fuzz or a thin wall: not plain */
        appear_openpbr_params p = appear_openpbr_params_default(), q;
        appear_openpbr m;
        int not_plain = 0;
        q = p; q.coat_weight = 0.5f; m = appear_openpbr_make(&q); not_plain += !m.plain;
        q = p; q.fuzz_weight = 0.5f; m = appear_openpbr_make(&q); not_plain += !m.plain;
        q = p; q.geometry_thin_walled = 1; m = appear_openpbr_make(&q); not_plain += !m.plain;
        H_CHECK(not_plain == 3, "%d of 3 layered models not plain", not_plain);
    }
}

#ifdef APPEAR_HAS_THINFILM
/* ---- the thin film ("Thin-film iridescence") ---- */

/* (tests/test_multiscatter.c) the linear sRGB sensitivity of channel c at wavenumber nu (1/nm),
   unnormalised, from the raw Gaussian fit [BB17 supp.] */
double tf_ref_sens(int c, double nu);

/* A second form of the film the model uses, in double: absolute indices, the ambient n1 over the
   film (n2, d nm) over the base n3 + i k3, lit so that n1 sin(theta_1) = s (light from air: s =
   sin theta_air), one wavelength; the Airy sum [BW99, Sec. 1.6.4] per polarisation. */
static double op_airy(double s, double lambda, double n1, double n2, double d, double n3, double k3)
{
    double complex N3 = n3 + I * k3, c1 = csqrt(1.0 - (s / n1) * (s / n1)), c2 = csqrt(1.0 - (s / n2) * (s / n2));
    double complex c3 = csqrt(1.0 - (s / N3) * (s / N3)), e, r12, r23, r;
    double R = 0.0;
    int pol;
    if (cimag(N3 * c3) < 0.0) c3 = -c3; /* the wave in the base decays */
    e = cexp(I * 4.0 * M_PI * n2 * d * c2 / lambda);
    for (pol = 0; pol < 2; ++pol) {
        r12 = pol ? (n2 * c1 - n1 * c2) / (n2 * c1 + n1 * c2) : (n1 * c1 - n2 * c2) / (n1 * c1 + n2 * c2);
        r23 = pol ? (N3 * c2 - n2 * c3) / (N3 * c2 + n2 * c3) : (n2 * c2 - N3 * c3) / (n2 * c2 + N3 * c3);
        r = (r12 + r23 * e) / (1.0 + r12 * r23 * e);
        R += 0.5 * creal(r * conj(r));
    }
    return R;
}
/* its channel c of linear sRGB: the reflectance integrated over the wavenumber against the
   sensitivities (Simpson), clamped into [0, 1] as appear_thinfilm_rgb's */
static double op_airy_rgb(int c, double s, double n1, double n2, double d, double n3, double k3)
{
    const int n = 4000;
    const double a = 2e-4, b = 4e-3, h = (b - a) / n;
    double num = 0.0, den = 0.0;
    int i;
    for (i = 0; i <= n; ++i) {
        double nu = a + i * h, w = (i == 0 || i == n) ? 1.0 : (i & 1) ? 4.0 : 2.0, sc = tf_ref_sens(c, nu);
        num += w * sc * op_airy(s, 1.0 / nu, n1, n2, d, n3, k3);
        den += w * sc;
    }
    return fmin(1.0, fmax(0.0, num / den));
}

/* the mean sample energy of every channel from one run (op_sample: a refraction's weight times
   eta^2), and its largest se */
static appear_spectrum op_mean3(const appear_openpbr *m, appear_vec3 wo, long n, h_rng *r, double *se)
{
    double s[3] = { 0, 0, 0 }, s2[3] = { 0, 0, 0 };
    appear_spectrum mean;
    long i;
    int c;
    *se = 0.0;
    for (i = 0; i < n; ++i) {
        appear_bsdf_record q;
        float uc = h_randf(r), u1 = h_randf(r), u2 = h_randf(r);
        if (!op_sample(m, wo, uc, u1, u2, &q)) continue;
        for (c = 0; c < 3; ++c) { s[c] += q.weight.v[c]; s2[c] += (double)q.weight.v[c] * q.weight.v[c]; }
    }
    for (c = 0; c < 3; ++c) {
        mean.v[c] = (float)(s[c] / n);
        *se = fmax(*se, sqrt(fmax(0.0, s2[c] / n - (s[c] / n) * (s[c] / n)) / n));
    }
    return mean;
}

/* the spec's white-furnace list with the film on [OpenPBR11, "White furnace testing": "regardless
   of the presence of thin-film"]: the film only moves light between the specular lobe and what
   lies below it */
static void op_film_furnace(void)
{
    static const int bases[5] = { 0, 1, 2, 3, 5 };
    static const float roughs[3] = { 0.0f, 0.3f, 0.8f }, mus[3] = { 1.0f, 0.5f, 0.15f };
    double worst[2] = { 0, 0 }, up[2] = { 0, 0 }, worst_z = 0, low = 2.0;
    char where[2][160] = { "", "" }, where_low[160] = "";
    long n = h_n(8000);
    h_rng r = h_rng_make(35);
    int bi, ci, ri, k, c, points = 0;
    h_case("openpbr: thin film: white furnace (diffuse, metal, mix, glass, glass sheet; with and without a coat); "
           "opaque: quadrature and mean weight <= 1 + 1e-3, within 3e-3 of 1; translucent: <= 1 + 5e-3, within 1e-2");
    for (bi = 0; bi < 5; ++bi)
        for (ci = 0; ci < 2; ++ci)
            for (ri = 0; ri < 3; ++ri) {
                op_white w;
                appear_openpbr_params p;
                appear_openpbr m;
                int cl = bases[bi] >= 3, alt = (bi + ri) % 2;
                if ((bi + ci + ri) % (h_quick() ? 4 : 2) != 0) continue; /* half the grid (a quarter quick) */
                w.base = bases[bi]; w.coat = (float)ci; w.fuzz = 0.0f; w.rough = roughs[ri]; w.aniso = 0.0f;
                w.ior = alt ? 1.5f : 2.0f; w.coat_rough = 0.3f; w.diff_rough = 0.5f;
                w.coat_aniso = 0.0f; w.coat_ior = 0.0f;
                p = op_white_params(&w);
                p.thin_film_weight = alt ? 1.0f : 0.7f;
                p.thin_film_thickness = alt ? 0.3f : 0.8f;
                p.thin_film_ior = alt ? 1.4f : 2.0f;
                if (bases[bi] == 5 && ri == 0) p.specular_ior = 1.0f; /* a soap bubble: the film alone */
                m = appear_openpbr_make(&p);
                H_CHECK(m.valid && m.film, "film furnace config base %d: valid %d film %d", w.base, m.valid, m.film);
                for (k = 0; k < 3; ++k) {
                    double st = sqrt(1.0 - (double)mus[k] * mus[k]), se, q, e;
                    appear_vec3 wo = appear_vec3_make((float)(st * 0.6), (float)(st * 0.8), mus[k]);
                    appear_spectrum mean = op_mean3(&m, wo, n, &r, &se);
                    for (c = 0; c < 3; ++c) {
                        e = fabs(mean.v[c] - 1.0) - 4.0 * se;
                        if (e > worst[cl]) {
                            worst[cl] = e;
                            snprintf(where[cl], sizeof where[cl], "base %d coat %d r %g mu %g ch %d: mean %.5f (se %.1g)",
                                     w.base, ci, w.rough, mus[k], c, mean.v[c], se);
                        }
                        up[cl] = fmax(up[cl], mean.v[c] - 1.0 - 4.0 * se);
                        if (mean.v[c] + 4.0 * se < low) {
                            low = mean.v[c] + 4.0 * se;
                            snprintf(where_low, sizeof where_low, "base %d coat %d r %g mu %g ch %d: %.5f", w.base, ci,
                                     w.rough, mus[k], c, mean.v[c]);
                        }
                    }
                    if (w.rough >= 0.3f && k != 1) { /* rough: by quadrature, one channel (red or blue) */
                        c = (bi + k) % 2 ? 2 : 0;
                        q = op_quad_tol(&m, wo, c, 0, 2e-4); /* (a film eval is ~1 us; 2e-4 of a 1e-3 bound) */
                        if (fabs(q - 1.0) > worst[cl]) {
                            worst[cl] = fabs(q - 1.0);
                            snprintf(where[cl], sizeof where[cl], "base %d coat %d r %g mu %g ch %d: quadrature %.5f",
                                     w.base, ci, w.rough, mus[k], c, q);
                        }
                        up[cl] = fmax(up[cl], q - 1.0);
                        worst_z = fmax(worst_z, fabs(q - mean.v[c]) / fmax(se, 1e-12));
                    }
                    ++points;
                }
            }
    h_measure("openpbr film furnace", "%d points; opaque max |E - 1| %.2g at %s (above 1: %.2g); translucent and thin "
              "%.2g at %s (above 1: %.2g); lowest %s; quadrature vs mean weight %.2f se", points, worst[0], where[0],
              up[0], worst[1], where[1], up[1], where_low, worst_z);
    /* the bound, 1 within 1e-3, opaque and translucent (measured 2.5e-4 and 6.6e-4, above 1
       2.2e-5 and 1.8e-4; 1.8e-3 and, above 1, 1.1e-3 before the conductor's and the dielectric's
       tables were bicubic) */
    H_CHECK(worst[0] <= 1e-3 && up[0] <= 1e-3 && worst[1] <= 1e-3 && up[1] <= 1e-3 && worst_z <= 5.0,
            "film furnace: opaque %.3g (bound 1e-3, above 1 %.3g, bound 1e-3) at %s; translucent %.3g (bound 1e-3, "
            "above 1 %.3g, bound 1e-3) at %s; agreement %.2f se (bound 5)", worst[0], up[0], where[0], worst[1],
            up[1], where[1], worst_z);
}

/* the per-microfacet film (the spec's form) of a lone specular lobe, what the model approximates
   by its affine map: its albedo by quadrature against the model's */
typedef struct { const appear_openpbr *m; appear_vec3 wo; int c; } op_film_ctx;
static double op_film_exact(void *ctx, appear_vec3 wi)
{
    const op_film_ctx *x = (const op_film_ctx *)ctx;
    appear_vec3 h;
    float c, g, f;
    if (wi.z <= 0.0f) return 0.0f;
    h = appear_normalize(appear_add(x->wo, wi));
    c = appear_dot(x->wo, h);
    g = appear_conductor_eval(&x->m->spec_lobe, x->wo, wi).v[0];
    f = appear_fresnel_dielectric(c, x->m->spec.eta) +
        appear__openpbr_film_dl(x->m, c, appear_spectrum_splat(x->m->spec.eta), appear_spectrum_splat(0.0f)).v[x->c];
    return (double)f * g * wi.z;
}

void suite_openpbr_film(void)
{
    h_rng r = h_rng_make(41);
    int i;
    {   /* (a) weight 0 or thickness 0: no film, the bits of the model without one */
        int bad = 0;
        h_case("openpbr: thin film: weight 0 or thickness 0 give the bits of no film (any thickness, IOR)");
        for (i = 0; i < 300; ++i) {
            appear_openpbr_params p = appear_openpbr_params_default(), q;
            appear_openpbr m, n;
            p.base_color = op_rgb(&r);
            p.specular_color = op_rgb(&r);
            p.base_metalness = (i % 3) * 0.5f;
            p.specular_roughness = (i % 4) * 0.3f;
            p.coat_weight = (i % 5) * 0.25f;
            p.transmission_weight = (i % 7) * 0.15f;
            p.geometry_thin_walled = i % 11 == 0;
            m = appear_openpbr_make(&p);
            q = p; q.thin_film_thickness = 3.0f * h_randf(&r); q.thin_film_ior = 0.5f + 2.0f * h_randf(&r);
            n = appear_openpbr_make(&q);
            bad += n.film || !op_same_model(&m, &n, &r);
            q.thin_film_weight = 0.1f + 0.9f * h_randf(&r); q.thin_film_thickness = 0.0f;
            n = appear_openpbr_make(&q);
            bad += n.film || !op_same_model(&m, &n, &r);
        }
        H_CHECK(!bad, "%d of 600 film-off models differ from no film", bad);
    }
    {   /* (b) the zero-thickness limit: 1e-6 um (the film on) is the bare model within float rounding */
        double worst_d = 0, worst_r = 0;
        h_case("openpbr: thin film: thickness -> 0 is the bare Fresnel (smooth coefficients 1e-4, rough f 1e-3)");
        for (i = 0; i < 200; ++i) {
            appear_openpbr_params p = appear_openpbr_params_default(), q;
            appear_openpbr m, n;
            appear_vec3 wo = op_upper(&r), wi = op_upper(&r);
            appear_spectrum a, b;
            appear_bsdf_record sa, sb;
            int c;
            p.base_color = op_rgb(&r);
            p.base_metalness = (i % 3) * 0.5f;
            p.specular_roughness = i % 2 ? 0.0f : 0.2f + 0.6f * h_randf(&r);
            p.specular_ior = 1.2f + 1.5f * h_randf(&r);
            p.coat_weight = (i % 4) * 0.33f;
            p.coat_roughness = 0.4f;
            p.coat_ior = 1.3f + 0.5f * h_randf(&r);
            p.transmission_weight = i % 5 == 0 ? 1.0f : 0.0f;
            m = appear_openpbr_make(&p);
            q = p; q.thin_film_weight = 1.0f; q.thin_film_thickness = 1e-6f; q.thin_film_ior = 1.2f + h_randf(&r);
            n = appear_openpbr_make(&q);
            H_CHECK(n.film, "thickness 1e-6 um: the film is off");
            if (p.specular_roughness == 0.0f) { /* the mirror's delta (uc 0: the first lobe) */
                float uc = p.coat_weight > 0.0f ? 0.99f : 0.0f;
                if (appear_openpbr_sample(&m, wo, uc, 0.5f, 0.5f, &sa) && appear_openpbr_sample(&n, wo, uc, 0.5f, 0.5f, &sb) &&
                    (sa.flags & sb.flags & APPEAR_LOBE_SPECULAR))
                    for (c = 0; c < 3; ++c)
                        worst_d = fmax(worst_d, fabs((double)sa.weight.v[c] * sa.pdf - (double)sb.weight.v[c] * sb.pdf));
            } else {
                a = appear_openpbr_eval(&m, wo, wi); b = appear_openpbr_eval(&n, wo, wi);
                for (c = 0; c < 3; ++c) worst_r = fmax(worst_r, fabs(a.v[c] - b.v[c]) / fmax(a.v[c], 1e-6));
            }
        }
        h_measure("openpbr film", "thickness 1e-6 um vs none: smooth coefficients max abs %.2g, rough f max rel %.2g",
                  worst_d, worst_r);
        H_CHECK(worst_d < 1e-4 && worst_r < 1e-3, "thickness -> 0: smooth %.3g (bound 1e-4), rough %.3g (bound 1e-3)",
                worst_d, worst_r);
    }
    {   /* (c) a second form: the film's change the model uses (appear__openpbr_film_dl: [BB17]'s
           Fourier RGB in relative indices at the refracted cosine) against the physical stack in
           absolute indices at the Snell invariant of the air, integrated over the wavelength in
           double (op_airy_rgb); dielectric bases bare and under a coat (its index above the film,
           the film of lower index than the coat included), a gold-like F82 metal through its
           [Gulbrandsen14] index, whose F(1) = F0 is checked too */
        static const float ds[3] = { 0.1f, 0.35f, 0.8f }, nfs[2] = { 1.38f, 2.0f }, cs[3] = { 1.0f, 0.7f, 0.3f };
        double worst = 0, worst_f0 = 0;
        char where[160] = "";
        int cfg, di, ni, ki, c;
        h_case("openpbr: thin film: the model's film vs the spectral Airy sum in absolute indices (double), 2e-4");
        for (cfg = 0; cfg < 4; ++cfg)
            for (di = 0; di < 3; ++di)
                for (ni = 0; ni < 2; ++ni)
                    for (ki = 0; ki < 3; ++ki) {
                        appear_openpbr_params p = appear_openpbr_params_default();
                        appear_openpbr m;
                        appear_spectrum got, eta, kk;
                        double ref[3], ref0[3], na;
                        float cc = cs[ki];
                        if ((cfg + di + ni + ki) % (h_quick() ? 3 : 1) != 0) continue;
                        p.thin_film_weight = 0.8f;
                        p.thin_film_thickness = ds[di];
                        p.thin_film_ior = nfs[ni];
                        p.specular_ior = cfg == 2 ? 1.45f : 1.8f; /* cfg 2: base below the coat (inverted ratio) */
                        p.coat_weight = cfg == 1 || cfg == 2 ? 1.0f : 0.0f;
                        p.coat_ior = 1.6f;
                        p.base_metalness = cfg == 3 ? 1.0f : 0.0f;
                        p.base_color = appear_spectrum_rgb(0.95f, 0.64f, 0.27f);
                        p.specular_color = appear_spectrum_rgb(1.0f, 0.95f, 0.9f);
                        m = appear_openpbr_make(&p);
                        na = 1.0 + m.C * (p.coat_ior - 1.0);
                        eta = cfg == 3 ? m.film_mn : appear_spectrum_splat(m.spec.eta);
                        kk = cfg == 3 ? m.film_mk : appear_spectrum_splat(0.0f);
                        got = appear__openpbr_film_dl(&m, cc, eta, kk);
                        for (c = 0; c < 3; ++c) {
                            double s = sqrt(1.0 - (double)cc * cc), e;
                            double n3 = (double)eta.v[c] * na, k3 = (double)kk.v[c] * na;
                            ref[c] = op_airy_rgb(c, s, na, p.thin_film_ior, 1000.0 * ds[di], n3, k3);
                            ref0[c] = op_airy(s, 550.0, na, p.thin_film_ior, 0.0, n3, k3);
                            e = fabs(got.v[c] - p.thin_film_weight * (ref[c] - ref0[c]));
                            if (e > worst) {
                                worst = e;
                                snprintf(where, sizeof where, "cfg %d d %g um n_f %g cos %g ch %d: %.5f vs %.5f", cfg,
                                         (double)ds[di], (double)nfs[ni], (double)cc, c, got.v[c],
                                         p.thin_film_weight * (ref[c] - ref0[c]));
                            }
                            if (cfg == 3) { /* [Gulbrandsen14]: the index reflects F0 at normal incidence */
                                double f0 = p.base_color.v[c], nn = m.film_mn.v[c], k = m.film_mk.v[c];
                                worst_f0 = fmax(worst_f0, fabs(((nn - 1) * (nn - 1) + k * k) / ((nn + 1) * (nn + 1) + k * k) - f0));
                            }
                        }
                    }
        h_measure("openpbr film", "vs the spectral Airy sum in absolute indices: max abs %.2g at %s; the metal's "
                  "index: |F(1) - F0| %.2g", worst, where, worst_f0);
        H_CHECK(worst < 2e-4 && worst_f0 < 1e-5, "film vs spectral Airy %.3g (bound 2e-4) at %s; metal F(1) %.3g "
                "(bound 1e-5)", worst, where, worst_f0);
    }
    {   /* what the affine map gives up: the albedo of a lone rough specular lobe with the film per
           microfacet (the spec's form, by quadrature) against the model's; held to what is measured */
        static const float alphas[2] = { 0.3f, 0.7f }, mus[2] = { 0.9f, 0.2f }, ds[2] = { 0.25f, 0.6f };
        double worst = 0, sum = 0;
        char where[160] = "";
        int ai, mi, di, cnt = 0;
        h_case("openpbr: thin film: the affine map's albedo vs the per-microfacet film's (rough lobes; measured)");
        for (ai = 0; ai < 2; ++ai)
            for (di = 0; di < 2; ++di)
                for (mi = 0; mi < 2; ++mi) {
                    appear_openpbr_params p = appear_openpbr_params_default();
                    appear_openpbr m;
                    op_film_ctx x;
                    double st = sqrt(1.0 - (double)mus[mi] * mus[mi]), e, q;
                    if ((ai + di + mi) % (h_quick() ? 3 : 1) != 0) continue;
                    p.base_weight = 0.0f; /* the specular lobe alone */
                    p.specular_roughness = alphas[ai];
                    p.thin_film_weight = 1.0f;
                    p.thin_film_thickness = ds[di];
                    m = appear_openpbr_make(&p);
                    x.m = &m; x.wo = appear_vec3_make((float)st, 0.0f, mus[mi]);
                    x.c = (ai + di + mi) % 2 ? 2 : 0; /* red or blue */
                    e = h_integrate_sphere(op_film_exact, &x, appear_vec3_make(-x.wo.x, -x.wo.y, x.wo.z), 3e-4);
                    q = op_quad_tol(&m, x.wo, x.c, 0, 3e-4);
                    sum += fabs(q - e); ++cnt;
                    if (fabs(q - e) > worst) {
                        worst = fabs(q - e);
                        snprintf(where, sizeof where, "r %g d %g um mu %g ch %d: model %.4f, per microfacet %.4f",
                                 (double)alphas[ai], (double)ds[di], (double)mus[mi], x.c, q, e);
                    }
                }
        h_measure("openpbr film", "affine map vs per-microfacet film, lone specular albedo: max |diff| %.3g at %s; mean "
                  "%.2g over %d", worst, where, sum / cnt, cnt);
        H_CHECK(worst < 0.05, "affine map vs per-microfacet film %.3g (held to what is measured: 0.05) at %s", worst,
                where);
    }
    op_film_furnace();
}
#else
void suite_openpbr_film(void) {}
#endif

/* A coat (weight 1, IOR 1.5) against appear_layered: the coat's multiple-scattering interface, a
   slab of one-way normal transmittance sqrt(coat_color) (OpenPBR's colour is the normal-incidence
   round trip), over the model with coat_weight 0 (EON: specular IOR 1, index-matched under the
   coat). Over EON (rho 0.8): the coated dielectric base's escape (the spec's Delta misses tinted
   coats by 0.09-0.11, a clear one over sigma 1 by 0.034); over a gold metal: the coated metal's
   escape (the spec's Delta misses by 0.05-0.08; tinted over gold held to 0.015 until the
   escape tables' absorbing path took whole paths per bounce, 2026-12-05).
   bench openpbr_walk runs the whole grid. */
typedef struct { float sigma, coat_r, metal_r; int tinted; double bound; } op_walk_case;
void suite_openpbr_walk(void)
{
    static const op_walk_case cases[] = {
        { 0.0f, 0.0f, -1.0f, 1, 0.01 }, { 1.0f, 0.3f, -1.0f, 1, 0.01 },  /* EON, tinted */
        { 1.0f, 0.6f, -1.0f, 0, 0.01 },                                  /* EON sigma 1, clear */
        { 0.0f, 0.0f, 0.3f, 0, 0.01 },  { 0.0f, 0.3f, 0.6f, 1, 0.01 }, /* gold, clear and tinted */
    };
    static const float mus[4] = { 1.0f, 0.7f, 0.4f, 0.15f };
    long n = h_n(20000), i;
    double worst[5] = { -1, -1, -1, -1, -1 }; /* per case, the largest |difference| - 4 se (< 0: noise) */
    char where[5][120] = { "", "", "", "", "" };
    int k, a, j;
    h_case("openpbr: coats over EON (tinted, clear) and over gold (clear, tinted) against the layered reference "
           "walk: |albedo difference| - 4 se <= 0.01");
    for (k = 0; k < 5; ++k) {
        const op_walk_case *c = &cases[k];
        appear_openpbr_params p = appear_openpbr_params_default(), q;
        appear_spectrum col = c->tinted ? appear_spectrum_rgb(0.9f, 0.6f, 0.3f) : appear_spectrum_splat(1.0f), t1;
        appear_openpbr m, mb;
        appear_bsdf base, top;
        appear_dielectric coat;
        appear_layered ref;
        appear_rng trng = appear_rng_make(77);
        float ac = c->coat_r * c->coat_r;
        if (c->metal_r < 0.0f) {
            p.base_color = appear_spectrum_splat(0.8f);
            p.base_diffuse_roughness = c->sigma;
        } else {
            p.base_metalness = 1.0f;
            p.base_color = appear_spectrum_rgb(1.0f, 0.78f, 0.34f);
            p.specular_roughness = c->metal_r;
        }
        p.coat_weight = 1.0f; p.coat_ior = 1.5f; p.coat_roughness = c->coat_r; p.coat_color = col;
        q = p;
        q.coat_weight = 0.0f;
        if (c->metal_r < 0.0f) q.specular_ior = 1.0f;
        m = appear_openpbr_make(&p);
        mb = appear_openpbr_make(&q);
        base = appear_bsdf_openpbr(&mb);
        coat = appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, ac, ac, APPEAR_SAMPLE_VISIBLE), 1.5f);
        top = ac > 0.0f ? appear_bsdf_dielectric_ms(coat, &trng) : appear_bsdf_dielectric(coat);
        for (j = 0; j < APPEAR_SPECTRUM_SAMPLES; ++j) t1.v[j] = sqrtf(col.v[j]);
        ref = appear_layered_make(&top, &base, appear_slab_from_transmittance(t1, appear_spectrum_splat(0.0f), 0.0f),
                                  1, 256);
        H_CHECK(m.valid && mb.valid && ref.valid, "walk comparison %d: a model is invalid", k);
        for (a = 0; a < 4; ++a) {
            double sf = 0, sr = 0, sf2 = 0, sr2 = 0, se, d;
            appear_vec3 wo = appear_vec3_make(sqrtf(1.0f - mus[a] * mus[a]), 0.0f, mus[a]);
            appear_rng rng = appear_rng_make(1234u + (unsigned)a);
            for (i = 0; i < n; ++i) {
                appear_bsdf_record s;
                float uc = appear_rng_next(&rng), u1 = appear_rng_next(&rng), u2 = appear_rng_next(&rng);
                double x;
                if (appear_openpbr_sample(&m, wo, uc, u1, u2, &s)) {
                    x = appear_spectrum_avg(s.weight);
                    sf += x; sf2 += x * x;
                }
                if (appear_layered_sample(&ref, wo, &rng, &s)) {
                    x = appear_spectrum_avg(s.weight);
                    sr += x; sr2 += x * x;
                }
            }
            sf /= n; sr /= n;
            se = sqrt((fmax(0.0, sf2 / n - sf * sf) + fmax(0.0, sr2 / n - sr * sr)) / n);
            d = fabs(sf - sr) - 4.0 * se; /* beyond 4 se of the two estimates' noise */
            if (d > worst[k]) {
                worst[k] = d;
                snprintf(where[k], sizeof where[k], "%s %g, coat r %g, mu %g: %.4f vs walk %.4f (se %.2g)",
                         c->metal_r < 0.0f ? "EON sigma" : "gold r", c->metal_r < 0.0f ? c->sigma : c->metal_r,
                         c->coat_r, mus[a], sf, sr, se);
            }
        }
        h_measure("openpbr walk", "%s coat: max |albedo - walk| - 4 se %.4f at %s", c->tinted ? "tinted" : "clear",
                  worst[k], where[k]);
        H_CHECK(worst[k] <= c->bound, "%s coat: |albedo - walk| - 4 se %.4f (bound %g) at %s",
                c->tinted ? "tinted" : "clear", worst[k], c->bound, where[k]);
    }
}

/* appear_openpbr_make_spectral: the index at the hero's wavelength, the secondaries terminated
   where the index varies, the bits of appear_openpbr_make where it does not */
void suite_openpbr_dispersion(void)
{
    static const float lam[3] = { 450.0f, 550.0f, 650.0f }, same[3] = { 550.0f, 550.0f, 550.0f };
    h_rng r = h_rng_make(91);
    int k, i;
    h_case("openpbr dispersion: no dispersion (scale 0, opaque, no or equal wavelengths) is appear_openpbr_make "
           "to the bit");
    for (k = 0; k < 40; ++k) {
        appear_openpbr_params p = appear_openpbr_params_default();
        appear_openpbr a, b;
        p.transmission_weight = (k & 3) ? h_randf(&r) : 0.0f;
        p.specular_roughness = h_randf(&r);
        p.specular_ior = 1.1f + 2.0f * h_randf(&r);
        p.coat_weight = (k & 4) ? h_randf(&r) : 0.0f;
        p.transmission_dispersion_abbe_number = 10.0f + 50.0f * h_randf(&r);
        p.transmission_dispersion_scale = (k & 8) ? 0.0f : h_randf(&r);
        a = appear_openpbr_make(&p);
        b = appear_openpbr_make_spectral(&p, (k & 16) ? lam : (k & 32) ? same : APPEAR__NULL);
        if (p.transmission_dispersion_scale > 0.0f && p.transmission_weight > 0.0f && (k & 16)) continue;
        H_CHECK(op_same_model(&a, &b, &r) && !appear_openpbr_terminates_secondary(&b),
                "case %d: not the bits of appear_openpbr_make", k);
    }
    h_case("openpbr dispersion: the hero's index, the secondaries terminated (eval and every sample)");
    for (k = 0; k < 8; ++k) {
        appear_openpbr_params p = appear_openpbr_params_default(), q;
        appear_openpbr m, h;
        double nd = 1.5 + 0.2 * k, v = 20.0 + 5.0 * k, s = 0.5 + 0.0625 * k;
        double lf = APPEAR_LAMBDA_F * 1e-3, lc = APPEAR_LAMBDA_C * 1e-3, ld = APPEAR_LAMBDA_D * 1e-3, l0 = lam[0] * 1e-3;
        double bb = (nd - 1.0) / (v / s * (1.0 / (lf * lf) - 1.0 / (lc * lc))), n0 = nd + bb * (1.0 / (l0 * l0) - 1.0 / (ld * ld));
        p.transmission_weight = 1.0f;
        p.specular_roughness = k & 1 ? 0.0f : 0.3f; /* smooth glass too */
        p.specular_ior = (float)nd;
        p.transmission_dispersion_abbe_number = (float)v;
        p.transmission_dispersion_scale = (float)s;
        p.coat_weight = k & 2 ? 0.5f : 0.0f;
        m = appear_openpbr_make_spectral(&p, lam);
        q = p;
        q.specular_ior = appear_ior_cauchy_abbe((float)nd, (float)(v / s), lam[0]);
        H_CHECK(fabs(q.specular_ior / n0 - 1.0) < 2e-6, "case %d: n(450 nm) %.7f, Cauchy in double %.7f", k,
                q.specular_ior, n0);
        h = appear_openpbr_make(&q);
        H_CHECK(appear_openpbr_terminates_secondary(&m), "case %d: not dispersive", k);
        for (i = 0; i < 64; ++i) {
            appear_vec3 wo = h_rand_dir(&r), wi = h_rand_dir(&r);
            float uc = h_randf(&r), u1 = h_randf(&r), u2 = h_randf(&r);
            appear_spectrum f = appear_openpbr_eval(&m, wo, wi), fh = appear_openpbr_eval(&h, wo, wi);
            appear_bsdf_record sm, sh;
            int om = appear_openpbr_sample(&m, wo, uc, u1, u2, &sm), oh = appear_openpbr_sample(&h, wo, uc, u1, u2, &sh);
            H_CHECK(memcmp(&f.v[0], &fh.v[0], sizeof(float)) == 0 && f.v[1] == 0.0f && f.v[2] == 0.0f,
                    "case %d: eval %g %g %g, the hero's model %g", k, f.v[0], f.v[1], f.v[2], fh.v[0]);
            H_CHECK(appear_openpbr_pdf(&m, wo, wi) == appear_openpbr_pdf(&h, wo, wi), "case %d: pdf differs", k);
            H_CHECK(om == oh, "case %d: sample %d, the hero's model %d", k, om, oh);
            if (om && oh) {
                H_CHECK((sm.flags & APPEAR_SAMPLE_TERMINATE_SECONDARY) &&
                            (sm.flags & ~(unsigned)APPEAR_SAMPLE_TERMINATE_SECONDARY) == sh.flags,
                        "case %d: flags %#x, the hero's %#x", k, sm.flags, sh.flags);
                H_CHECK(memcmp(&sm.wi, &sh.wi, sizeof sm.wi) == 0 && sm.pdf == sh.pdf && sm.eta == sh.eta &&
                            sm.weight.v[0] == sh.weight.v[0] && sm.f.v[0] == sh.f.v[0] &&
                            sm.weight.v[1] == 0.0f && sm.weight.v[2] == 0.0f && sm.f.v[2] == 0.0f,
                        "case %d: the record is not the hero's channel 0", k);
            }
        }
    }
    h_case("openpbr dispersion: the Abbe number V_d / scale (n_d at the d line, (n_d - 1) / (n_F - n_C) = V)");
    {
        float nd = 1.7f, v = 30.0f, s = 0.5f;
        float n_d = appear_ior_cauchy_abbe(nd, v / s, APPEAR_LAMBDA_D), n_f = appear_ior_cauchy_abbe(nd, v / s, APPEAR_LAMBDA_F);
        float n_c = appear_ior_cauchy_abbe(nd, v / s, APPEAR_LAMBDA_C);
        H_CHECK(fabsf(n_d - nd) < 1e-6f && fabs((nd - 1.0) / ((double)n_f - n_c) / (v / s) - 1.0) < 1e-3,
                "n_d %.7f, V %.4f (expected %.4f)", n_d, (nd - 1.0) / ((double)n_f - n_c), v / s);
    }
    h_case("openpbr dispersion: bad wavelengths (NaN, out of range) give finite values; NaN scale is invalid");
    {
        static const float bad[3] = { NAN, 100.0f, 5000.0f };
        appear_openpbr_params p = appear_openpbr_params_default();
        appear_openpbr m;
        p.transmission_weight = 1.0f;
        p.transmission_dispersion_scale = 1.0f;
        m = appear_openpbr_make_spectral(&p, bad);
        for (i = 0; i < 64; ++i) {
            appear_vec3 wo = h_rand_dir(&r), wi = h_rand_dir(&r);
            appear_spectrum f = appear_openpbr_eval(&m, wo, wi);
            H_CHECK(m.valid && isfinite(f.v[0]) && isfinite(appear_openpbr_pdf(&m, wo, wi)), "bad wavelengths: %g",
                    f.v[0]);
        }
        p.transmission_dispersion_scale = NAN;
        m = appear_openpbr_make_spectral(&p, lam);
        H_CHECK(!m.valid && !appear_openpbr_terminates_secondary(&m), "NaN dispersion scale: valid");
    }
}

#else
void suite_openpbr_furnace(void) {}
void suite_openpbr_corners(void) {}
void suite_openpbr_pdf(void) {}
void suite_openpbr_chi2(void) {}
void suite_openpbr_bad(void) {}
void suite_openpbr_medium(void) {}
void suite_openpbr_film(void) {}
void suite_openpbr_walk(void) {}
void suite_openpbr_dispersion(void) {}
void suite_openpbr_plain(void) {}
#endif
