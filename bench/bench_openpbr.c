/* bench/bench_openpbr.c - OpenPBR Surface (appear.h SECTION openpbr):
     bench_openpbr   latency (dependent chain: each call's directions from the previous call's
                     output) of eval, pdf and sample for four materials, against the sum of
                     their active lobes called directly (the same lobe structs, taken from the
                     made model): eval the lobes' evals, pdf their pdfs, sample one lobe's
                     sampler (by uc) plus every lobe's eval and pdf, what a hand-written
                     mixture costs without the layering's weights. Issue 33's goal: <= 1.3x.
                     The metal lobe is the energy-compensated conductor (appear_conductor_comp_*:
                     OpenPBR's metal is the F82 conductor times Turquin's factor, its albedo read
                     from the same tables; until the sixteenth session the sums called the single-
                     scattering conductor and the table read counted as the model's overhead).
                       plastic    the spec's default (specular GGX r 0.3 over an EON diffuse)
                       car paint  a clear smooth coat over a half metal, half diffuse base
                       glass      transmission 1, specular r 0.1 (the dielectric's R + T)
                       diffuse    base only, specular_weight 0: every optional lobe off
                       brushed metal  metalness 1, specular r 0.4, anisotropy 0.9: the metal's
                                  compensation from the anisotropic albedo table
     bench_openpbr_walk  issue 33's validation item 2: the directional albedo (mean sample
                     weight) of OpenPBR's coat (weight 1, IOR 1.5, roughness 0 to 1, clear and
                     tinted) over an EON base (sigma 0 and 1, rho 0.8) and over a gold metal
                     (roughness 0.3, 0.6), against the layered reference walk (SECTION layered,
                     the coat's multiple-scattering interface, its absorption a slab whose
                     normal-incidence one-way transmittance is sqrt(coat_color), over the same
                     base: the model with coat_weight 0, its specular IOR 1 under an index-matched
                     coat); 9 view cosines 1 ... 0.05; the largest |difference| per material.
     ./build/bench_O2 openpbr
     ./build/bench_O2 openpbr_walk */
#include "bench.h"
#include <stdio.h>

#define ON 4096
typedef struct {
    const appear_openpbr *m;
    int kind; /* 0 plastic, 1 car paint, 2 glass, 3 diffuse, 4 brushed metal */
    float u[ON][3];
} octx;

/* glass: every other wi below (its refraction) */
#define O_RUN(name, ...) B_CHAIN_RUN(name, octx, ON, c->kind == 2 && (i & 1) ? -1.0f : 1.0f, __VA_ARGS__)
O_RUN(run_o_eval, v = appear_openpbr_eval(c->m, wo, wi).v[0])
O_RUN(run_o_pdf, v = appear_openpbr_pdf(c->m, wo, wi))
O_RUN(run_o_sample, {
    appear_bsdf_record s;
    v = appear_openpbr_sample(c->m, wo, c->u[i][2], c->u[i][0], c->u[i][1], &s) ? s.weight.v[0] : 0.0f;
})

/* the sum of the active lobes, called directly */
static float s_eval(const octx *c, appear_vec3 wo, appear_vec3 wi)
{
    const appear_openpbr *m = c->m;
    switch (c->kind) {
    case 0: return appear_dielectric_eval(&m->spec, wo, wi).v[0] + appear_eon_eval(&m->diffuse, wo, wi).v[0];
    case 1:
        return appear_conductor_comp_eval(&m->metal, wo, wi).v[0] + appear_dielectric_eval(&m->spec, wo, wi).v[0] +
               appear_eon_eval(&m->diffuse, wo, wi).v[0];
    case 2: return appear_dielectric_eval(&m->glass, wo, wi).v[0];
    case 4: return appear_conductor_comp_eval(&m->metal, wo, wi).v[0];
    default: return appear_eon_eval(&m->diffuse, wo, wi).v[0];
    }
}
static float s_pdf(const octx *c, appear_vec3 wo, appear_vec3 wi)
{
    const appear_openpbr *m = c->m;
    switch (c->kind) {
    case 0: return appear_conductor_pdf(&m->spec_lobe, wo, wi) + appear_eon_pdf(&m->diffuse, wo, wi);
    case 1:
        return appear_conductor_comp_pdf(&m->metal, wo, wi) + appear_conductor_pdf(&m->spec_lobe, wo, wi) +
               appear_eon_pdf(&m->diffuse, wo, wi);
    case 2: return appear_dielectric_pdf(&m->glass, wo, wi);
    case 4: return appear_conductor_comp_pdf(&m->metal, wo, wi);
    default: return appear_eon_pdf(&m->diffuse, wo, wi);
    }
}
O_RUN(run_s_eval, v = s_eval(c, wo, wi))
O_RUN(run_s_pdf, v = s_pdf(c, wo, wi))
O_RUN(run_s_sample, {
    appear_bsdf_record s;
    float uc = c->u[i][2];
    int ok;
    if (c->kind == 2) ok = appear_dielectric_sample(&c->m->glass, wo, uc, c->u[i][0], c->u[i][1], &s);
    else if (c->kind == 4) ok = appear_conductor_comp_sample(&c->m->metal, wo, uc, c->u[i][0], c->u[i][1], &s);
    else if (c->kind == 3 || uc < 0.5f) ok = appear_eon_sample(&c->m->diffuse, wo, uc, c->u[i][0], c->u[i][1], &s);
    else ok = appear_conductor_sample(&c->m->spec_lobe, wo, uc, c->u[i][0], c->u[i][1], &s);
    v = ok ? s_eval(c, wo, s.wi) / s_pdf(c, wo, s.wi) : 0.0f;
})

void bench_openpbr(void)
{
    static octx c;
    static const char *names[5] = { "plastic", "car paint", "glass", "diffuse (every optional lobe off)",
                                    "brushed metal (anisotropy 0.9)" };
    static void (*const fast[3])(void *) = { run_o_eval, run_o_pdf, run_o_sample };
    static void (*const sum[3])(void *) = { run_s_eval, run_s_pdf, run_s_sample };
    static const char *verbs[3] = { "eval", "pdf", "sample" };
    b_rng r = b_rng_make(37);
    int k, i, v;
    for (i = 0; i < ON; ++i) { c.u[i][0] = b_randf(&r); c.u[i][1] = b_randf(&r); c.u[i][2] = b_randf(&r); }
    b_note("openpbr latency: appear_openpbr against the sum of its active lobes called directly (the same "
           "lobe structs); dependent chains, ns per call");
    for (k = 0; k < 5; ++k) {
        appear_openpbr_params p = appear_openpbr_params_default();
        appear_openpbr m;
        p.base_color = appear_spectrum_rgb(0.8f, 0.1f, 0.1f);
        if (k == 1) { p.coat_weight = 1.0f; p.base_metalness = 0.5f; p.specular_roughness = 0.4f; }
        if (k == 2) { p.transmission_weight = 1.0f; p.specular_roughness = 0.1f; }
        if (k == 3) p.specular_weight = 0.0f;
        if (k == 4) { p.base_metalness = 1.0f; p.specular_roughness = 0.4f; p.specular_roughness_anisotropy = 0.9f; }
        m = appear_openpbr_make(&p);
        c.m = &m; c.kind = k;
        for (v = 0; v < 3; ++v) {
            char name[160], note[160];
            double ta, tb, ratio;
            snprintf(name, sizeof name, "openpbr %s %s", names[k], verbs[v]);
            if (!b_filter_match(name)) continue;
            ratio = b_time_latency_pair(fast[v], &c, sum[v], &c, ON, &ta, &tb);
            snprintf(note, sizeof note, "sum of lobes %.1f ns (ratio %.2f)", tb, ratio);
            b_row("openpbr", name, ta, -1.0, note);
        }
    }
}

void bench_openpbr_walk(void)
{
    static const float rcs[4] = { 0.0f, 0.3f, 0.6f, 1.0f };
    static const char *bases[4] = { "EON sigma 0", "EON sigma 1", "gold r 0.3", "gold r 0.6" };
    long n = b_quick() ? 2000 : 20000;
    double worst[2] = { 0, 0 };
    int b, ri, c, a, k;
    if (!b_filter_match("openpbr_walk")) return; /* `./build/bench_O2 openpbr --filter="openpbr "`: latency alone */
    printf("| base | coat roughness | coat | max abs albedo diff | at cos | OpenPBR | walk (se) |\n");
    printf("|---|---|---|---|---|---|---|\n");
    for (b = 0; b < 4; ++b)
        for (ri = 0; ri < 4; ++ri)
            for (c = 0; c < 2; ++c) {
                appear_openpbr_params p = appear_openpbr_params_default(), q;
                appear_spectrum col = c ? appear_spectrum_rgb(0.9f, 0.6f, 0.3f) : appear_spectrum_splat(1.0f), t1;
                appear_openpbr m, mb;
                appear_bsdf base, top;
                appear_microfacet d;
                appear_dielectric coat;
                appear_layered ref;
                appear_rng trng = appear_rng_make(77);
                float ac = rcs[ri] * rcs[ri];
                double w = -1, wmu = 0, wf = 0, wr = 0, wse = 0;
                if (b < 2) {
                    p.base_color = appear_spectrum_splat(0.8f);
                    p.base_diffuse_roughness = b ? 1.0f : 0.0f;
                } else {
                    p.base_metalness = 1.0f;
                    p.base_color = appear_spectrum_rgb(1.0f, 0.78f, 0.34f);
                    p.specular_roughness = b == 2 ? 0.3f : 0.6f;
                }
                p.coat_weight = 1.0f; p.coat_ior = 1.5f; p.coat_roughness = rcs[ri]; p.coat_color = col;
                q = p;
                q.coat_weight = 0.0f;
                if (b < 2) q.specular_ior = 1.0f; /* specular_ior = coat_ior: index-matched under the coat */
                m = appear_openpbr_make(&p);
                mb = appear_openpbr_make(&q);
                base = appear_bsdf_openpbr(&mb);
                d = appear_microfacet_make(APPEAR_GGX, ac, ac, APPEAR_SAMPLE_VISIBLE);
                coat = appear_dielectric_make(d, 1.5f);
                top = ac > 0.0f ? appear_bsdf_dielectric_ms(coat, &trng) : appear_bsdf_dielectric(coat);
                for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) t1.v[k] = sqrtf(col.v[k]); /* coat_color: a round trip */
                ref = appear_layered_make(&top, &base, appear_slab_from_transmittance(t1, appear_spectrum_splat(0.0f),
                                                                                      0.0f), 1, 256);
                for (a = 0; a < 9; ++a) {
                    double mu = a == 8 ? 0.05 : 1.0 - a * 0.12, sf = 0, sr = 0, sr2 = 0;
                    appear_vec3 wo = appear_vec3_make((float)sqrt(1.0 - mu * mu), 0.0f, (float)mu);
                    appear_rng rng = appear_rng_make(1234u + (unsigned)a);
                    long i;
                    for (i = 0; i < n; ++i) {
                        appear_bsdf_record s;
                        float uc = appear_rng_next(&rng), u1 = appear_rng_next(&rng), u2 = appear_rng_next(&rng);
                        if (appear_openpbr_sample(&m, wo, uc, u1, u2, &s)) sf += appear_spectrum_avg(s.weight);
                        if (appear_layered_sample(&ref, wo, &rng, &s)) {
                            double x = appear_spectrum_avg(s.weight);
                            sr += x; sr2 += x * x;
                        }
                    }
                    sf /= n; sr /= n;
                    if (fabs(sf - sr) > w) {
                        w = fabs(sf - sr); wmu = mu; wf = sf; wr = sr;
                        wse = sqrt(fmax(0.0, sr2 / n - sr * sr) / n);
                    }
                }
                worst[c] = fmax(worst[c], w);
                printf("| %s | %.1f | %s | %.4f | %.2f | %.4f | %.4f (%.4f) |\n", bases[b], rcs[ri],
                       c ? "tinted (0.9, 0.6, 0.3)" : "clear", w, wmu, wf, wr, wse);
            }
    printf("largest |albedo OpenPBR - walk|: clear coats %.4f, tinted coats %.4f\n", worst[0], worst[1]);
}
