/* tests/battery.c - see battery.h */
#include "battery.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define BT_PI 3.14159265358979323846

/* ------------------------------------------------------------------------ */
/* Instances and directions                                                  */
/* ------------------------------------------------------------------------ */

typedef struct {
    const bt_row *row;
    ad_model m;
    int ai;         /* alpha index (0 without a sweep) */
    char label[96]; /* "" or " alpha (ax, ay)" */
} bt_inst;

static int bt_n_inst(const bt_row *r) { return r->n_alpha > 0 ? r->n_alpha : 1; }
static int bt_n_wo(const bt_row *r) { return r->n_wo > 0 ? r->n_wo : r->n_cos; }

static appear_vec3 bt_unit_d(double x, double y, double z)
{
    double l = sqrt(x * x + y * y + z * z);
    return appear_vec3_make((float)(x / l), (float)(y / l), (float)(z / l));
}
static appear_vec3 bt_wo(const bt_row *r, int ai, int k)
{
    appear_vec3 w;
    if (r->n_wo > 0)
        w = bt_unit_d(r->wo[k][0], r->wo[k][1], r->wo[k][2]);
    else {
        double c = r->cos[k], s = sqrt(fmax(0.0, 1.0 - c * c));
        w = appear_vec3_make((float)(s * cos(r->phi)), (float)(s * sin(r->phi)), (float)c);
    }
    if (r->flip == BT_FLIP_PARITY && ((ai + k) & 1)) w.z = -w.z;
    return w;
}
static const char *bt_wo_str(appear_vec3 w)
{
    static char buf[4][64];
    static int i;
    i = (i + 1) & 3;
    snprintf(buf[i], sizeof buf[i], "wo (%.6g %.6g %.6g)", w.x, w.y, w.z);
    return buf[i];
}

/* builds instance ai of the row; 0 (and a failure line if report) when make() rejects it */
static int bt_make(const bt_row *r, int ai, bt_inst *in, int report)
{
    ad_params p = r->p;
    in->row = r;
    in->ai = ai;
    in->label[0] = 0;
    if (r->n_alpha > 0) {
        p.alpha[0] = r->alpha[ai][0];
        p.alpha[1] = r->alpha[ai][1];
        snprintf(in->label, sizeof in->label, " alpha (%g, %g)", p.alpha[0], p.alpha[1]);
    }
    if (!p.seed) p.seed = (unsigned)(r->seed * 2654435761u + 7u);
    ad_make(&in->m, r->family, &p);
    snprintf(in->m.name, sizeof in->m.name, "%s%s", r->name, in->label);
    if (!in->m.valid && report) h_fail("%s: make() rejected the parameters", in->m.name);
    return in->m.valid;
}

static uint64_t bt_seed(const bt_row *r, int check, int ai, int k)
{
    uint64_t s = r->seed;
    const char *c;
    if (!s)
        for (s = 1469598103934665603ull, c = r->name; *c; ++c)
            s = (s ^ (unsigned char)*c) * 1099511628211ull;
    return s + 1000003ull * (uint64_t)check + 7919ull * (uint64_t)ai + 104729ull * (uint64_t)k;
}

static int bt_side(appear_vec3 wo, appear_vec3 wi) { return wi.z * wo.z > 0 ? 1 : -1; }
static double bt_rel(double got, double ref)
{
    double d = fabs(got - ref);
    return d == 0 ? 0 : d / fmax(fabs(ref), 1e-30);
}
static int bt_spec_ok(appear_spectrum s)
{
    int k, ok = 1;
    for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) ok &= H_OK_VALUE(s.v[k]);
    return ok;
}
static int bt_spec_zero(appear_spectrum s)
{
    int k, z = 1;
    for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) z &= s.v[k] == 0.0f;
    return z;
}

/* micro-flakes: wo mirrored about the axis of the largest eigenvalue */
static appear_vec3 bt_flake_mirror(const ad_model *m, appear_vec3 wo)
{
    const appear_sggx *s = &m->sggx;
    appear_vec3 n = s->lam[0] >= s->lam[1] && s->lam[0] >= s->lam[2]
                        ? s->e.x
                        : (s->lam[1] >= s->lam[2] ? s->e.y : s->e.z);
    appear_vec3 r = appear_sub(appear_scale(n, 2.0f * appear_dot(wo, n)), wo);
    return bt_unit_d(r.x, r.y, r.z);
}
static appear_vec3 bt_axis(const bt_inst *in, int axis, appear_vec3 wo)
{
    const bt_row *r = in->row;
    switch (axis) {
    case BT_AXIS_MIRROR: return appear_vec3_make(-wo.x, -wo.y, wo.z);
    case BT_AXIS_FORWARD: return appear_neg(wo);
    case BT_AXIS_BACKWARD: return wo;
    case BT_AXIS_LOBE:
        if (in->m.family == AD_SGGX_SPECULAR || in->m.family == AD_SGGX_DIFFUSE)
            return bt_flake_mirror(&in->m, wo);
        return in->m.bsdf ? appear_vec3_make(-wo.x, -wo.y, wo.z) : appear_neg(wo);
    case BT_AXIS_V: return bt_unit_d(r->v[0], r->v[1], r->v[2]);
    default: return appear_vec3_make(0, 0, 1);
    }
}

/* ------------------------------------------------------------------------ */
/* The sampler at one wo, one side, for chi2 and quadrature; the magnified   */
/* domain for narrow lobes                                                   */
/* ------------------------------------------------------------------------ */

typedef struct {
    ad_model *m; /* a model at wo; or NULL and the sampler fs, fp, fc */
    appear_vec3 wo;
    int side; /* +1 keep wi on wo's side only, -1 the other side only, 0 both */
    h_sample_fn fs;
    h_dir_fn fp;
    void *fc;
    int mag; /* magnified projected-disc domain around bz */
    double K, bx[3], by[3], bz[3];
} bt_dom;

static int bt_raw_sample(bt_dom *d, float uc, float u1, float u2, appear_vec3 *w)
{
    ad_rec r;
    if (!d->m) return d->fs(d->fc, uc, u1, u2, w);
    ad_sample(d->m, d->wo, uc, u1, u2, &r);
    if (!r.ok || (r.flags & APPEAR_LOBE_SPECULAR)) return 0;
    if (d->side && bt_side(d->wo, r.wi) != d->side) return 0;
    *w = r.wi;
    return 1;
}
static double bt_raw_pdf(bt_dom *d, appear_vec3 w)
{
    if (!d->m) return d->fp(d->fc, w);
    if (d->side && bt_side(d->wo, w) != d->side) return 0;
    return ad_pdf(d->m, d->wo, w);
}
/* Magnified domain: a direction w near the axis bz, with projected-disc
   coordinates (a, b) = (w.bx, w.by), maps to v = (K a, K b, sqrt(1 - K^2
   (a^2 + b^2))). dw = da db / (w.bz), dv = K^2 da db / v.z, so
   p_v = p_w v.z / (K^2 w.bz). A lobe of width ~1/K fills the hemisphere,
   so float directions resolve it however narrow it is. */
static int bt_dom_sample(void *ctx, float uc, float u1, float u2, appear_vec3 *out)
{
    bt_dom *d = (bt_dom *)ctx;
    appear_vec3 w;
    double a, b, c, r2;
    if (!bt_raw_sample(d, uc, u1, u2, &w)) return 0;
    if (!d->mag) {
        *out = w;
        return 1;
    }
    a = w.x * d->bx[0] + w.y * d->bx[1] + w.z * d->bx[2];
    b = w.x * d->by[0] + w.y * d->by[1] + w.z * d->by[2];
    c = w.x * d->bz[0] + w.y * d->bz[1] + w.z * d->bz[2];
    r2 = d->K * d->K * (a * a + b * b);
    if (c <= 0 || r2 >= 1) return 0;
    *out = appear_vec3_make((float)(d->K * a), (float)(d->K * b), (float)sqrt(1 - r2));
    return 1;
}
static double bt_dom_pdf(void *ctx, appear_vec3 v)
{
    bt_dom *d = (bt_dom *)ctx;
    double a, b, c, x[3];
    int i;
    if (!d->mag) return bt_raw_pdf(d, v);
    if (v.z <= 0) return 0;
    a = v.x / d->K;
    b = v.y / d->K;
    c = sqrt(fmax(0.0, 1 - a * a - b * b));
    for (i = 0; i < 3; ++i) x[i] = a * d->bx[i] + b * d->by[i] + c * d->bz[i];
    return bt_raw_pdf(d,
                      appear_normalize(appear_vec3_make((float)x[0], (float)x[1], (float)x[2]))) *
           v.z / (d->K * d->K * c);
}
static int bt_dcmp(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return a < b ? -1 : a > b;
}
/* Chooses the domain from a pilot run: the axis is the mean sampled
   direction; when half of the samples lie within 0.15 rad of it, the lobe
   is magnified so that the median radius maps to projected radius 0.35
   (the harness' quadrature cannot resolve a peak much narrower than its
   cells). Returns the number of pilot successes. */
static long bt_setup_domain(bt_dom *d, long pilot)
{
    h_rng r = h_rng_make(777);
    double mean[3] = { 0, 0, 0 }, l, *rad;
    long i, ok = 0;
    appear_vec3 w;
    d->mag = 0;
    rad = (double *)malloc(sizeof(double) * (size_t)pilot);
    for (i = 0; i < pilot; ++i) {
        float uc = h_randf(&r), u1 = h_randf(&r), u2 = h_randf(&r);
        if (bt_raw_sample(d, uc, u1, u2, &w)) {
            mean[0] += w.x;
            mean[1] += w.y;
            mean[2] += w.z;
            ++ok;
        }
    }
    l = sqrt(mean[0] * mean[0] + mean[1] * mean[1] + mean[2] * mean[2]);
    if (ok < 100 || !(l > 0)) {
        free(rad);
        return ok;
    }
    for (i = 0; i < 3; ++i) d->bz[i] = mean[i] / l;
    { /* Duff et al. 2017 */
        double *n = d->bz, sg = n[2] >= 0 ? 1.0 : -1.0, a = -1.0 / (sg + n[2]), b = n[0] * n[1] * a;
        d->bx[0] = 1.0 + sg * n[0] * n[0] * a;
        d->bx[1] = sg * b;
        d->bx[2] = -sg * n[0];
        d->by[0] = b;
        d->by[1] = sg + n[1] * n[1] * a;
        d->by[2] = -n[1];
    }
    r = h_rng_make(777);
    ok = 0;
    for (i = 0; i < pilot; ++i) {
        float uc = h_randf(&r), u1 = h_randf(&r), u2 = h_randf(&r);
        if (bt_raw_sample(d, uc, u1, u2, &w)) {
            double c = w.x * d->bz[0] + w.y * d->bz[1] + w.z * d->bz[2];
            rad[ok++] = c > 0 ? sqrt(fmax(0.0, 1 - c * c)) : 2.0;
        }
    }
    { /* the median radius */
        double q;
        qsort(rad, (size_t)ok, sizeof(double), bt_dcmp);
        q = rad[(long)(0.5 * (double)(ok - 1))];
        if (q < 0.15) {
            d->mag = 1;
            d->K = 0.35 / fmax(q, 1e-9);
        }
    }
    free(rad);
    return ok;
}

/* ------------------------------------------------------------------------ */
/* Checks                                                                    */
/* ------------------------------------------------------------------------ */

static int bt_quick_skip(int every, long *count)
{
    if (!h_quick() || every <= 1) return 0;
    return ((*count)++ % every) != 0;
}

/* ---- consistency ---- */
static void bt_do_consistency(bt_inst *in, appear_vec3 wo, uint64_t seed, long *bad, long *checked)
{
    const bt_cons *c = &in->row->cons;
    ad_model *m = &in->m;
    h_rng r = h_rng_make(seed);
    long i, n = h_n(c->n), nok = 0;
    int k;
    for (i = 0; i < n; ++i) {
        ad_rec s;
        appear_spectrum fe;
        float pe;
        double cs;
        int good = 1, side, est0;
        char why[160];
        float uc, u1, u2;
        if (c->random_wo) wo = h_rand_dir(&r);
        uc = h_randf(&r);
        u1 = h_randf(&r);
        u2 = h_randf(&r);
        ad_sample(m, wo, uc, u1, u2, &s);
        if (!s.ok) continue;
        ++nok;
        /* every sample's lobe is in the model's lobe set (TERMINATE_SECONDARY: a sample's own
           flag, never a model's) */
        if (s.flags & ~ad_flags(m) & ~(unsigned)APPEAR_SAMPLE_TERMINATE_SECONDARY) {
            if (++*bad <= 3)
                h_fail("%s%s %s: sample flags %#x outside the model's (appear_*_flags) %#x",
                       in->row->name, in->label, bt_wo_str(wo), s.flags, ad_flags(m));
            continue;
        }
        if (s.flags & APPEAR_LOBE_SPECULAR) continue;
        ++*checked;
        why[0] = 0;
        side = bt_side(wo, s.wi);
        cs = m->bsdf ? fabs(s.wi.z) : 1.0;
        /* a pdf estimate of 0 (layered): the record's f must be 0 too */
        est0 = c->pdf_estimate && s.pdf == 0.0f;
        pe = c->pdf_estimate ? s.pdf : ad_pdf(m, wo, s.wi);
        /* unit to 1e-4 (tighter than appear_is_unit's 1e-3: wo is unit here) */
        if (!(fabs(appear_dot(s.wi, s.wi) - 1.0) < 1e-4) || !(s.pdf > 0 || est0) || !h_finite(s.pdf)) {
            good = 0;
            snprintf(why, sizeof why, "|wi|^2 - 1 = %.3g or pdf %g", appear_dot(s.wi, s.wi) - 1.0, s.pdf);
        } else if (m->bsdf && !((s.flags & APPEAR_LOBE_REFLECTION)
                                    ? side > 0
                                    : (s.flags & APPEAR_LOBE_TRANSMISSION) && side < 0)) {
            good = 0;
            snprintf(why, sizeof why, "flags %u but wi on %s side", s.flags,
                     side > 0 ? "wo's" : "the other");
        } else if (!m->bsdf && !s.flags) {
            good = 0;
            snprintf(why, sizeof why, "no lobe flag");
        } else if (c->pdf_exact ? s.pdf != pe : bt_rel(s.pdf, pe) > c->tol) {
            good = 0;
            snprintf(why, sizeof why, "pdf %.9g vs pdf() %.9g: rel %.3g > tol %.3g", s.pdf, pe,
                     bt_rel(s.pdf, pe), c->pdf_exact ? 0.0 : c->tol);
        }
        if (good && !c->no_f && !m->stochastic_eval) {
            /* a dispersive refraction keeps the hero (channel 0) and zeroes the secondaries */
            int nk = (s.flags & APPEAR_SAMPLE_TERMINATE_SECONDARY) ? 1 : APPEAR_SPECTRUM_SAMPLES;
            fe = ad_eval(m, wo, s.wi);
            for (k = 0; k < nk && good; ++k) {
                double we = pe > 0 ? fe.v[k] * cs / pe : 0;
                if (bt_rel(s.f.v[k], fe.v[k]) > c->tol) {
                    good = 0;
                    snprintf(why, sizeof why,
                             "channel %d: f %.9g vs eval %.9g: rel %.3g > tol %.3g", k, s.f.v[k],
                             fe.v[k], bt_rel(s.f.v[k], fe.v[k]), c->tol);
                } else if (bt_rel(s.weight.v[k], we) > c->tol) {
                    good = 0;
                    snprintf(
                        why, sizeof why,
                        "channel %d: weight %.9g vs eval |cos| / pdf() %.9g: rel %.3g > tol %.3g",
                        k, s.weight.v[k], we, bt_rel(s.weight.v[k], we), c->tol);
                }
            }
        }
        for (k = 0; k < APPEAR_SPECTRUM_SAMPLES && good; ++k) {
            double wr = est0 ? 0.0 : s.f.v[k] * cs / s.pdf;
            if (est0 && !(s.f.v[k] == 0.0f && H_OK_VALUE(s.weight.v[k]))) {
                good = 0;
                snprintf(why, sizeof why, "channel %d: pdf estimate 0 but f %.9g, weight %.9g", k, s.f.v[k],
                         s.weight.v[k]);
            } else if (!est0 && (!h_finite(s.f.v[k]) || bt_rel(s.weight.v[k], wr) > c->tol)) {
                good = 0;
                snprintf(why, sizeof why,
                         "channel %d: weight %.9g vs f |cos| / pdf %.9g: rel %.3g > tol %.3g", k,
                         s.weight.v[k], wr, bt_rel(s.weight.v[k], wr), c->tol);
            }
            if (good && c->unit_weight && (s.weight.v[k] != 1.0f || s.f.v[k] != s.pdf)) {
                good = 0;
                snprintf(why, sizeof why,
                         "weight %.9g (must be 1), f %.9g pdf %.9g (must be equal)", s.weight.v[k],
                         s.f.v[k], s.pdf);
            }
        }
        if (!good && ++*bad <= 3)
            h_fail("%s%s %s: wi (%.6g %.6g %.6g): %s", in->row->name, in->label, bt_wo_str(wo),
                   s.wi.x, s.wi.y, s.wi.z, why);
    }
    if (c->min_ok > 0 && !(nok >= c->min_ok * n)) {
        ++*bad;
        h_fail("%s%s %s: %ld of %ld samples succeeded, fewer than %.3g of them", in->row->name,
               in->label, bt_wo_str(wo), nok, n, c->min_ok);
    }
}

/* ---- chi2 ---- */
static long g_chi2_count, g_pdf_count;
/* runs sp (sample, pdf, ctx: d's) in the domain of a pilot run */
static void bt_chi2_auto(bt_dom *d, h_chi2_spec *sp)
{
    if (bt_setup_domain(d, 4000) < 100 && bt_setup_domain(d, 100000) < 100) {
        /* a lobe with probability < 1e-3 (e.g. transmission that is almost
           all totally reflected): too few samples for a chi-square */
        h_measure("chi2 skipped", "%s: lobe probability < 1e-3", sp->name);
        return;
    }
    /* not magnified: bands around the lobe's mean direction, so that a lobe
       hugging the horizon (grazing transmission) lies at the pole, where the
       expected-count quadrature resolves it, not inside one band */
    sp->axis = d->mag ? appear_vec3_make(0, 0, 1)
                      : appear_vec3_make((float)d->bz[0], (float)d->bz[1], (float)d->bz[2]);
    sp->zmin = d->mag ? 1e-12 : 0.0; /* magnified: the hemisphere v.z > 0 */
    h_chi2(sp);
}
void bt_chi2_domain(const char *name, h_sample_fn sample, h_dir_fn pdf, void *ctx, long n, int nz,
                    int nphi, uint64_t seed, int quick_every)
{
    static long count;
    bt_dom d;
    h_chi2_spec sp;
    if (bt_quick_skip(quick_every, &count)) return;
    memset(&d, 0, sizeof d);
    memset(&sp, 0, sizeof sp);
    d.fs = sample;
    d.fp = pdf;
    d.fc = ctx;
    sp.name = name;
    sp.sample = bt_dom_sample;
    sp.pdf = bt_dom_pdf;
    sp.ctx = &d;
    sp.n_z = nz;
    sp.n_phi = nphi;
    sp.n_samples = n;
    sp.seed = seed;
    bt_chi2_auto(&d, &sp);
}
static void bt_do_chi2_side(bt_inst *in, appear_vec3 wo, int k, uint64_t seed, int side)
{
    const bt_chi2 *c = &in->row->chi2;
    bt_dom d;
    h_chi2_spec sp;
    char name[200];
    memset(&d, 0, sizeof d);
    memset(&sp, 0, sizeof sp);
    if (bt_quick_skip(c->quick_every, &g_chi2_count)) return;
    d.m = &in->m;
    d.wo = wo;
    d.side = side;
    snprintf(name, sizeof name, "%s%s wo%d%s", in->row->name, in->label, k,
             side > 0   ? " R"
             : side < 0 ? " T"
                        : "");
    sp.name = name;
    sp.sample = bt_dom_sample;
    sp.pdf = bt_dom_pdf;
    sp.ctx = &d;
    sp.n_z = c->nz;
    sp.n_phi = c->nphi;
    sp.n_samples = c->n;
    sp.seed = c->seed ? c->seed : seed;
    if (c->axis == BT_AXIS_AUTO)
        bt_chi2_auto(&d, &sp);
    else {
        sp.axis = bt_axis(in, c->axis, wo);
        sp.zmin = c->cap > 0 ? cos(c->cap) : 0.0;
        h_chi2(&sp);
    }
}
static void bt_do_chi2(bt_inst *in, appear_vec3 wo, int k, uint64_t seed)
{
    int side = in->row->chi2.side;
    if (side != BT_SIDE_EACH) {
        bt_do_chi2_side(in, wo, k, seed, side);
        return;
    }
    bt_do_chi2_side(in, wo, k, seed, -1); /* transmission, then reflection */
    bt_do_chi2_side(in, wo, k, seed, 1);
}

/* ---- pdf integral ---- */
static double bt_pdf_fn(void *ctx, appear_vec3 w) { return bt_raw_pdf((bt_dom *)ctx, w); }
static void bt_do_pdf_side(bt_inst *in, appear_vec3 wo, uint64_t seed, long *bad, int side)
{
    const bt_pdf *c = &in->row->pdf;
    bt_dom d;
    appear_vec3 axis;
    double I;
    memset(&d, 0, sizeof d);
    if (bt_quick_skip(c->quick_every, &g_pdf_count)) return;
    d.m = &in->m;
    d.wo = wo;
    d.side = side;
    if (c->axis == BT_AXIS_AUTO) {
        bt_setup_domain(&d, 2000);
        axis = d.mag || d.bz[2] != 0
                   ? appear_vec3_make((float)d.bz[0], (float)d.bz[1], (float)d.bz[2])
                   : appear_vec3_make(0, 0, 1);
        d.mag = 0;
    } else
        axis = bt_axis(in, c->axis, wo);
    I = h_integrate_sphere(bt_pdf_fn, &d, axis, c->quad_tol);
    if (c->mode == BT_ONE) {
        if (!(fabs(I - 1.0) <= c->tol)) {
            if (++*bad <= 3)
                h_fail("%s%s %s: integral of pdf %.8f, |I - 1| > tol %.3g", in->row->name,
                       in->label, bt_wo_str(wo), I, c->tol);
        }
    } else {
        h_rng r = h_rng_make(seed);
        long i, ok = 0, n = h_n(c->n);
        double p, sigma;
        appear_vec3 w;
        for (i = 0; i < n; ++i) {
            float uc = h_randf(&r), u1 = h_randf(&r), u2 = h_randf(&r);
            ok += bt_raw_sample(&d, uc, u1, u2, &w);
        }
        p = (double)ok / (double)n;
        sigma = sqrt(fmax(p * (1 - p), c->floor ? 1.0 / (double)n : 0.0) / (double)n);
        if (!(fabs(I - p) <= c->k * sigma + c->tol) || !(I <= 1.0 + c->tol)) {
            if (++*bad <= 3)
                h_fail("%s%s %s%s: integral of pdf %.6f, success rate %.6f +- %.2g: |I - rate| > "
                       "%g sigma + %.3g (or I > 1)",
                       in->row->name, in->label, bt_wo_str(wo),
                       side > 0   ? " (wo's side)"
                       : side < 0 ? " (other side)"
                                  : "",
                       I, p, sigma, c->k, c->tol);
        }
    }
}
static void bt_do_pdf(bt_inst *in, appear_vec3 wo, uint64_t seed, long *bad)
{
    int side = in->row->pdf.side;
    if (side != BT_SIDE_EACH) {
        bt_do_pdf_side(in, wo, seed, bad, side);
        return;
    }
    bt_do_pdf_side(in, wo, seed, bad, -1);
    bt_do_pdf_side(in, wo, seed, bad, 1);
}

/* ---- furnace ---- */
typedef struct {
    ad_model *m;
    appear_vec3 wo;
    int side; /* 0 both, +1 reflection, -1 transmission */
} bt_alb;
/* f |cos| (times e^2 for a transmission: the flux), channel average */
static double bt_alb_fn(void *p, appear_vec3 wi)
{
    bt_alb *a = (bt_alb *)p;
    int s = bt_side(a->wo, wi);
    double v, e;
    if (a->side && s != a->side) return 0;
    v = ad_eval1(a->m, a->wo, wi);
    if (!a->m->bsdf) return v;
    e = s < 0 && a->m->eta != 1.0f ? (a->wo.z > 0 ? a->m->eta : 1.0 / a->m->eta) : 1.0;
    return v * e * e * fabs(wi.z);
}
static double bt_albedo_quad(bt_inst *in, appear_vec3 wo, double tol, int axis)
{
    bt_alb a;
    double r;
    a.m = &in->m;
    a.wo = wo;
    a.side = 0;
    if (!in->m.bsdf) return h_integrate_sphere(bt_alb_fn, &a, bt_axis(in, axis, wo), tol);
    if (in->m.eta == 1.0f)
        return h_integrate_sphere(bt_alb_fn, &a, appear_vec3_make(-wo.x, -wo.y, wo.z), tol);
    /* refraction: reflection and transmission each with its lobe at the pole */
    a.side = 1;
    r = h_integrate_sphere(bt_alb_fn, &a, appear_vec3_make(-wo.x, -wo.y, wo.z), tol);
    a.side = -1;
    {
        double e = wo.z > 0 ? in->m.eta : 1.0 / in->m.eta, sx = -wo.x / e, sy = -wo.y / e,
               st2 = sx * sx + sy * sy;
        /* beyond the critical angle (st2 >= 1) the rough transmission lobe
           hugs the far horizon, opposite wo's azimuth: put the pole there
           (a pole at -z let the quadrature miss the whole lobe, 8e-3 of
           Beckmann alpha 2, e = 1/1.5, mu = 0.1) */
        appear_vec3 t =
            st2 < 1 ? appear_vec3_make((float)sx, (float)sy,
                                       (float)(-(wo.z > 0 ? 1 : -1) * sqrt(1 - st2)))
                    : appear_normalize(appear_vec3_make(-wo.x, -wo.y, wo.z > 0 ? -0.05f : 0.05f));
        r += h_integrate_sphere(bt_alb_fn, &a, t, tol);
    }
    return r;
}
static long g_fur_count;
static double g_fur_dev_one, g_fur_dev_ref; /* the largest |E - 1|, |mean - ref| of a row */
static void bt_do_furnace(bt_inst *in, appear_vec3 wo, uint64_t seed, long *bad)
{
    const bt_fur *c = &in->row->fur;
    double ref = 1.0;
    const char *what = "1";
    char msg[256];
    msg[0] = 0;
    if (bt_quick_skip(c->quick_every, &g_fur_count)) return;
    if (c->mode == BT_QUAD) {
        ref = bt_albedo_quad(in, wo, c->quad_tol, c->axis);
        g_fur_dev_one = fmax(g_fur_dev_one, fabs(ref - 1.0));
        what = "the quadrature of f |cos|";
        if (c->one_tol > 0 && !(fabs(ref - 1.0) <= c->one_tol)) {
            if (++*bad <= 3)
                h_fail("%s%s %s: quadrature albedo %.7f, |E - 1| > %.3g", in->row->name, in->label,
                       bt_wo_str(wo), ref, c->one_tol);
        }
        if (c->bound_quad > 0 && !(ref <= 1.0 + c->bound_quad)) {
            if (++*bad <= 3)
                h_fail("%s%s %s: quadrature albedo %.7f > 1 + %.3g", in->row->name, in->label,
                       bt_wo_str(wo), ref, c->bound_quad);
        }
    }
    if (c->n > 0) {
        check_model cm = ad_check_model(&in->m);
        check_furnace_result fr;
        int good;
        double se;
        check_furnace(&cm, ad_cv(wo), h_n(c->n), seed, &fr);
        /* check.h's standard error divides the variance by n - 1; the bound takes n */
        se = fr.n > 1 ? fr.se * sqrt((double)(fr.n - 1) / (double)fr.n) : fr.se;
        g_fur_dev_ref = fmax(g_fur_dev_ref, fabs(fr.albedo - ref));
        if (c->mode == BT_BOUND)
            good = fr.albedo <= 1.0 + c->k * se + c->abs;
        else
            good = fabs(fr.albedo - ref) <= c->k * se + c->abs + c->rel * ref;
        if (!good)
            snprintf(msg, sizeof msg,
                     "mean weight %.7f +- %.2g (%ld samples, %.3g failed) vs %s %.7f: bound %g se "
                     "+ %.3g + %.3g ref",
                     fr.albedo, se, fr.n, fr.failed, c->mode == BT_BOUND ? "at most" : what, ref,
                     c->k, c->abs, c->rel);
        if (good && c->max_w > 0 && !(fr.max_weight <= c->max_w)) {
            good = 0;
            snprintf(msg, sizeof msg, "largest weight %.7f > %.7f", fr.max_weight, c->max_w);
        }
        if (!good && ++*bad <= 3)
            h_fail("%s%s %s: %s", in->row->name, in->label, bt_wo_str(wo), msg);
    }
    if (c->uniform_k > 0) {
        /* a second form, independent of the sampler: eval |cos| on uniform directions */
        h_rng r = h_rng_make(seed + 17);
        bt_alb a;
        long i, n = h_n(c->n > 0 ? c->n : 100000);
        double s1 = 0, s2 = 0, se;
        a.m = &in->m;
        a.wo = wo;
        a.side = 0;
        for (i = 0; i < n; ++i) {
            double e = bt_alb_fn(&a, h_rand_dir(&r)) * 4.0 * BT_PI;
            s1 += e;
            s2 += e * e;
        }
        s1 /= n;
        se = sqrt(fmax(0.0, s2 / n - s1 * s1) / n);
        if (!(fabs(s1 - ref) <= c->uniform_k * se) && ++*bad <= 3)
            h_fail("%s%s %s: uniform-sphere albedo %.6f +- %.2g vs %s %.7f: beyond %g se",
                   in->row->name, in->label, bt_wo_str(wo), s1, se, what, ref, c->uniform_k);
    }
}

/* ---- reciprocity ---- */
/* the two sides of the rule: x = (n_i^2 or sigma(wo)) f(wo, wi),
   y = (n_o^2 or sigma(wi)) f(wi, wo) */
static void bt_rule(ad_model *m, appear_vec3 wo, appear_vec3 wi, double *kx, double *ky)
{
    *kx = *ky = 1.0;
    if (m->bsdf && m->eta != 1.0f && bt_side(wo, wi) < 0) {
        double no = wo.z > 0 ? 1.0 : m->eta, ni = wi.z > 0 ? 1.0 : m->eta;
        *kx = ni * ni;
        *ky = no * no;
    }
    if (ad_has_sigma(m)) {
        *kx = ad_sigma(m, wo);
        *ky = ad_sigma(m, wi);
    }
}
/* float conditioning of a refraction: h from wo + e wi carries ~1e-7/L error
   (L = |wo + e wi|, small when e ~ 1), which moves D by ~(slope/alpha^2)
   1e-7/L relative (Beckmann tails: slope ~ 4 alpha); and near the critical
   angle 1 - F ~ g = |wi.h| (or |wo.h|), whose relative error is then
   ~1e-7 / (L g): eta 1.0001 at L ~ 1e-2 gives 0.5% */
static double bt_refr_tol(const ad_model *m, appear_vec3 wo, appear_vec3 wi)
{
    double L = 1.0, gm = 1.0;
    if (bt_side(wo, wi) < 0) {
        double e = wo.z > 0 ? m->eta : 1.0 / m->eta;
        appear_vec3 hv = appear_add(wo, appear_scale(wi, (float)e)), hn;
        L = sqrt(appear_dot(hv, hv));
        hn = appear_normalize(hv);
        gm = fmin(fabs(appear_dot(wo, hn)), fabs(appear_dot(wi, hn)));
    }
    return 1e-5 / (fmin(m->ax, m->ay) * L) + 2e-7 / (L * fmax(gm, 1e-12));
}
static int bt_rec_pair(bt_inst *in, appear_vec3 wo, appear_vec3 wi, long *bad)
{
    const bt_rec *c = &in->row->rec;
    ad_model *m = &in->m;
    double kx, ky, tol = c->rel;
    int k;
    bt_rule(m, wo, wi, &kx, &ky);
    if (c->refr) tol += bt_refr_tol(m, wo, wi);
    if (c->repeats > 0) {
        double a1[APPEAR_SPECTRUM_SAMPLES] = { 0 }, a2[APPEAR_SPECTRUM_SAMPLES] = { 0 };
        double b1[APPEAR_SPECTRUM_SAMPLES] = { 0 }, b2[APPEAR_SPECTRUM_SAMPLES] = { 0 };
        long i, n = h_n(c->repeats);
        for (i = 0; i < n; ++i) {
            appear_spectrum x = ad_eval(m, wo, wi), y = ad_eval(m, wi, wo);
            for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) {
                a1[k] += x.v[k];
                a2[k] += (double)x.v[k] * x.v[k];
                b1[k] += y.v[k];
                b2[k] += (double)y.v[k] * y.v[k];
            }
        }
        for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) {
            double ma = a1[k] / n * kx, mb = b1[k] / n * ky;
            double va = (a2[k] / n - (a1[k] / n) * (a1[k] / n)) / n * kx * kx,
                   vb = (b2[k] / n - (b1[k] / n) * (b1[k] / n)) / n * ky * ky;
            if (!(fabs(ma - mb) <= c->z * sqrt(fmax(0.0, va + vb)) + tol * (ma + mb))) {
                if (++*bad <= 3)
                    h_fail("%s%s %s wi (%.6g %.6g %.6g) channel %d: mean of %ld estimates %.7g vs "
                           "reverse %.7g (se %.2g): beyond %g se + %.3g",
                           in->row->name, in->label, bt_wo_str(wo), wi.x, wi.y, wi.z, k, n, ma, mb,
                           sqrt(fmax(0.0, va + vb)), c->z, tol);
                return 0;
            }
        }
        return 1;
    }
    {
        appear_spectrum fa = ad_eval(m, wo, wi), fb = ad_eval(m, wi, wo);
        for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) {
            double x = kx * fa.v[k], y = ky * fb.v[k], d = fabs(x - y);
            if (!(d <= tol * fmin(fabs(x), fabs(y)) || d <= c->abs)) {
                if (++*bad <= 3)
                    h_fail("%s%s %s wi (%.6g %.6g %.6g) channel %d: %.9g vs reverse %.9g: rel %.3g "
                           "> %.3g (and |d| %.3g > %.3g)",
                           in->row->name, in->label, bt_wo_str(wo), wi.x, wi.y, wi.z, k, x, y,
                           d / fmax(fmin(fabs(x), fabs(y)), 1e-300), tol, d, c->abs);
                return 0;
            }
        }
    }
    return 1;
}
static void bt_do_reciprocity(bt_inst *in, appear_vec3 wo, int sampled, uint64_t seed, long *bad,
                              long *pairs)
{
    const bt_rec *c = &in->row->rec;
    h_rng r = h_rng_make(seed);
    long i, n = c->repeats > 0 ? c->n : h_n(c->n);
    for (i = 0; i < n; ++i) {
        appear_vec3 a = wo, b;
        if (sampled) {
            ad_rec s;
            float uc = h_randf(&r), u1 = h_randf(&r), u2 = h_randf(&r);
            ad_sample(&in->m, wo, uc, u1, u2, &s);
            if (!s.ok || (s.flags & APPEAR_LOBE_SPECULAR)) continue;
            b = s.wi;
        } else {
            a = h_rand_dir(&r);
            b = h_rand_dir(&r);
            if (c->pairs == BT_PAIRS_UPPER) {
                a.z = fabsf(a.z);
                b.z = fabsf(b.z);
            }
        }
        ++*pairs;
        bt_rec_pair(in, a, b, bad);
    }
}

/* ---- adversarial inputs ---- */
static void bt_do_adversarial(bt_inst *in, uint64_t seed, long *bad, long *count)
{
    ad_model *m = &in->m;
    h_rng r = h_rng_make(seed);
    long i, n = h_n(in->row->adv.n);
    for (i = 0; i < n; ++i) {
        appear_vec3 wo = h_adv_dir(&r), wi = h_adv_dir(&r);
        float uc = h_adv_u(&r), u1 = h_adv_u(&r), u2 = h_adv_u(&r);
        appear_spectrum f = ad_eval(m, wo, wi);
        float p = ad_pdf(m, wo, wi);
        ad_rec s;
        const char *why = 0;
        ad_sample(m, wo, uc, u1, u2, &s);
        ++*count;
        if (!bt_spec_ok(f))
            why = "eval not finite and >= 0";
        else if (!H_OK_VALUE(p))
            why = "pdf not finite and >= 0";
        else if (s.ok) {
            /* the diffuse SGGX record's f = pdf and the layered record's pdf (f then 0) are
               estimates that may be 0 */
            int est0 = (m->family == AD_SGGX_DIFFUSE || m->family == AD_LAYERED) && s.pdf == 0.0f &&
                       bt_spec_zero(s.f);
            if (!(h_finite(s.wi.x) && h_finite(s.wi.y) && h_finite(s.wi.z) && appear_is_unit(s.wi)))
                why = "sample: wi not a finite unit vector";
            else if (!(H_OK_VALUE(s.pdf) && (s.pdf > 0 || est0)))
                why = "sample: pdf not finite and > 0";
            else if (!(bt_spec_ok(s.f) && bt_spec_ok(s.weight)))
                why = "sample: f or weight not finite and >= 0";
            else if (!s.flags)
                why = "sample: no lobe flag";
            else if (m->bsdf && !(h_finite(s.eta) && s.eta > 0))
                why = "sample: eta not finite and > 0";
        } else if (!(s.flags == 0 && s.pdf == 0.0f && bt_spec_zero(s.weight) && bt_spec_zero(s.f)))
            why = "failed sample not clean (flags, pdf, f, weight must be 0)";
        if (why && ++*bad <= 3)
            h_fail("%s%s: wo (%g %g %g) wi (%g %g %g) u (%g %g %g): %s (f %g pdf %g; sample ok %d "
                   "wi (%g %g %g) pdf %g f %g weight %g flags %u)",
                   in->row->name, in->label, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, uc, u1, u2, why,
                   f.v[0], p, s.ok, s.wi.x, s.wi.y, s.wi.z, s.pdf, s.f.v[0], s.weight.v[0],
                   s.flags);
    }
}

/* ------------------------------------------------------------------------ */
/* A row                                                                     */
/* ------------------------------------------------------------------------ */

enum { C_CONS, C_CHI2, C_PDF, C_FUR, C_REC, C_ADV };

/* APPEAR_TEST_CHI2_ONLY=1: the chi-square rows alone (a full-length rerun of every
   chi-square row with APPEAR_TEST_SEED_OFFSET = 1, 2, 3 ...) */
static int bt_chi2_only(void)
{
    const char *e = getenv("APPEAR_TEST_CHI2_ONLY");
    return e && e[0] == '1';
}

void bt_run(const bt_row *row)
{
    int na = bt_n_inst(row), nw = bt_n_wo(row), ai, k, only = bt_chi2_only();
    bt_inst *ins = (bt_inst *)malloc(sizeof(bt_inst) * (size_t)na);
    for (ai = 0; ai < na; ++ai) bt_make(row, ai, &ins[ai], 0);
#define BT_EACH(check)                                                                             \
    for (ai = 0; ai < na; ++ai)                                                                    \
        if (!ins[ai].m.valid)                                                                      \
            h_fail("%s: make() rejected the parameters", ins[ai].m.name);                          \
        else                                                                                       \
            for (k = 0; k < nw; ++k) check
    if (!only && row->cons.n > 0) {
        long bad = 0, checked = 0;
        h_case("%s: sample/eval/pdf consistency (tol %g)", row->name, row->cons.tol);
        if (row->cons.random_wo) nw = 1;
        BT_EACH(bt_do_consistency(&ins[ai], bt_wo(row, ai, k), bt_seed(row, C_CONS, ai, k), &bad,
                                  &checked));
        nw = bt_n_wo(row);
        H_CHECK(bad == 0 && checked > 0, "%ld of %ld samples inconsistent", bad, checked);
    }
    if (row->chi2.n > 0) {
        h_case("%s: chi2 of sample against pdf", row->name);
        BT_EACH(bt_do_chi2(&ins[ai], bt_wo(row, ai, k), k, bt_seed(row, C_CHI2, ai, k)));
    }
    if (!only && row->pdf.mode) {
        long bad = 0;
        h_case("%s: pdf integrates to %s", row->name,
               row->pdf.mode == BT_ONE ? "1" : "the success rate");
        BT_EACH(bt_do_pdf(&ins[ai], bt_wo(row, ai, k), bt_seed(row, C_PDF, ai, k), &bad));
    }
    if (!only && row->fur.mode) {
        long bad = 0;
        h_case("%s: white furnace (%s)", row->name,
               row->fur.mode == BT_ONE     ? "lossless: 1"
               : row->fur.mode == BT_BOUND ? "albedo <= 1"
                                           : "albedo = quadrature of f |cos|");
        g_fur_dev_one = g_fur_dev_ref = 0;
        BT_EACH(bt_do_furnace(&ins[ai], bt_wo(row, ai, k), bt_seed(row, C_FUR, ai, k), &bad));
        if (row->fur.measure)
            h_measure("battery furnace", "%s: max |E - 1| %.3g (E %s)%s", row->name,
                      row->fur.mode == BT_QUAD ? g_fur_dev_one : g_fur_dev_ref,
                      row->fur.mode == BT_QUAD ? "by quadrature" : "by the sampler",
                      h_quick() ? ", quick mode" : "");
    }
    if (!only && row->rec.n > 0) {
        long bad = 0, pairs = 0;
        h_case("%s: reciprocity", row->name);
        if (row->rec.pairs == BT_PAIRS_SAMPLED) {
            BT_EACH(bt_do_reciprocity(&ins[ai], bt_wo(row, ai, k), 1, bt_seed(row, C_REC, ai, k),
                                      &bad, &pairs));
        } else {
            nw = 1; /* uniform pairs: once per instance */
            BT_EACH(bt_do_reciprocity(&ins[ai], appear_vec3_make(0, 0, 1), 0,
                                      bt_seed(row, C_REC, ai, 0), &bad, &pairs));
            nw = bt_n_wo(row);
        }
        H_CHECK(bad == 0 && pairs > 0, "%ld of %ld pairs break reciprocity", bad, pairs);
    }
    if (!only && row->adv.n > 0) {
        long bad = 0, count = 0;
        h_case("%s: adversarial inputs (NaN, Inf, denormals, +-0, unnormalised, grazing; u = 0, 1, "
               "out of range)",
               row->name);
        /* invalid models too: their calls must be as clean */
        for (ai = 0; ai < na; ++ai)
            bt_do_adversarial(&ins[ai], bt_seed(row, C_ADV, ai, 0), &bad, &count);
        H_CHECK(bad == 0, "%ld of %ld inputs give a bad output", bad, count);
    }
#undef BT_EACH
    free(ins);
}

void bt_run_table(const bt_row *rows, int n)
{
    int i;
    for (i = 0; i < n; ++i) bt_run(&rows[i]);
}
