/* bench/bench_openpbr.c - OpenPBR Surface (appear.h SECTION openpbr):
     bench_openpbr   latency (dependent chain: each call's directions from the previous call's
                     output) of eval, pdf and sample for four materials, against the sum of
                     their active lobes called directly (the same lobe structs, taken from the
                     made model): eval the lobes' evals, pdf their pdfs, sample one lobe's
                     sampler (by uc) plus every lobe's eval and pdf, what a hand-written
                     mixture costs without the layering's weights. Issue 33's goal: <= 1.3x.
                       plastic    the spec's default (specular GGX r 0.3 over an EON diffuse)
                       car paint  a clear smooth coat over a half metal, half diffuse base
                       glass      transmission 1, specular r 0.1 (the dielectric's R + T)
                       diffuse    base only, specular_weight 0: every optional lobe off
     ./build/bench_O2 openpbr */
#include "bench.h"
#include <stdio.h>

#define ON 4096
typedef struct {
    const appear_openpbr *m;
    int kind; /* 0 plastic, 1 car paint, 2 glass, 3 diffuse */
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
        return appear_conductor_eval(&m->metal, wo, wi).v[0] + appear_dielectric_eval(&m->spec, wo, wi).v[0] +
               appear_eon_eval(&m->diffuse, wo, wi).v[0];
    case 2: return appear_dielectric_eval(&m->glass, wo, wi).v[0];
    default: return appear_eon_eval(&m->diffuse, wo, wi).v[0];
    }
}
static float s_pdf(const octx *c, appear_vec3 wo, appear_vec3 wi)
{
    const appear_openpbr *m = c->m;
    switch (c->kind) {
    case 0: return appear_conductor_pdf(&m->spec_lobe, wo, wi) + appear_eon_pdf(&m->diffuse, wo, wi);
    case 1:
        return appear_conductor_pdf(&m->metal, wo, wi) + appear_conductor_pdf(&m->spec_lobe, wo, wi) +
               appear_eon_pdf(&m->diffuse, wo, wi);
    case 2: return appear_dielectric_pdf(&m->glass, wo, wi);
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
    else if (c->kind == 3 || uc < 0.5f) ok = appear_eon_sample(&c->m->diffuse, wo, uc, c->u[i][0], c->u[i][1], &s);
    else ok = appear_conductor_sample(&c->m->spec_lobe, wo, uc, c->u[i][0], c->u[i][1], &s);
    v = ok ? s_eval(c, wo, s.wi) / s_pdf(c, wo, s.wi) : 0.0f;
})

void bench_openpbr(void)
{
    static octx c;
    static const char *names[4] = { "plastic", "car paint", "glass", "diffuse (every optional lobe off)" };
    static void (*const fast[3])(void *) = { run_o_eval, run_o_pdf, run_o_sample };
    static void (*const sum[3])(void *) = { run_s_eval, run_s_pdf, run_s_sample };
    static const char *verbs[3] = { "eval", "pdf", "sample" };
    b_rng r = b_rng_make(37);
    int k, i, v;
    for (i = 0; i < ON; ++i) { c.u[i][0] = b_randf(&r); c.u[i][1] = b_randf(&r); c.u[i][2] = b_randf(&r); }
    b_note("openpbr latency: appear_openpbr against the sum of its active lobes called directly (the same "
           "lobe structs); dependent chains, ns per call");
    for (k = 0; k < 4; ++k) {
        appear_openpbr_params p = appear_openpbr_params_default();
        appear_openpbr m;
        p.base_color = appear_spectrum_rgb(0.8f, 0.1f, 0.1f);
        if (k == 1) { p.coat_weight = 1.0f; p.base_metalness = 0.5f; p.specular_roughness = 0.4f; }
        if (k == 2) { p.transmission_weight = 1.0f; p.specular_roughness = 0.1f; }
        if (k == 3) p.specular_weight = 0.0f;
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
