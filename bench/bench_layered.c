/* bench/bench_layered.c - the layered materials (appear.h SECTIONs layered and coated):
     bench_layered        latency (dependent chain: each call's direction from the previous
                          call's output) of appear_plastic (a GGX 0.1 coat, eta 1.5, over
                          Lambert; its reciprocal mode) and appear_coated over a GGX 0.2
                          conductor, in the reciprocal and the default albedo mode: eval, pdf,
                          sample (and of appear_coated's albedo mode over the same Lambert),
                          against the sum of their lobes called directly (the coat's
                          dielectric eval + the base's eval, appear_lambert_* or
                          appear_conductor_*, not through appear_bsdf, since the twentieth
                          session; pdf: the two pdfs; sample: what a
                          hand-written mixture costs, the coat's reflection sampler (its
                          microfacets' visible normals, F = 1) or the base's, picked by uc with
                          the model's own probability P_c(mu_o) (read from its nodes: the same
                          lobe on the same draw), then the coat's dielectric eval, the other
                          lobe's eval and both pdfs; until the eighteenth session the base's
                          sampler alone, a mixture that never samples the coat, still printed
                          as "base only") and against the reference walk at 1 sample (max
                          depth 10);
     bench_layered_grid   the fast coat against the reference walk over the grid of
                          tests/coated_grid.h (7 bases x coat alpha 0, 0.05, 0.2, 0.5, 1 x eta
                          1.3, 1.5, 2 x clear / absorbing x 9 view angles, 20000 samples
                          each): per material the largest |albedo difference| over the angles
                          and its angle, and the lobe's L1 distance; bench/REPORT.md holds the
                          table (./build/bench_O2 layered_grid). APPEAR_BENCH_SAMPLES=N sets
                          the samples per point (the walk's noise: se ~0.002 at 20000, whose
                          largest over 1890 points reaches ~1%); --filter=NAME keeps the
                          bases whose name holds NAME (e.g. --filter="gold GGX 0.05"). */
#include "bench.h"
#include "../tests/coated_grid.h"
#include <stdio.h>
#include <stdlib.h>

#define LN 4096
typedef struct {
    const appear_coated *m;
    const appear_conductor *lobe; /* the coat's reflection sampler: its microfacets, F = 1 */
    const appear_layered *ref;
    const appear_dielectric *coat;
    const appear_lambert *lam;    /* the base's own model, called directly (not through appear_bsdf): */
    const appear_conductor *cond; /* one of the two is set */
    appear_rng rng;
    float u[LN][3];
} lctx;

/* the base's lobe, its own function (a branch that never changes within a run) */
static appear_spectrum base_eval(const lctx *c, appear_vec3 wo, appear_vec3 wi)
{ return c->lam ? appear_lambert_eval(c->lam, wo, wi) : appear_conductor_eval(c->cond, wo, wi); }
static float base_pdf(const lctx *c, appear_vec3 wo, appear_vec3 wi)
{ return c->lam ? appear_lambert_pdf(c->lam, wo, wi) : appear_conductor_pdf(c->cond, wo, wi); }
static int base_sample(const lctx *c, appear_vec3 wo, float uc, float u1, float u2, appear_bsdf_record *s)
{ return c->lam ? appear_lambert_sample(c->lam, wo, uc, u1, u2, s) : appear_conductor_sample(c->cond, wo, uc, u1, u2, s); }
#define L_RUN(name, ...) B_CHAIN_RUN(name, lctx, LN, 1.0f, __VA_ARGS__)
L_RUN(run_c_eval, v = appear_coated_eval(c->m, wo, wi).v[0])
L_RUN(run_c_pdf, v = appear_coated_pdf(c->m, wo, wi))
L_RUN(run_c_sample, {
    appear_bsdf_record s;
    v = appear_coated_sample(c->m, wo, c->u[i][2], c->u[i][0], c->u[i][1], &s) ? s.weight.v[0] : 0.0f;
})
L_RUN(run_s_eval, v = appear_dielectric_eval(c->coat, wo, wi).v[0] + base_eval(c, wo, wi).v[0])
L_RUN(run_s_pdf, v = appear_dielectric_pdf(c->coat, wo, wi) + base_pdf(c, wo, wi))
L_RUN(run_s_sample, { /* the mixture, by P_c */
    appear_bsdf_record s;
    float pc = appear__coated_pc(c->m, wo.z), uc = c->u[i][2];
    v = 0.0f;
    if (uc < pc) {
        if (appear_conductor_sample(c->lobe, wo, 0.5f, c->u[i][0], c->u[i][1], &s))
            v = (appear_dielectric_eval(c->coat, wo, s.wi).v[0] + base_eval(c, wo, s.wi).v[0]) /
                (pc * s.pdf + (1.0f - pc) * base_pdf(c, wo, s.wi));
    } else if (base_sample(c, wo, (uc - pc) / (1.0f - pc), c->u[i][0], c->u[i][1], &s)) {
        v = (appear_dielectric_eval(c->coat, wo, s.wi).v[0] + s.f.v[0]) /
            (pc * appear_conductor_pdf(c->lobe, wo, s.wi) + (1.0f - pc) * s.pdf);
    }
})
L_RUN(run_b_sample, { /* the base's sampler alone (the sums before the eighteenth session) */
    appear_bsdf_record s;
    v = 0.0f;
    if (base_sample(c, wo, c->u[i][2], c->u[i][0], c->u[i][1], &s))
        v = (appear_dielectric_eval(c->coat, wo, s.wi).v[0] + s.f.v[0]) /
            (appear_dielectric_pdf(c->coat, wo, s.wi) + s.pdf);
})
L_RUN(run_r_eval, v = appear_layered_eval(c->ref, wo, wi, &c->rng).v[0])
L_RUN(run_r_pdf, v = appear_layered_pdf(c->ref, wo, wi, &c->rng))
L_RUN(run_r_sample, {
    appear_bsdf_record s;
    v = appear_layered_sample(c->ref, wo, &c->rng, &s) ? s.weight.v[0] : 0.0f;
})

void bench_layered(void)
{
    appear_microfacet d1 = appear_microfacet_make(APPEAR_GGX, 0.1f, 0.1f, APPEAR_SAMPLE_VISIBLE);
    appear_microfacet d2 = appear_microfacet_make(APPEAR_GGX, 0.2f, 0.2f, APPEAR_SAMPLE_VISIBLE);
    appear_dielectric coat = appear_dielectric_make(d1, 1.5f);
    appear_bsdf bases[2], top = appear_bsdf_dielectric_comp(coat);
    static lctx c;
    b_rng r = b_rng_make(31);
    int k, i;
    static const char *names[4] = { "plastic (GGX 0.1 coat / Lambert)", "coated (GGX 0.1 coat / GGX 0.2 conductor)",
                                    "coated albedo mode (GGX 0.1 coat / GGX 0.2 conductor)",
                                    "coated albedo mode (GGX 0.1 coat / Lambert)" };
    bases[0] = appear_bsdf_lambert(appear_lambert_make(appear_spectrum_rgb(0.8f, 0.4f, 0.2f)));
    bases[1] = appear_bsdf_conductor(appear_conductor_make(d2, appear_spectrum_rgb(0.18f, 0.42f, 1.37f),
                                                           appear_spectrum_rgb(3.42f, 2.35f, 1.77f)));
    for (i = 0; i < LN; ++i) { c.u[i][0] = b_randf(&r); c.u[i][1] = b_randf(&r); c.u[i][2] = b_randf(&r); }
    b_note("layered latency: appear_coated against the sum of its lobes called directly, and against the "
           "reference walk (1 sample, max depth 10); dependent chains, ns per call");
    for (k = 0; k < 4; ++k) {
        int b = k == 1 || k == 2; /* the conductor base */
        appear_coated m = k == 0 ? appear_plastic_make(d1, 1.5f, appear_spectrum_rgb(0.8f, 0.4f, 0.2f),
                                                       appear_spectrum_splat(1.0f))
                                 : appear_coated_make(coat, &bases[b], appear_spectrum_splat(1.0f),
                                                      k == 1 ? APPEAR_COATED_RECIPROCAL : APPEAR_COATED_ALBEDO);
        appear_layered ref = appear_layered_make(&top, &bases[b], appear_slab_none(), 1, 10);
        static void (*const fast[3])(void *) = { run_c_eval, run_c_pdf, run_c_sample };
        static void (*const sum[3])(void *) = { run_s_eval, run_s_pdf, run_s_sample };
        static void (*const walk[3])(void *) = { run_r_eval, run_r_pdf, run_r_sample };
        static const char *verbs[3] = { "eval", "pdf", "sample" };
        int v;
        c.m = &m; c.lobe = &m.lobe; c.ref = &ref; c.coat = &coat;
        c.lam = b ? NULL : &bases[0].m.lambert;
        c.cond = b ? &bases[1].m.conductor : NULL;
        c.rng = appear_rng_make(5);
        for (v = 0; v < 3; ++v) {
            char name[160], note[200];
            double ta, tb, tw, ratio;
            snprintf(name, sizeof name, "%s %s", names[k], verbs[v]);
            if (!b_filter_match(name)) continue;
            ratio = b_time_latency_pair(fast[v], &c, sum[v], &c, LN, &ta, &tb);
            tw = b_time(walk[v], &c, LN);
            if (v == 2) { /* and the base-only sum */
                double tc, tbo, rb = b_time_latency_pair(fast[v], &c, run_b_sample, &c, LN, &tc, &tbo);
                snprintf(note, sizeof note, "sum of lobes %.1f ns (ratio %.2f); base only %.1f ns (%.2f); walk %.0f ns "
                         "(%.0fx)", tb, ratio, tbo, rb, tw, tw / ta);
            } else {
                snprintf(note, sizeof note, "sum of lobes %.1f ns (ratio %.2f); walk %.0f ns (%.0fx)", tb, ratio, tw,
                         tw / ta);
            }
            b_row("layered", name, ta, -1.0, note);
        }
    }
}

void bench_layered_grid(void)
{
    static const float alphas[5] = { 0.0f, 0.05f, 0.2f, 0.5f, 1.0f }, etas[3] = { 1.3f, 1.5f, 2.0f };
    appear_spectrum colors[2];
    const char *ns = getenv("APPEAR_BENCH_SAMPLES"); /* samples per point (20000; more for less noise) */
    long n = ns && atol(ns) > 0 ? atol(ns) : b_quick() ? 2000 : 20000;
    int b, i, j, c, a;
    double worst = 0;
    colors[0] = appear_spectrum_splat(1.0f);
    colors[1] = appear_spectrum_rgb(0.9f, 0.6f, 0.3f);
    printf("| base | coat alpha | eta | coat | max abs albedo diff | at cos | fast | walk (se) | lobe L1 (max) |\n");
    printf("|---|---|---|---|---|---|---|---|---|\n");
    for (b = 0; b < CG_NBASES; ++b)
        for (i = 0; i < 5; ++i)
            for (j = 0; j < 3; ++j)
                for (c = 0; c < 2; ++c) {
                    double w = -1, wmu = 0, l1 = 0;
                    if (!b_filter_match(cg_base_name(b))) continue; /* --filter="gold GGX 0.8" */
                    cg_result wr = { 0, 0, 0, 0 };
                    for (a = 0; a < 9; ++a) {
                        double mu = a == 8 ? 0.05 : 1.0 - a * 0.12;
                        cg_result r = cg_compare(b, alphas[i], etas[j], colors[c], mu, n, 7u + (unsigned)a);
                        l1 = fmax(l1, r.l1);
                        if (fabs(r.fast - r.ref) > w) { w = fabs(r.fast - r.ref); wmu = mu; wr = r; }
                    }
                    worst = fmax(worst, w);
                    printf("| %s | %.2f | %.1f | %s | %.4f | %.2f | %.4f | %.4f (%.4f) | %.3f |\n", cg_base_name(b),
                           alphas[i], etas[j], c ? "absorbing" : "clear", w, wmu, wr.fast, wr.ref, wr.ref_se, l1);
                }
    printf("largest |albedo fast - walk| over the grid: %.4f\n", worst);
}
