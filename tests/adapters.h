/* tests/adapters.h - one adapter per model family of appear.h, shared by
   build/appear-check (examples/appear_check.c) and the model battery
   (tests/battery.c, whose table is tests/test_models.c).

     ad_params        the parameters of one model instance: plain numbers,
                      one struct for every family (a family reads its fields)
     ad_make          builds an ad_model of a family from its parameters
     ad_eval, ad_pdf, ad_sample
                      the model's verbs with every colour channel, the
                      sample's lobe flags and eta (phase functions: the
                      scalar value in every channel)
     ad_eval1, ad_sample1
                      the same reduced to one number (BSDFs: the channel
                      average; phase functions: the value itself)
     ad_check_model   the model as tests/check.h callbacks (eval, pdf,
                      sample, sigma), for check_furnace and the other checks

   Adding a model family: an AD_ value, its fields in ad_params and
   ad_model, one case in ad_make and in each verb. Then rows in
   tests/test_models.c. Header only (static inline), C99, appear.h and
   tests/check.h; no allocation (a phase table is the caller's). */
#ifndef APPEAR_TEST_ADAPTERS_H
#define APPEAR_TEST_ADAPTERS_H
#include "../appear.h"
#include "check.h"
#include <math.h>
#include <string.h>

/* The families. The order is appear-check's model list (examples/appear_check.c). */
enum {
    AD_LAMBERT, AD_WARD, AD_CONDUCTOR, AD_CONDUCTOR_COMP, AD_CONDUCTOR_MS, AD_DIELECTRIC,
    AD_DIELECTRIC_COMP, AD_DIELECTRIC_MS, AD_THIN_DIELECTRIC, AD_THINFILM_CONDUCTOR, AD_ISOTROPIC,
    AD_HG, AD_DHG, AD_RAYLEIGH, AD_DRAINE, AD_MIE, AD_TABLE, AD_SGGX_SPECULAR, AD_SGGX_DIFFUSE,
    AD_FIBER,
    AD_CONDUCTOR_F0, /* appear-check's name for AD_CONDUCTOR with fresnel = AD_FRESNEL_F0 */
    AD_COUNT
};
/* conductor Fresnel: complex IOR (n, k), constant reflectance (f0), F82-tint (f0, tint) */
enum { AD_FRESNEL_IOR, AD_FRESNEL_F0, AD_FRESNEL_F82 };
/* SGGX shapes: alpha[0] about axis (surface: normals along it; fiber: normals
   orthogonal to it); the matrix S; eigenvalues S[0..2] on the frame of axis */
enum { AD_SGGX_SURFACE, AD_SGGX_FIBER, AD_SGGX_MATRIX, AD_SGGX_EIGEN };

typedef struct ad_params {
    int dist, sampling;        /* microfacet: APPEAR_GGX | APPEAR_BECKMANN; APPEAR_SAMPLE_* */
    float alpha[2];            /* ax, ay (sggx surface / fiber: alpha[0]; draine: Draine's alpha) */
    float eta;                 /* dielectric, thin dielectric: n_inside / n_outside */
    int fresnel;               /* conductor: AD_FRESNEL_* */
    float n[3], k[3];          /* conductor, thin-film base: complex IOR per channel */
    float f0[3], tint[3];      /* conductor: AD_FRESNEL_F0 / _F82 */
    float albedo[3];           /* lambert */
    int variant;               /* ward: appear_ward_variant */
    float rho_d[3], rho_s[3];  /* ward */
    float g, g1, g2, w;        /* hg, draine: g; dhg: g1, g2, w */
    float d;                   /* mie: droplet diameter in micrometres */
    const appear_phase_table *table;
    float film_eta, thickness; /* thin film: index, nm */
    int shape;                 /* sggx: AD_SGGX_* */
    float axis[3];             /* sggx, fiber: the axis (normalised in double by ad_make) */
    float S[6];                /* sggx: matrix xx yy zz xy xz yz, or eigenvalues */
    float p;                   /* fiber: exponent of |sin theta_m|^p */
    unsigned seed;             /* the rng of random walks and of SGGX diffuse sampling */
} ad_params;

typedef struct ad_model {
    int family;
    int valid, bsdf;
    int delta_only;      /* every lobe is a delta: eval and pdf are 0 */
    int stochastic_eval; /* eval is a noisy unbiased estimate (random walks) */
    int approx_pdf;      /* pdf is an approximation of the sampler's density (random walks) */
    float eta;           /* dielectric: eta; else 1 (check.h's transmitted-energy rule) */
    float ax, ay;        /* roughness of the microfacet families, else 0 */
    appear_lambert lambert;
    appear_ward ward;
    appear_conductor cond;
    appear_dielectric diel;
    appear_thin_dielectric thin;
    appear_thinfilm_conductor tfc;
    float g;
    appear_dhg dhg;
    appear_draine draine;
    appear_mie mie;
    const appear_phase_table *table;
    appear_sggx sggx;
    appear_fiber fiber;
    appear_rng rng;
    char name[160];      /* free for the caller (appear-check writes its options here) */
} ad_model;

/* One sample of any family: every channel; phase functions fill each channel
   with the scalar. ok = what the sampler returned. */
typedef struct ad_rec {
    appear_vec3 wi;
    appear_spectrum f, weight;
    float pdf, eta;
    unsigned flags;
    int ok;
} ad_rec;

static inline int ad_is_bsdf(int family)
{
    return family <= AD_THINFILM_CONDUCTOR || family == AD_CONDUCTOR_F0;
}
static inline appear_spectrum ad_rgb(const float v[3])
{
    appear_spectrum s = appear_spectrum_splat(v[2]);
    s.v[0] = v[0]; s.v[1] = v[1];
    return s;
}
static inline appear_vec3 ad_unit(const float v[3])
{   /* normalised in double (a zero or non-finite axis stays as given: make() rejects it) */
    double l = sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]);
    if (!(l > 0) || !isfinite(l)) return appear_vec3_make(v[0], v[1], v[2]);
    return appear_vec3_make((float)(v[0] / l), (float)(v[1] / l), (float)(v[2] / l));
}

/* Builds the model; returns m->valid (make()'s verdict). m->name is left empty. */
static inline int ad_make(ad_model *m, int family, const ad_params *p)
{
    appear_microfacet d = appear_microfacet_make(p->dist, p->alpha[0], p->alpha[1], p->sampling);
    appear_vec3 axis = ad_unit(p->axis);
    memset(m, 0, sizeof *m);
    if (family == AD_CONDUCTOR_F0) family = AD_CONDUCTOR;
    m->family = family;
    m->bsdf = ad_is_bsdf(family);
    m->eta = 1.0f;
    m->valid = 1;
    m->rng = appear_rng_make(p->seed);
    switch (family) {
    case AD_LAMBERT:
        m->lambert = appear_lambert_make(ad_rgb(p->albedo));
        m->valid = m->lambert.valid;
        break;
    case AD_WARD:
        m->ward = appear_ward_make(ad_rgb(p->rho_d), ad_rgb(p->rho_s), p->alpha[0], p->alpha[1],
                                   (appear_ward_variant)p->variant);
        m->valid = m->ward.valid; m->delta_only = m->ward.delta && m->ward.p_spec >= 1.0f;
        m->ax = p->alpha[0]; m->ay = p->alpha[1];
        break;
    case AD_CONDUCTOR: case AD_CONDUCTOR_COMP: case AD_CONDUCTOR_MS:
        if (p->fresnel == AD_FRESNEL_F0)
            m->cond = appear_conductor_make_reflectance(d, ad_rgb(p->f0));
        else if (p->fresnel == AD_FRESNEL_F82)
            m->cond = appear_conductor_make_f82(d, ad_rgb(p->f0), ad_rgb(p->tint));
        else m->cond = appear_conductor_make(d, ad_rgb(p->n), ad_rgb(p->k));
        m->valid = m->cond.valid; m->delta_only = d.smooth;
        m->stochastic_eval = m->approx_pdf = family == AD_CONDUCTOR_MS;
        m->ax = d.ax; m->ay = d.ay;
        break;
    case AD_DIELECTRIC: case AD_DIELECTRIC_COMP: case AD_DIELECTRIC_MS:
        m->diel = appear_dielectric_make(d, p->eta);
        m->valid = m->diel.valid; m->delta_only = m->diel.smooth; m->eta = p->eta;
        m->stochastic_eval = m->approx_pdf = family == AD_DIELECTRIC_MS;
        m->ax = d.ax; m->ay = d.ay;
        break;
    case AD_THIN_DIELECTRIC:
        m->thin = appear_thin_dielectric_make(p->eta);
        m->valid = m->thin.valid; m->delta_only = 1;
        break;
    case AD_THINFILM_CONDUCTOR:
        m->tfc = appear_thinfilm_conductor_make(
            d, appear_thinfilm_make_rgb(p->film_eta, p->thickness, ad_rgb(p->n), ad_rgb(p->k)));
        m->valid = m->tfc.valid; m->delta_only = d.smooth;
        m->ax = d.ax; m->ay = d.ay;
        break;
    case AD_ISOTROPIC: case AD_RAYLEIGH: break;
    case AD_HG:
        m->g = p->g; m->delta_only = fabsf(p->g) == 1.0f;
        m->valid = fabsf(p->g) <= 1.0f;
        break;
    case AD_DHG:
        m->dhg = appear_dhg_make(p->g1, p->g2, p->w);
        m->valid = m->dhg.valid;
        m->delta_only = fabsf(p->g1) == 1.0f && fabsf(p->g2) == 1.0f;
        break;
    case AD_DRAINE:
        m->draine = appear_draine_make(p->g, p->alpha[0]);
        m->valid = m->draine.valid; m->delta_only = fabsf(p->g) == 1.0f;
        break;
    case AD_MIE:
        m->mie = appear_mie_make(p->d);
        m->valid = m->mie.valid;
        break;
    case AD_TABLE:
        m->table = p->table;
        m->valid = p->table != NULL && p->table->n >= 2;
        break;
    case AD_SGGX_SPECULAR: case AD_SGGX_DIFFUSE:
        if (p->shape == AD_SGGX_MATRIX)
            m->sggx = appear_sggx_make(p->S[0], p->S[1], p->S[2], p->S[3], p->S[4], p->S[5]);
        else if (p->shape == AD_SGGX_EIGEN) {
            appear_frame f = appear_frame_from_normal(axis);
            m->sggx = appear_sggx_make_eigen(f.x, f.y, f.z, p->S[0], p->S[1], p->S[2]);
        } else
            m->sggx = p->shape == AD_SGGX_FIBER ? appear_sggx_make_fiber(axis, p->alpha[0])
                                                : appear_sggx_make_surface(axis, p->alpha[0]);
        m->valid = m->sggx.valid;
        m->delta_only = family == AD_SGGX_SPECULAR && m->sggx.singular;
        /* the stratified eval below is an average of the one-sample estimate: deterministic,
           but not exact; the pdf is that same average */
        break;
    default:
        m->fiber = appear_fiber_make(axis, p->p);
        m->valid = m->fiber.valid;
        break;
    }
    return m->valid;
}

/* SGGX diffuse: 16 x 16 stratified average of the one-sample estimate (deterministic) */
static inline float ad_sggx_diffuse_avg(const appear_sggx *s, appear_vec3 wo, appear_vec3 wi)
{
    double acc = 0;
    int i, j;
    for (i = 0; i < 16; ++i)
        for (j = 0; j < 16; ++j)
            acc += appear_sggx_diffuse_eval(s, wo, wi, (i + 0.5f) / 16.0f, (j + 0.5f) / 16.0f);
    return (float)(acc / 256.0);
}

/* the scalar value of a phase function (the BSDFs return -1) */
static inline float ad_phase_eval(ad_model *m, appear_vec3 wo, appear_vec3 wi)
{
    switch (m->family) {
    case AD_ISOTROPIC: return appear_isotropic_eval(wo, wi);
    case AD_HG: { appear_hg h = appear_hg_make(m->g); return appear_hg_eval(&h, wo, wi); }
    case AD_DHG: return appear_dhg_eval(&m->dhg, wo, wi);
    case AD_RAYLEIGH: return appear_rayleigh_eval(wo, wi);
    case AD_DRAINE: return appear_draine_eval(&m->draine, wo, wi);
    case AD_MIE: return appear_mie_eval(&m->mie, wo, wi);
    case AD_TABLE: return m->table ? appear_phase_table_eval(m->table, wo, wi) : 0.0f;
    case AD_SGGX_SPECULAR: return appear_sggx_specular_eval(&m->sggx, wo, wi);
    case AD_SGGX_DIFFUSE: return ad_sggx_diffuse_avg(&m->sggx, wo, wi);
    case AD_FIBER: return appear_fiber_eval(&m->fiber, wo, wi);
    default: return -1.0f;
    }
}

static inline appear_spectrum ad_eval(ad_model *m, appear_vec3 wo, appear_vec3 wi)
{
    switch (m->family) {
    case AD_LAMBERT: return appear_lambert_eval(&m->lambert, wo, wi);
    case AD_WARD: return appear_ward_eval(&m->ward, wo, wi);
    case AD_CONDUCTOR: return appear_conductor_eval(&m->cond, wo, wi);
    case AD_CONDUCTOR_COMP: return appear_conductor_comp_eval(&m->cond, wo, wi);
    case AD_CONDUCTOR_MS: return appear_conductor_ms_eval(&m->cond, wo, wi, &m->rng);
    case AD_DIELECTRIC: return appear_dielectric_eval(&m->diel, wo, wi);
    case AD_DIELECTRIC_COMP: return appear_dielectric_comp_eval(&m->diel, wo, wi);
    case AD_DIELECTRIC_MS: return appear_dielectric_ms_eval(&m->diel, wo, wi, &m->rng);
    case AD_THIN_DIELECTRIC: return appear_thin_dielectric_eval(&m->thin, wo, wi);
    case AD_THINFILM_CONDUCTOR: return appear_thinfilm_conductor_eval(&m->tfc, wo, wi);
    default: return appear_spectrum_splat(ad_phase_eval(m, wo, wi));
    }
}
static inline float ad_eval1(ad_model *m, appear_vec3 wo, appear_vec3 wi)
{
    return m->bsdf ? appear_spectrum_avg(ad_eval(m, wo, wi)) : ad_phase_eval(m, wo, wi);
}

static inline float ad_pdf(ad_model *m, appear_vec3 wo, appear_vec3 wi)
{
    switch (m->family) {
    case AD_LAMBERT: return appear_lambert_pdf(&m->lambert, wo, wi);
    case AD_WARD: return appear_ward_pdf(&m->ward, wo, wi);
    case AD_CONDUCTOR: return appear_conductor_pdf(&m->cond, wo, wi);
    case AD_CONDUCTOR_COMP: return appear_conductor_comp_pdf(&m->cond, wo, wi);
    case AD_CONDUCTOR_MS: return appear_conductor_ms_pdf(&m->cond, wo, wi);
    case AD_DIELECTRIC: return appear_dielectric_pdf(&m->diel, wo, wi);
    case AD_DIELECTRIC_COMP: return appear_dielectric_comp_pdf(&m->diel, wo, wi);
    case AD_DIELECTRIC_MS: return appear_dielectric_ms_pdf(&m->diel, wo, wi);
    case AD_THIN_DIELECTRIC: return appear_thin_dielectric_pdf(&m->thin, wo, wi);
    case AD_THINFILM_CONDUCTOR: return appear_thinfilm_conductor_pdf(&m->tfc, wo, wi);
    case AD_ISOTROPIC: return appear_isotropic_pdf(wo, wi);
    case AD_HG: { appear_hg h = appear_hg_make(m->g); return appear_hg_pdf(&h, wo, wi); }
    case AD_DHG: return appear_dhg_pdf(&m->dhg, wo, wi);
    case AD_RAYLEIGH: return appear_rayleigh_pdf(wo, wi);
    case AD_DRAINE: return appear_draine_pdf(&m->draine, wo, wi);
    case AD_MIE: return appear_mie_pdf(&m->mie, wo, wi);
    case AD_TABLE: return m->table ? appear_phase_table_pdf(m->table, wo, wi) : 0.0f;
    case AD_SGGX_SPECULAR: return appear_sggx_specular_pdf(&m->sggx, wo, wi);
    case AD_SGGX_DIFFUSE: return ad_sggx_diffuse_avg(&m->sggx, wo, wi);
    default: return appear_fiber_pdf(&m->fiber, wo, wi);
    }
}

static inline void ad_from_bsdf(ad_rec *r, const appear_bsdf_sample *s, int ok)
{
    r->ok = ok; r->wi = s->wi; r->f = s->f; r->weight = s->weight; r->pdf = s->pdf;
    r->eta = s->eta; r->flags = s->flags;
}
static inline void ad_from_phase(ad_rec *r, const appear_phase_sample *s, int ok)
{
    r->ok = ok; r->wi = s->wi; r->f = appear_spectrum_splat(s->f);
    r->weight = appear_spectrum_splat(s->weight); r->pdf = s->pdf; r->eta = 1.0f;
    r->flags = s->flags;
}
/* uc chooses a lobe (BSDFs), u1 u2 the direction; the random walks draw from
   m->rng; SGGX diffuse takes uc and one number of m->rng as its two extra
   numbers and reports f = pdf = the stratified eval at wi, weight 1. */
static inline void ad_sample(ad_model *m, appear_vec3 wo, float uc, float u1, float u2, ad_rec *r)
{
    appear_bsdf_sample b;
    appear_phase_sample p;
    switch (m->family) {
    case AD_LAMBERT:
        ad_from_bsdf(r, &b, appear_lambert_sample(&m->lambert, wo, uc, u1, u2, &b)); return;
    case AD_WARD: ad_from_bsdf(r, &b, appear_ward_sample(&m->ward, wo, uc, u1, u2, &b)); return;
    case AD_CONDUCTOR:
        ad_from_bsdf(r, &b, appear_conductor_sample(&m->cond, wo, uc, u1, u2, &b)); return;
    case AD_CONDUCTOR_COMP:
        ad_from_bsdf(r, &b, appear_conductor_comp_sample(&m->cond, wo, uc, u1, u2, &b)); return;
    case AD_CONDUCTOR_MS:
        ad_from_bsdf(r, &b, appear_conductor_ms_sample(&m->cond, wo, &m->rng, &b)); return;
    case AD_DIELECTRIC:
        ad_from_bsdf(r, &b, appear_dielectric_sample(&m->diel, wo, uc, u1, u2, &b)); return;
    case AD_DIELECTRIC_COMP:
        ad_from_bsdf(r, &b, appear_dielectric_comp_sample(&m->diel, wo, uc, u1, u2, &b)); return;
    case AD_DIELECTRIC_MS:
        ad_from_bsdf(r, &b, appear_dielectric_ms_sample(&m->diel, wo, &m->rng, &b)); return;
    case AD_THIN_DIELECTRIC:
        ad_from_bsdf(r, &b, appear_thin_dielectric_sample(&m->thin, wo, uc, u1, u2, &b)); return;
    case AD_THINFILM_CONDUCTOR:
        ad_from_bsdf(r, &b, appear_thinfilm_conductor_sample(&m->tfc, wo, uc, u1, u2, &b)); return;
    case AD_ISOTROPIC: ad_from_phase(r, &p, appear_isotropic_sample(wo, u1, u2, &p)); return;
    case AD_HG: {
        appear_hg h = appear_hg_make(m->g);
        ad_from_phase(r, &p, appear_hg_sample(&h, wo, u1, u2, &p));
        return;
    }
    case AD_DHG: ad_from_phase(r, &p, appear_dhg_sample(&m->dhg, wo, u1, u2, &p)); return;
    case AD_RAYLEIGH: ad_from_phase(r, &p, appear_rayleigh_sample(wo, u1, u2, &p)); return;
    case AD_DRAINE: ad_from_phase(r, &p, appear_draine_sample(&m->draine, wo, u1, u2, &p)); return;
    case AD_MIE: ad_from_phase(r, &p, appear_mie_sample(&m->mie, wo, u1, u2, &p)); return;
    case AD_TABLE:
        if (!m->table) { memset(&p, 0, sizeof p); ad_from_phase(r, &p, 0); return; }
        ad_from_phase(r, &p, appear_phase_table_sample(m->table, wo, u1, u2, &p)); return;
    case AD_SGGX_SPECULAR:
        ad_from_phase(r, &p, appear_sggx_specular_sample(&m->sggx, wo, u1, u2, &p)); return;
    case AD_SGGX_DIFFUSE: {
        int ok = appear_sggx_diffuse_sample(&m->sggx, wo, u1, u2, uc, appear_rng_next(&m->rng), &p);
        ad_from_phase(r, &p, ok);
        if (ok) {   /* exact weight 1; f = pdf by the stratified eval */
            float v = ad_sggx_diffuse_avg(&m->sggx, wo, p.wi);
            r->f = appear_spectrum_splat(v); r->pdf = v; r->weight = appear_spectrum_splat(1.0f);
        }
        return;
    }
    default: ad_from_phase(r, &p, appear_fiber_sample(&m->fiber, wo, u1, u2, &p)); return;
    }
}
/* one-number view of a sample: f and weight as ad_eval1 reduces them */
typedef struct ad_rec1 { appear_vec3 wi; float f, pdf, weight; unsigned flags; int ok; } ad_rec1;
static inline void ad_sample1(ad_model *m, appear_vec3 wo, float uc, float u1, float u2, ad_rec1 *r)
{
    ad_rec s;
    ad_sample(m, wo, uc, u1, u2, &s);
    r->ok = s.ok; r->wi = s.wi; r->pdf = s.pdf; r->flags = s.flags;
    r->f = m->bsdf ? appear_spectrum_avg(s.f) : s.f.v[0];
    r->weight = m->bsdf ? appear_spectrum_avg(s.weight) : s.weight.v[0];
}

/* micro-flake media: the projected area sigma(w) (reciprocity is sigma-weighted); else 1 */
static inline float ad_sigma(ad_model *m, appear_vec3 w)
{
    if (m->family == AD_FIBER) return appear_fiber_sigma(&m->fiber, w);
    if (m->family == AD_SGGX_SPECULAR || m->family == AD_SGGX_DIFFUSE)
        return appear_sggx_sigma(&m->sggx, w);
    return 1.0f;
}
static inline int ad_has_sigma(const ad_model *m)
{
    return m->family == AD_FIBER || m->family == AD_SGGX_SPECULAR || m->family == AD_SGGX_DIFFUSE;
}

/* ---- tests/check.h callbacks ---------------------------------------------- */
static inline appear_vec3 ad_v(check_vec3 v)
{
    return appear_vec3_make((float)v.x, (float)v.y, (float)v.z);
}
static inline check_vec3 ad_cv(appear_vec3 v) { return check_vec3_make(v.x, v.y, v.z); }
static inline double ad_cb_eval(void *c, check_vec3 wo, check_vec3 wi)
{
    return ad_eval1((ad_model *)c, ad_v(wo), ad_v(wi));
}
static inline double ad_cb_pdf(void *c, check_vec3 wo, check_vec3 wi)
{
    return ad_pdf((ad_model *)c, ad_v(wo), ad_v(wi));
}
static inline int ad_cb_sample(void *c, check_vec3 wo, double uc, double u1, double u2,
                               check_sample *s)
{
    ad_rec1 r;
    ad_sample1((ad_model *)c, ad_v(wo), (float)uc, (float)u1, (float)u2, &r);
    s->wi = ad_cv(r.wi); s->f = r.f; s->pdf = r.pdf; s->weight = r.weight;
    s->delta = (r.flags & APPEAR_LOBE_SPECULAR) != 0;
    return r.ok;
}
static inline double ad_cb_sigma(void *c, check_vec3 w) { return ad_sigma((ad_model *)c, ad_v(w)); }
static inline check_model ad_check_model(ad_model *m)
{
    check_model cm;
    memset(&cm, 0, sizeof cm);
    cm.name = m->name; cm.ctx = m; cm.is_bsdf = m->bsdf; cm.eta = m->eta;
    cm.eval_is_estimate = m->stochastic_eval;
    cm.eval = ad_cb_eval; cm.pdf = ad_cb_pdf; cm.sample = ad_cb_sample;
    if (ad_has_sigma(m)) cm.sigma = ad_cb_sigma;
    return cm;
}

#endif
