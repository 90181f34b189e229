/* tests/test_generic.c - the generic interface (SECTION generic of appear.h): appear_bsdf and
   appear_phase give the same bits as the direct calls, for every model; their lobe sets; the
   defined results of invalid and zero-initialised values; their size; and every kind is
   reached by the model battery's registry (tests/adapters.h), so no model is left out of it.

   A row is one model instance: the generic value, the same model for the direct calls, and
   the lobe set the model must report. Each row runs random and adversarial (wo, wi, uc, u1,
   u2) through eval, pdf and sample both ways and compares the results bit for bit (memcmp of
   the values and records); the stochastic models run from two copies of one rng state, whose
   states must agree afterwards too. */
#include "harness.h"
#include "adapters.h"
#include <string.h>

#define NROWS(t) ((int)(sizeof(t) / sizeof((t)[0])))

/* the direct models of a row (one of them is used) */
typedef struct g_direct {
    appear_lambert lambert;
    appear_eon eon;
    appear_ward ward;
    appear_conductor conductor;
    appear_dielectric dielectric;
    appear_thin_dielectric thin;
    appear_thinfilm_conductor thinfilm;
    appear_hg hg;
    appear_dhg dhg;
    appear_draine draine;
    appear_mie mie;
    appear_sggx sggx;
    appear_sheen sheen;
    appear_layered layered; /* the generic value refers to it: keep g_direct in place */
    appear_coated coated;   /* the same */
    appear_openpbr openpbr; /* the same */
    appear_dielectric_dispersive dispersive;
    appear_rng rng; /* the direct calls' copy of the generic value's rng */
} g_direct;

static appear_phase_table g_table;
static appear_fiber g_fiber;
static appear_rng g_rng; /* the generic values' rng */

/* The direct calls of each model: D_BSDF(id, FN, member) writes g_<id>_eval / _pdf /
   _sample for a model with the usual signatures. */
typedef appear_spectrum (*g_eval_fn)(g_direct *d, appear_vec3 wo, appear_vec3 wi);
typedef float (*g_pdf_fn)(g_direct *d, appear_vec3 wo, appear_vec3 wi);
typedef int (*g_sample_fn)(g_direct *d, appear_vec3 wo, float uc, float u1, float u2,
                           appear_bsdf_record *s);
typedef float (*g_peval_fn)(g_direct *d, appear_vec3 wo, appear_vec3 wi);
typedef int (*g_psample_fn)(g_direct *d, appear_vec3 wo, float uc, float u1, float u2,
                            appear_phase_record *s);
#define D_BSDF(id, FN, member)                                                                     \
    static appear_spectrum g_##id##_eval(g_direct *d, appear_vec3 wo, appear_vec3 wi)              \
    { return FN##_eval(&d->member, wo, wi); }                                                      \
    static float g_##id##_pdf(g_direct *d, appear_vec3 wo, appear_vec3 wi)                         \
    { return FN##_pdf(&d->member, wo, wi); }                                                       \
    static int g_##id##_sample(g_direct *d, appear_vec3 wo, float uc, float u1, float u2,          \
                               appear_bsdf_record *s)                                              \
    { return FN##_sample(&d->member, wo, uc, u1, u2, s); }
D_BSDF(lambert, appear_lambert, lambert)
D_BSDF(eon, appear_eon, eon)
D_BSDF(ward, appear_ward, ward)
D_BSDF(conductor, appear_conductor, conductor)
D_BSDF(conductor_comp, appear_conductor_comp, conductor)
D_BSDF(thinfilm, appear_thinfilm_conductor, thinfilm)
D_BSDF(dielectric, appear_dielectric, dielectric)
D_BSDF(dielectric_comp, appear_dielectric_comp, dielectric)
D_BSDF(thin, appear_thin_dielectric, thin)
D_BSDF(sheen, appear_sheen, sheen)
D_BSDF(coated, appear_coated, coated)
D_BSDF(openpbr, appear_openpbr, openpbr)
D_BSDF(dispersive, appear_dielectric_dispersive, dispersive)
/* the random walks: eval and sample draw from the rng; uc, u1, u2 unused */
#define D_BSDF_MS(id, FN, member)                                                                  \
    static appear_spectrum g_##id##_eval(g_direct *d, appear_vec3 wo, appear_vec3 wi)              \
    { return FN##_eval(&d->member, wo, wi, &d->rng); }                                             \
    static float g_##id##_pdf(g_direct *d, appear_vec3 wo, appear_vec3 wi)                         \
    { return FN##_pdf(&d->member, wo, wi); }                                                       \
    static int g_##id##_sample(g_direct *d, appear_vec3 wo, float uc, float u1, float u2,          \
                               appear_bsdf_record *s)                                              \
    { (void)uc; (void)u1; (void)u2; return FN##_sample(&d->member, wo, &d->rng, s); }
D_BSDF_MS(conductor_ms, appear_conductor_ms, conductor)
D_BSDF_MS(dielectric_ms, appear_dielectric_ms, dielectric)
/* the layered reference: eval, pdf and sample all draw from the rng; uc, u1, u2 unused */
static appear_spectrum g_layered_eval(g_direct *d, appear_vec3 wo, appear_vec3 wi)
{ return appear_layered_eval(&d->layered, wo, wi, &d->rng); }
static float g_layered_pdf(g_direct *d, appear_vec3 wo, appear_vec3 wi)
{ return appear_layered_pdf(&d->layered, wo, wi, &d->rng); }
static int g_layered_sample(g_direct *d, appear_vec3 wo, float uc, float u1, float u2, appear_bsdf_record *s)
{ (void)uc; (void)u1; (void)u2; return appear_layered_sample(&d->layered, wo, &d->rng, s); }

#define D_PHASE(id, EVAL, PDF, SAMPLE)                                                             \
    static float g_##id##_eval(g_direct *d, appear_vec3 wo, appear_vec3 wi)                        \
    { (void)d; return EVAL; }                                                                      \
    static float g_##id##_pdf(g_direct *d, appear_vec3 wo, appear_vec3 wi)                         \
    { (void)d; return PDF; }                                                                       \
    static int g_##id##_sample(g_direct *d, appear_vec3 wo, float uc, float u1, float u2,          \
                               appear_phase_record *s)                                             \
    { (void)d; (void)uc; return SAMPLE; }
D_PHASE(isotropic, appear_isotropic_eval(wo, wi), appear_isotropic_pdf(wo, wi),
        appear_isotropic_sample(wo, u1, u2, s))
D_PHASE(hg, appear_hg_eval(&d->hg, wo, wi), appear_hg_pdf(&d->hg, wo, wi),
        appear_hg_sample(&d->hg, wo, u1, u2, s))
D_PHASE(dhg, appear_dhg_eval(&d->dhg, wo, wi), appear_dhg_pdf(&d->dhg, wo, wi),
        appear_dhg_sample(&d->dhg, wo, u1, u2, s))
D_PHASE(rayleigh, appear_rayleigh_eval(wo, wi), appear_rayleigh_pdf(wo, wi),
        appear_rayleigh_sample(wo, u1, u2, s))
D_PHASE(draine, appear_draine_eval(&d->draine, wo, wi), appear_draine_pdf(&d->draine, wo, wi),
        appear_draine_sample(&d->draine, wo, u1, u2, s))
D_PHASE(mie, appear_mie_eval(&d->mie, wo, wi), appear_mie_pdf(&d->mie, wo, wi),
        appear_mie_sample(&d->mie, wo, u1, u2, s))
D_PHASE(table, appear_phase_table_eval(&g_table, wo, wi), appear_phase_table_pdf(&g_table, wo, wi),
        appear_phase_table_sample(&g_table, wo, u1, u2, s))
D_PHASE(sggx_spec, appear_sggx_specular_eval(&d->sggx, wo, wi),
        appear_sggx_specular_pdf(&d->sggx, wo, wi), appear_sggx_specular_sample(&d->sggx, wo, u1, u2, s))
D_PHASE(fiber, appear_fiber_eval(&g_fiber, wo, wi), appear_fiber_pdf(&g_fiber, wo, wi),
        appear_fiber_sample(&g_fiber, wo, u1, u2, s))
/* SGGX diffuse: the documented draws (eval and pdf: u1 then u2; sample: u4 after the call's
   uc as u3) */
static float g_sggx_diff_est(g_direct *d, appear_vec3 wo, appear_vec3 wi)
{
    float u1 = appear_rng_next(&d->rng);
    float u2 = appear_rng_next(&d->rng);
    return appear_sggx_diffuse_eval(&d->sggx, wo, wi, u1, u2);
}
static int g_sggx_diff_sample(g_direct *d, appear_vec3 wo, float uc, float u1, float u2,
                              appear_phase_record *s)
{
    float u4 = appear_rng_next(&d->rng);
    return appear_sggx_diffuse_sample(&d->sggx, wo, u1, u2, uc, u4, s);
}

typedef struct g_row {
    const char *name;
    unsigned flags; /* the lobe set the model must report */
    int stochastic; /* the rng is part of the state compared */
    /* BSDF rows */
    g_eval_fn eval;
    g_pdf_fn pdf;
    g_sample_fn sample;
    /* phase rows */
    g_peval_fn peval;
    g_peval_fn ppdf;
    g_psample_fn psample;
} g_row;

#define R_ APPEAR_LOBE_REFLECTION
#define T_ APPEAR_LOBE_TRANSMISSION
#define DIF APPEAR_LOBE_DIFFUSE
#define GLO APPEAR_LOBE_GLOSSY
#define SPE APPEAR_LOBE_SPECULAR
#define STO APPEAR_MODEL_STOCHASTIC
#define B_(id) g_##id##_eval, g_##id##_pdf, g_##id##_sample, 0, 0, 0
#define P_(id) 0, 0, 0, g_##id##_eval, g_##id##_pdf, g_##id##_sample

/* Builds row i's generic value (b or p) and its direct model (d); names the row. The rows
   and this switch are one table: row i here is g_rows[i]. */
enum {
    G_LAMBERT, G_LAMBERT_BLACK, G_EON, G_EON_COSINE, G_WARD, G_WARD_NO_DIFFUSE, G_WARD_MIRROR, G_CONDUCTOR,
    G_CONDUCTOR_SMOOTH, G_CONDUCTOR_F0, G_CONDUCTOR_F82, G_CONDUCTOR_COMP, G_CONDUCTOR_MS,
    G_CONDUCTOR_MS_SMOOTH, G_THINFILM, G_DIELECTRIC, G_DIELECTRIC_SMOOTH, G_DIELECTRIC_ETA1,
    G_DIELECTRIC_COMP, G_DIELECTRIC_MS, G_THIN, G_ISOTROPIC, G_HG, G_HG_DELTA, G_DHG,
    G_DHG_ONE_LOBE, G_RAYLEIGH, G_DRAINE, G_MIE, G_HG_DRAINE, G_TABLE, G_SGGX_SPEC,
    G_SGGX_SPEC_SINGULAR, G_SGGX_DIFF, G_FIBER, G_SHEEN, G_LAYERED, G_LAYERED_SMOOTH, G_LAYERED_GLASS,
    G_COATED, G_PLASTIC, G_COATED_MIRROR, G_OPENPBR, G_OPENPBR_GLASS, G_DISPERSIVE, G_ROWS
};
static const g_row g_rows[G_ROWS] = {
    { "lambert", R_ | DIF, 0, B_(lambert) },
    { "lambert black", R_ | DIF, 0, B_(lambert) },
    { "eon sigma 0.7", R_ | DIF, 0, B_(eon) },
    { "eon sigma 1, cosine sampling", R_ | DIF, 0, B_(eon) },
    { "ward duer", R_ | DIF | GLO, 0, B_(ward) },
    { "ward balanced, rho_d 0", R_ | GLO, 0, B_(ward) },
    { "ward original, mirror limit", R_ | DIF | SPE, 0, B_(ward) },
    { "conductor ggx 0.3", R_ | GLO, 0, B_(conductor) },
    { "conductor smooth", R_ | SPE, 0, B_(conductor) },
    { "conductor constant F0, beckmann anisotropic", R_ | GLO, 0, B_(conductor) },
    { "conductor F82-tint", R_ | GLO, 0, B_(conductor) },
    { "conductor comp", R_ | GLO, 0, B_(conductor_comp) },
    { "conductor ms", R_ | GLO | STO, 1, B_(conductor_ms) },
    { "conductor ms smooth", R_ | SPE, 1, B_(conductor_ms) },
    { "thin-film conductor", R_ | GLO, 0, B_(thinfilm) },
    { "dielectric ggx 0.2 eta 1.5", R_ | T_ | GLO, 0, B_(dielectric) },
    { "dielectric smooth eta 1.33", R_ | T_ | SPE, 0, B_(dielectric) },
    { "dielectric eta 1 (pass-through)", T_ | SPE, 0, B_(dielectric) },
    { "dielectric comp", R_ | T_ | GLO, 0, B_(dielectric_comp) },
    { "dielectric ms", R_ | T_ | GLO | STO, 1, B_(dielectric_ms) },
    { "thin dielectric", R_ | T_ | SPE, 0, B_(thin) },
    { "isotropic", DIF, 0, P_(isotropic) },
    { "hg 0.7", GLO, 0, P_(hg) },
    { "hg -1 (delta)", SPE, 0, P_(hg) },
    { "dhg 0.8 / -1 (glossy + delta)", GLO | SPE, 0, P_(dhg) },
    { "dhg w 1 (the second lobe unused)", GLO, 0, P_(dhg) },
    { "rayleigh", DIF, 0, P_(rayleigh) },
    { "draine", GLO, 0, P_(draine) },
    { "mie 2 um", GLO, 0, P_(mie) },
    { "hg + draine", GLO, 0, P_(mie) },
    { "table", GLO, 0, P_(table) },
    { "sggx specular", GLO, 0, P_(sggx_spec) },
    { "sggx specular singular", SPE, 0, P_(sggx_spec) },
    { "sggx diffuse", DIF | STO, 1, 0, 0, 0, g_sggx_diff_est, g_sggx_diff_est, g_sggx_diff_sample },
    { "fiber", GLO, 0, P_(fiber) },
    { "sheen", R_ | GLO, 0, B_(sheen) },
    { "layered: ggx 0.3 coat eta 1.5 over lambert", R_ | GLO | DIF | STO, 1, B_(layered) },
    { "layered: smooth coat eta 1.5 over a smooth conductor (all deltas)", R_ | SPE, 1, B_(layered) },
    { "layered: ggx 0.2 coat over a ggx 0.3 glass base, absorbing slab (transmits)", R_ | T_ | GLO | STO, 1,
      B_(layered) },
    { "coated: ggx 0.2 coat over lambert, absorbing", R_ | GLO | DIF, 0, B_(coated) },
    { "plastic: smooth coat over lambert", R_ | SPE | DIF, 0, B_(coated) },
    { "coated: smooth coat over a smooth conductor (albedo mode)", R_ | SPE, 0, B_(coated) },
    { "openpbr: a plastic under a smooth clear coat", R_ | DIF | GLO | SPE, 0, B_(openpbr) },
    { "openpbr: a frosted glass (transmission 1), both sides", R_ | T_ | GLO, 0, B_(openpbr) },
    { "dielectric dispersive ggx 0.3 (n_d 1.7, Abbe 30)", R_ | T_ | GLO, 0, B_(dispersive) },
};

static void g_make(int i, appear_bsdf *b, appear_phase *p, g_direct *d)
{
    appear_microfacet ggx = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
    appear_microfacet smooth = appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f,
                                                      APPEAR_SAMPLE_VISIBLE);
    appear_spectrum eta = appear_spectrum_rgb(0.2f, 0.9f, 1.4f);
    appear_spectrum k = appear_spectrum_rgb(3.9f, 2.4f, 1.6f);
    appear_vec3 axis = appear_normalize(appear_vec3_make(0.3f, -0.2f, 0.9f));
    memset(b, 0, sizeof *b);
    memset(p, 0, sizeof *p);
    memset(d, 0, sizeof *d);
    switch (i) {
    case G_LAMBERT: d->lambert = appear_lambert_make(appear_spectrum_rgb(0.8f, 0.5f, 0.2f));
        *b = appear_bsdf_lambert(d->lambert); break;
    case G_LAMBERT_BLACK: d->lambert = appear_lambert_make(appear_spectrum_splat(0.0f));
        *b = appear_bsdf_lambert(d->lambert); break;
    case G_EON: d->eon = appear_eon_make(appear_spectrum_rgb(0.8f, 0.5f, 0.2f), 0.7f);
        *b = appear_bsdf_eon(d->eon); break;
    case G_EON_COSINE:
        d->eon = appear_eon_make_sampled(appear_spectrum_splat(1.0f), 1.0f, APPEAR_EON_SAMPLE_COSINE);
        *b = appear_bsdf_eon(d->eon); break;
    case G_WARD:
        d->ward = appear_ward_make(appear_spectrum_splat(0.3f), appear_spectrum_splat(0.2f), 0.2f,
                                   0.4f, APPEAR_WARD_DUER);
        *b = appear_bsdf_ward(d->ward); break;
    case G_WARD_NO_DIFFUSE:
        d->ward = appear_ward_make(appear_spectrum_splat(0.0f), appear_spectrum_splat(0.5f), 0.1f,
                                   0.1f, APPEAR_WARD_BALANCED);
        *b = appear_bsdf_ward(d->ward); break;
    case G_WARD_MIRROR:
        d->ward = appear_ward_make(appear_spectrum_splat(0.4f), appear_spectrum_splat(0.5f), 5e-5f,
                                   5e-5f, APPEAR_WARD_ORIGINAL);
        *b = appear_bsdf_ward(d->ward); break;
    case G_CONDUCTOR: d->conductor = appear_conductor_make(ggx, eta, k);
        *b = appear_bsdf_conductor(d->conductor); break;
    case G_CONDUCTOR_SMOOTH: d->conductor = appear_conductor_make(smooth, eta, k);
        *b = appear_bsdf_conductor(d->conductor); break;
    case G_CONDUCTOR_F0:
        d->conductor = appear_conductor_make_reflectance(
            appear_microfacet_make(APPEAR_BECKMANN, 0.1f, 0.5f, APPEAR_SAMPLE_VISIBLE),
            appear_spectrum_rgb(0.9f, 0.6f, 0.3f));
        *b = appear_bsdf_conductor(d->conductor); break;
    case G_CONDUCTOR_F82:
        d->conductor = appear_conductor_make_f82(ggx, appear_spectrum_rgb(0.9f, 0.6f, 0.3f),
                                                 appear_spectrum_rgb(0.8f, 0.8f, 0.9f));
        *b = appear_bsdf_conductor(d->conductor); break;
    case G_CONDUCTOR_COMP: d->conductor = appear_conductor_make(ggx, eta, k);
        *b = appear_bsdf_conductor_comp(d->conductor); break;
    case G_CONDUCTOR_MS: d->conductor = appear_conductor_make(ggx, eta, k);
        *b = appear_bsdf_conductor_ms(d->conductor, &g_rng); break;
    case G_CONDUCTOR_MS_SMOOTH: d->conductor = appear_conductor_make(smooth, eta, k);
        *b = appear_bsdf_conductor_ms(d->conductor, &g_rng); break;
    case G_THINFILM:
        d->thinfilm = appear_thinfilm_conductor_make(ggx, appear_thinfilm_make_rgb(1.4f, 400.0f,
                                                                                   eta, k));
        *b = appear_bsdf_thinfilm_conductor(d->thinfilm); break;
    case G_DIELECTRIC:
        d->dielectric = appear_dielectric_make(
            appear_microfacet_make(APPEAR_GGX, 0.2f, 0.2f, APPEAR_SAMPLE_VISIBLE), 1.5f);
        *b = appear_bsdf_dielectric(d->dielectric); break;
    case G_DIELECTRIC_SMOOTH: d->dielectric = appear_dielectric_make(smooth, 1.33f);
        *b = appear_bsdf_dielectric(d->dielectric); break;
    case G_DIELECTRIC_ETA1: d->dielectric = appear_dielectric_make(ggx, 1.0f);
        *b = appear_bsdf_dielectric(d->dielectric); break;
    case G_DIELECTRIC_COMP: d->dielectric = appear_dielectric_make(ggx, 1.5f);
        *b = appear_bsdf_dielectric_comp(d->dielectric); break;
    case G_DIELECTRIC_MS: d->dielectric = appear_dielectric_make(ggx, 1.5f);
        *b = appear_bsdf_dielectric_ms(d->dielectric, &g_rng); break;
    case G_THIN: d->thin = appear_thin_dielectric_make(1.5f);
        *b = appear_bsdf_thin_dielectric(d->thin); break;
    case G_ISOTROPIC: *p = appear_phase_isotropic(); break;
    case G_HG: d->hg = appear_hg_make(0.7f); *p = appear_phase_hg(d->hg); break;
    case G_HG_DELTA: d->hg = appear_hg_make(-1.0f); *p = appear_phase_hg(d->hg); break;
    case G_DHG: d->dhg = appear_dhg_make(0.8f, -1.0f, 0.7f); *p = appear_phase_dhg(d->dhg); break;
    case G_DHG_ONE_LOBE: d->dhg = appear_dhg_make(0.5f, 1.0f, 1.0f); *p = appear_phase_dhg(d->dhg);
        break;
    case G_RAYLEIGH: *p = appear_phase_rayleigh(); break;
    case G_DRAINE: d->draine = appear_draine_make(0.6f, 1.0f); *p = appear_phase_draine(d->draine);
        break;
    case G_MIE: d->mie = appear_mie_make(2.0f); *p = appear_phase_mie(d->mie); break;
    case G_HG_DRAINE: d->mie = appear_hg_draine_make(0.8f, 0.3f, 2.0f, 0.25f);
        *p = appear_phase_mie(d->mie); break;
    case G_TABLE: *p = appear_phase_tabulated(&g_table); break;
    case G_SGGX_SPEC: d->sggx = appear_sggx_make_surface(axis, 0.3f);
        *p = appear_phase_sggx_specular(d->sggx); break;
    case G_SGGX_SPEC_SINGULAR:
        d->sggx = appear_sggx_make(0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f);
        *p = appear_phase_sggx_specular(d->sggx); break;
    case G_SGGX_DIFF: d->sggx = appear_sggx_make_fiber(axis, 0.4f);
        *p = appear_phase_sggx_diffuse(d->sggx, &g_rng); break;
    case G_FIBER: *p = appear_phase_fiber(&g_fiber); break;
    case G_SHEEN: d->sheen = appear_sheen_make(appear_spectrum_rgb(0.9f, 0.5f, 0.3f), 0.6f);
        *b = appear_bsdf_sheen(d->sheen); break;
    case G_LAYERED: case G_LAYERED_SMOOTH: case G_LAYERED_GLASS: {
        /* the parts are copied into d->layered; *b refers to d->layered */
        appear_microfacet g2 = appear_microfacet_make(APPEAR_GGX, 0.2f, 0.2f, APPEAR_SAMPLE_VISIBLE);
        appear_bsdf top, base;
        appear_slab slab = appear_slab_none();
        if (i == G_LAYERED) {
            top = appear_bsdf_dielectric(appear_dielectric_make(ggx, 1.5f));
            base = appear_bsdf_lambert(appear_lambert_make(appear_spectrum_rgb(0.8f, 0.5f, 0.2f)));
        } else if (i == G_LAYERED_SMOOTH) {
            top = appear_bsdf_dielectric(appear_dielectric_make(smooth, 1.5f));
            base = appear_bsdf_conductor(appear_conductor_make(smooth, eta, k));
        } else {
            top = appear_bsdf_dielectric(appear_dielectric_make(g2, 1.5f));
            base = appear_bsdf_dielectric(appear_dielectric_make(ggx, 1.0f / 1.5f));
            slab = appear_slab_from_transmittance(appear_spectrum_rgb(0.9f, 0.7f, 0.5f),
                                                  appear_spectrum_splat(0.0f), 0.0f);
        }
        d->layered = appear_layered_make(&top, &base, slab, 1, 64);
        *b = appear_bsdf_layered(&d->layered, &g_rng);
    } break;
    case G_COATED: case G_PLASTIC: case G_COATED_MIRROR: {
        /* the base is copied into d->coated; *b refers to d->coated */
        appear_microfacet g2 = appear_microfacet_make(APPEAR_GGX, 0.2f, 0.2f, APPEAR_SAMPLE_VISIBLE);
        appear_bsdf base = appear_bsdf_lambert(appear_lambert_make(appear_spectrum_rgb(0.8f, 0.5f, 0.2f)));
        if (i == G_COATED)
            d->coated = appear_coated_make(appear_dielectric_make(g2, 1.5f), &base,
                                           appear_spectrum_rgb(0.9f, 0.7f, 0.5f), APPEAR_COATED_RECIPROCAL);
        else if (i == G_PLASTIC)
            d->coated = appear_plastic_make(smooth, 1.5f, appear_spectrum_rgb(0.8f, 0.5f, 0.2f),
                                            appear_spectrum_splat(1.0f));
        else {
            base = appear_bsdf_conductor(appear_conductor_make(smooth, eta, k));
            d->coated = appear_coated_make(appear_dielectric_make(smooth, 1.5f), &base, appear_spectrum_splat(1.0f),
                                           APPEAR_COATED_ALBEDO);
        }
        *b = appear_bsdf_coated(&d->coated);
    } break;
    case G_OPENPBR: case G_OPENPBR_GLASS: {
        /* *b refers to d->openpbr */
        appear_openpbr_params q = appear_openpbr_params_default();
        q.base_color = appear_spectrum_rgb(0.8f, 0.5f, 0.2f);
        if (i == G_OPENPBR) q.coat_weight = 1.0f;
        else { q.transmission_weight = 1.0f; q.transmission_color = q.base_color; }
        d->openpbr = appear_openpbr_make(&q);
        *b = appear_bsdf_openpbr(&d->openpbr);
    } break;
    case G_DISPERSIVE:
        d->dispersive = appear_dielectric_make_dispersive(ggx, appear_spectrum_rgb(1.72f, 1.70f, 1.69f));
        *b = appear_bsdf_dielectric_dispersive(d->dispersive); break;
    default: break;
    }
}

/* a and b within rel of each other (both 0 or equal: yes; a NaN: no) */
static int g_close(float a, float b, double rel)
{ return a == b || fabs((double)a - (double)b) <= rel * fmax(fabs((double)a), fabs((double)b)); }

/* the shared models by reference */
static void g_setup(void)
{
    static const float v[5] = { 0.1f, 0.2f, 0.3f, 1.0f, 4.0f };
    appear_phase_table_make(&g_table, v, NULL, 5);
    g_fiber = appear_fiber_make(appear_normalize(appear_vec3_make(0.1f, 0.7f, 0.7f)), 8.0f);
}

/* one input: random, or (every 8th) adversarial */
static void g_input(h_rng *r, long i, appear_vec3 *wo, appear_vec3 *wi, float u[3])
{
    int adv = i % 8 == 7, k;
    *wo = adv ? h_adv_dir(r) : h_rand_dir(r);
    *wi = adv && i % 16 == 15 ? h_adv_dir(r) : h_rand_dir(r);
    for (k = 0; k < 3; ++k) u[k] = adv ? h_adv_u(r) : h_randf(r);
}

void suite_generic(void)
{
    long n = h_n(20000);
    int i, j;
    g_setup();
    for (i = 0; i < G_ROWS; ++i) {
        const g_row *row = &g_rows[i];
        int is_bsdf = row->eval != 0;
        appear_bsdf b;
        appear_phase p;
        g_direct d;
        h_rng r = h_rng_make(9000u + (unsigned)i);
        long k, diff = 0, outside = 0, delta_nonzero = 0, nok = 0, rec_off = 0;
        int rec_is_eval;
        unsigned flags, seen = 0;
        g_rng = appear_rng_make(77u + (unsigned)i);
        g_make(i, &b, &p, &d);
        flags = is_bsdf ? appear_bsdf_flags(&b) : appear_phase_flags(&p);
        rec_is_eval = is_bsdf && appear__bsdf_record_is_eval(&b);
        h_case("generic %s: flags, bits of eval / pdf / sample against the direct calls",
               row->name);
        H_CHECK(flags == row->flags, "%s: flags %#x, expected %#x", row->name, flags, row->flags);
        for (k = 0; k < n; ++k) {
            appear_vec3 wo, wi;
            float u[3];
            int sg, sd;
            g_input(&r, k, &wo, &wi, u);
            d.rng = g_rng;
            if (is_bsdf) {
                appear_spectrum eg = appear_bsdf_eval(&b, wo, wi), ed = row->eval(&d, wo, wi);
                float pg = appear_bsdf_pdf(&b, wo, wi), pd = row->pdf(&d, wo, wi);
                appear_bsdf_record sgr, sdr;
                memset(&sgr, 0, sizeof sgr);
                memset(&sdr, 0, sizeof sdr);
                sg = appear_bsdf_sample(&b, wo, u[0], u[1], u[2], &sgr);
                sd = row->sample(&d, wo, u[0], u[1], u[2], &sdr);
                diff += memcmp(&eg, &ed, sizeof eg) != 0 || memcmp(&pg, &pd, sizeof pg) != 0 ||
                        sg != sd || memcmp(&sgr, &sdr, sizeof sgr) != 0;
                /* (a sample's own flag, never a model's) */
                sgr.flags &= ~(unsigned)APPEAR_SAMPLE_TERMINATE_SECONDARY;
                if (sg) { ++nok; seen |= sgr.flags; outside += (sgr.flags & ~flags) != 0; }
                delta_nonzero += !(flags & APPEAR_LOBE_NONDELTA) &&
                                 (eg.v[0] != 0.0f || eg.v[1] != 0.0f || eg.v[2] != 0.0f || pg != 0.0f);
                if (sg && rec_is_eval && (sgr.flags & APPEAR_LOBE_NONDELTA)) { /* the composites reuse it */
                    appear_spectrum ew = appear_bsdf_eval(&b, wo, sgr.wi);
                    rec_off += !g_close(appear_bsdf_pdf(&b, wo, sgr.wi), sgr.pdf, 2e-6);
                    for (j = 0; j < APPEAR_SPECTRUM_SAMPLES; ++j) rec_off += !g_close(ew.v[j], sgr.f.v[j], 2e-6);
                }
            } else {
                float eg = appear_phase_eval(&p, wo, wi), ed = row->peval(&d, wo, wi);
                float pg = appear_phase_pdf(&p, wo, wi), pd = row->ppdf(&d, wo, wi);
                appear_phase_record sgr, sdr;
                memset(&sgr, 0, sizeof sgr);
                memset(&sdr, 0, sizeof sdr);
                sg = appear_phase_sample(&p, wo, u[0], u[1], u[2], &sgr);
                sd = row->psample(&d, wo, u[0], u[1], u[2], &sdr);
                diff += memcmp(&eg, &ed, sizeof eg) != 0 || memcmp(&pg, &pd, sizeof pg) != 0 ||
                        sg != sd || memcmp(&sgr, &sdr, sizeof sgr) != 0;
                if (sg) { ++nok; seen |= sgr.flags; outside += (sgr.flags & ~flags) != 0; }
                delta_nonzero += !(flags & APPEAR_LOBE_NONDELTA) && (eg != 0.0f || pg != 0.0f);
            }
            diff += row->stochastic && memcmp(&d.rng, &g_rng, sizeof d.rng) != 0;
        }
        H_CHECK(diff == 0, "%s: %ld of %ld inputs differ from the direct calls", row->name, diff, n);
        H_CHECK(nok > n / 4, "%s: only %ld of %ld samples succeeded", row->name, nok, n);
        /* the kinds whose record a composite takes for the sampled lobe's eval and pdf (appear.h
           appear__bsdf_record_is_eval): the record holds them at its wi, and no random walk is one */
        H_CHECK(rec_off == 0, "%s: %ld record values differ from eval / pdf at the record's wi by > 2e-6",
                row->name, rec_off);
        H_CHECK(!(rec_is_eval && row->stochastic), "%s: a random walk's record taken for its eval", row->name);
        H_CHECK(outside == 0, "%s: %ld samples carry a flag outside the model's %#x", row->name,
                outside, flags);
        /* the lobe set is tight: every lobe kind it names is sampled (the stochastic bit is not
           a lobe) */
        H_CHECK(seen == (flags & ~(unsigned)APPEAR_MODEL_STOCHASTIC),
                "%s: samples carried the lobes %#x, the model reports %#x", row->name, seen, flags);
        H_CHECK(delta_nonzero == 0, "%s: all-delta model with %ld nonzero eval / pdf", row->name,
                delta_nonzero);
    }

    h_case("generic: invalid models, NULL references and rngs, zero-initialised values");
    {
        appear_microfacet ggx = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f,
                                                       APPEAR_SAMPLE_VISIBLE);
        appear_conductor c = appear_conductor_make(ggx, appear_spectrum_splat(0.2f),
                                                   appear_spectrum_splat(3.0f));
        appear_bsdf bs[8];
        appear_phase ps[5];
        appear_vec3 wo = appear_vec3_make(0.0f, 0.6f, 0.8f), wi = appear_vec3_make(0.6f, 0.0f, 0.8f);
        /* the layered reference: a valid model with a NULL rng, a NULL model, an invalid one (a NaN
           slab albedo) */
        appear_bsdf top = appear_bsdf_dielectric(appear_dielectric_make(ggx, 1.5f));
        appear_bsdf base = appear_bsdf_lambert(appear_lambert_make(appear_spectrum_splat(0.5f)));
        appear_slab bad_slab = appear_slab_make(1.0f, appear_spectrum_splat(1.0f),
                                                appear_spectrum_splat(NAN), 0.0f);
        appear_layered lv = appear_layered_make(&top, &base, appear_slab_none(), 1, 8);
        appear_layered li = appear_layered_make(&top, &base, bad_slab, 1, 8);
        appear_rng rng = appear_rng_make(5u);
        memset(&bs[0], 0, sizeof bs[0]);
        bs[1] = appear_bsdf_lambert(appear_lambert_make(appear_spectrum_splat(NAN)));
        bs[2] = appear_bsdf_conductor_ms(c, NULL);
        bs[3] = appear_bsdf_dielectric_ms(appear_dielectric_make(ggx, 1.5f), NULL);
        bs[4] = appear_bsdf_dielectric(appear_dielectric_make(ggx, -1.0f));
        bs[5] = appear_bsdf_layered(&lv, NULL);
        bs[6] = appear_bsdf_layered(NULL, &rng);
        bs[7] = appear_bsdf_layered(&li, &rng);
        H_CHECK(lv.valid && !li.valid, "layered: make() verdicts %d (valid parts) and %d (NaN slab albedo)",
                lv.valid, li.valid);
        memset(&ps[0], 0, sizeof ps[0]);
        ps[1] = appear_phase_hg(appear_hg_make(1.5f));
        ps[2] = appear_phase_tabulated(NULL);
        ps[3] = appear_phase_fiber(NULL);
        ps[4] = appear_phase_sggx_diffuse(appear_sggx_make_surface(appear_vec3_make(0, 0, 1), 0.3f),
                                          NULL);
        for (j = 0; j < NROWS(bs); ++j) {
            appear_bsdf_record s;
            appear_spectrum f = appear_bsdf_eval(&bs[j], wo, wi);
            int ok = appear_bsdf_sample(&bs[j], wo, 0.3f, 0.4f, 0.5f, &s);
            H_CHECK(appear_bsdf_flags(&bs[j]) == 0 && f.v[0] == 0.0f && f.v[1] == 0.0f &&
                        f.v[2] == 0.0f && appear_bsdf_pdf(&bs[j], wo, wi) == 0.0f && !ok &&
                        s.flags == 0 && s.pdf == 0.0f && s.weight.v[0] == 0.0f,
                    "invalid bsdf %d: flags %#x, f %g, ok %d", j, appear_bsdf_flags(&bs[j]),
                    (double)f.v[0], ok);
        }
        /* the direct calls of the invalid layered model, and with a NULL rng: 0 / failure */
        {
            appear_bsdf_record s;
            appear_spectrum f = appear_layered_eval(&li, wo, wi, &rng);
            appear_spectrum g = appear_layered_eval(&lv, wo, wi, NULL);
            int ok = appear_layered_sample(&li, wo, &rng, &s), ok2;
            H_CHECK(appear_layered_flags(&li) == 0 && f.v[0] == 0.0f &&
                        appear_layered_pdf(&li, wo, wi, &rng) == 0.0f && !ok && s.flags == 0 && s.pdf == 0.0f,
                    "invalid layered model: flags %#x, f %g, ok %d", appear_layered_flags(&li), (double)f.v[0],
                    ok);
            ok2 = appear_layered_sample(&lv, wo, NULL, &s);
            H_CHECK(g.v[0] == 0.0f && appear_layered_pdf(&lv, wo, wi, NULL) == 0.0f && !ok2 && s.flags == 0,
                    "layered with a NULL rng: f %g, ok %d", (double)g.v[0], ok2);
        }
        for (j = 0; j < NROWS(ps); ++j) {
            appear_phase_record q;
            int ok = appear_phase_sample(&ps[j], wo, 0.3f, 0.4f, 0.5f, &q);
            H_CHECK(appear_phase_flags(&ps[j]) == 0 && appear_phase_eval(&ps[j], wo, wi) == 0.0f &&
                        appear_phase_pdf(&ps[j], wo, wi) == 0.0f && !ok && q.flags == 0 &&
                        q.pdf == 0.0f && q.weight == 0.0f,
                    "invalid phase %d: flags %#x, ok %d", j, appear_phase_flags(&ps[j]), ok);
        }
    }

    h_case("generic: sizes as documented (128 and 200 bytes on LP64, 3 spectrum samples)");
    if (sizeof(void *) == 8 && APPEAR_SPECTRUM_SAMPLES == 3) {
        H_CHECK(sizeof(appear_bsdf) == 128, "sizeof(appear_bsdf) = %zu", sizeof(appear_bsdf));
        H_CHECK(sizeof(appear_phase) == 200, "sizeof(appear_phase) = %zu", sizeof(appear_phase));
    }

    /* the battery's registry builds every kind, so no model is left out of the battery */
    h_case("generic: every appear_bsdf and appear_phase kind is built by a family of "
           "tests/adapters.h");
    {
        int bseen[APPEAR_BSDF_KIND_COUNT] = { 0 }, pseen[APPEAR_PHASE_KIND_COUNT] = { 0 };
        static ad_model m;
        ad_params q;
        memset(&q, 0, sizeof q);
        q.table = &g_table;
        for (j = 0; j < AD_COUNT; ++j) {
            ad_make(&m, j, &q);
            if (m.bsdf && m.b.kind > 0 && m.b.kind < APPEAR_BSDF_KIND_COUNT) bseen[m.b.kind] = 1;
            if (!m.bsdf && m.ph.kind > 0 && m.ph.kind < APPEAR_PHASE_KIND_COUNT) pseen[m.ph.kind] = 1;
        }
        for (j = 1; j < APPEAR_BSDF_KIND_COUNT; ++j)
            H_CHECK(bseen[j], "appear_bsdf kind %d is built by no family of tests/adapters.h", j);
        for (j = 1; j < APPEAR_PHASE_KIND_COUNT; ++j)
            H_CHECK(pseen[j], "appear_phase kind %d is built by no family of tests/adapters.h", j);
    }
    /* and every row of this file's table is one kind: all kinds are tested above */
    h_case("generic: this file's rows cover every kind");
    {
        int bseen[APPEAR_BSDF_KIND_COUNT] = { 0 }, pseen[APPEAR_PHASE_KIND_COUNT] = { 0 };
        for (i = 0; i < G_ROWS; ++i) {
            appear_bsdf b;
            appear_phase p;
            g_direct d;
            g_make(i, &b, &p, &d);
            if (g_rows[i].eval) bseen[b.kind] = 1; else pseen[p.kind] = 1;
        }
        for (j = 1; j < APPEAR_BSDF_KIND_COUNT; ++j)
            H_CHECK(bseen[j], "appear_bsdf kind %d has no row in tests/test_generic.c", j);
        for (j = 1; j < APPEAR_PHASE_KIND_COUNT; ++j)
            H_CHECK(pseen[j], "appear_phase kind %d has no row in tests/test_generic.c", j);
    }
}
