/* tests/test_batch.c - the structure-of-arrays entry points (SECTION batch
   of appear.h) against their scalar twins: every output element must be
   BIT-identical to what the scalar function returns for the same inputs
   (memcmp of the float bits), over ordinary and adversarial inputs (NaN,
   Inf, denormals, +-0, unnormalised and zero directions, u = 0 or 1, out of
   range) and over a grid of model parameters that includes the limits
   (alpha -> 0 and smooth, anisotropic, |g| = 1, eta = 1, invalid).
   Array lengths are odd (not a multiple of any vector width) so that the
   vectoriser's remainder loop is exercised too. */
#include "harness.h"
#include <stdlib.h>
#include <string.h>

#define S_ APPEAR_SPECTRUM_SAMPLES

typedef struct {
    int n;
    float *wo_x, *wo_y, *wo_z, *wi_x, *wi_y, *wi_z, *uc, *u1, *u2, *d;
    float *o_x, *o_y, *o_z, *o_p, *o_w;   /* batch outputs; o_w planar S_*n */
    unsigned *o_fl; int *o_sc;
} tb_arrays;

static float *tb_alloc(int n) { return (float *)calloc((size_t)n, sizeof(float)); }

/* inputs: 3/4 ordinary (unit directions, u in [0,1)), 1/4 adversarial */
static void tb_make(tb_arrays *a, int n, uint64_t seed)
{
    h_rng r = h_rng_make(seed);
    int i;
    a->n = n;
    a->wo_x = tb_alloc(n); a->wo_y = tb_alloc(n); a->wo_z = tb_alloc(n);
    a->wi_x = tb_alloc(n); a->wi_y = tb_alloc(n); a->wi_z = tb_alloc(n);
    a->uc = tb_alloc(n); a->u1 = tb_alloc(n); a->u2 = tb_alloc(n); a->d = tb_alloc(n);
    a->o_x = tb_alloc(n); a->o_y = tb_alloc(n); a->o_z = tb_alloc(n); a->o_p = tb_alloc(n);
    a->o_w = tb_alloc(S_ * n);
    a->o_fl = (unsigned *)calloc((size_t)n, sizeof(unsigned)); a->o_sc = (int *)calloc((size_t)n, sizeof(int));
    for (i = 0; i < n; ++i) {
        int adv = h_rand(&r) < 0.25;
        appear_vec3 wo = adv ? h_adv_dir(&r) : h_rand_dir(&r);
        appear_vec3 wi = adv ? h_adv_dir(&r) : h_rand_dir(&r);
        a->wo_x[i] = wo.x; a->wo_y[i] = wo.y; a->wo_z[i] = wo.z;
        a->wi_x[i] = wi.x; a->wi_y[i] = wi.y; a->wi_z[i] = wi.z;
        a->uc[i] = adv ? h_adv_u(&r) : h_randf(&r);
        a->u1[i] = adv ? h_adv_u(&r) : h_randf(&r);
        a->u2[i] = adv ? h_adv_u(&r) : h_randf(&r);
        a->d[i] = adv ? h_adv_float(&r) : (float)(3.0 * h_rand(&r));
    }
}
static void tb_free(tb_arrays *a)
{
    free(a->wo_x); free(a->wo_y); free(a->wo_z); free(a->wi_x); free(a->wi_y); free(a->wi_z);
    free(a->uc); free(a->u1); free(a->u2); free(a->d);
    free(a->o_x); free(a->o_y); free(a->o_z); free(a->o_p); free(a->o_w); free(a->o_fl); free(a->o_sc);
}

static int tb_same(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

/* counts mismatches of one element; reports the first of each case */
static long tb_bad;
static void tb_cmp(const char *what, int i, float got, float want)
{
    if (!tb_same(got, want)) {
        if (tb_bad == 0) h_fail("%s: element %d: batch %.9g != scalar %.9g", what, i, got, want);
        ++tb_bad;
    }
}
/* nb: the n the batch call was given (planar stride of the weight) */
static void tb_cmp_bsdf(const char *what, const tb_arrays *a, int nb, int i, const appear_bsdf_record *s)
{
    int k;
    tb_cmp(what, i, a->o_x[i], s->wi.x); tb_cmp(what, i, a->o_y[i], s->wi.y); tb_cmp(what, i, a->o_z[i], s->wi.z);
    tb_cmp(what, i, a->o_p[i], s->pdf);
    for (k = 0; k < S_; ++k) tb_cmp(what, i, a->o_w[k * nb + i], s->weight.v[k]);
    if (a->o_fl[i] != s->flags) { if (tb_bad == 0) h_fail("%s: element %d: flags %u != %u", what, i, a->o_fl[i], s->flags); ++tb_bad; }
}
#define TB_WO(a, i) appear_vec3_make((a)->wo_x[i], (a)->wo_y[i], (a)->wo_z[i])
#define TB_WI(a, i) appear_vec3_make((a)->wi_x[i], (a)->wi_y[i], (a)->wi_z[i])

static int tb_n(void) { return (int)h_n(100003); }

void suite_batch(void)
{
    tb_arrays a;
    int i, n = tb_n(), p;
    tb_make(&a, n, 7);

    h_case("batch: sincos_2pi_batch == appear_sincos_2pi");
    tb_bad = 0;
    {   /* u over a wide range with specials, not only [0,1) */
        h_rng r = h_rng_make(3);
        for (i = 0; i < n; ++i) a.d[i] = (i & 3) == 0 ? h_adv_float(&r) : (float)(8.0 * h_rand(&r) - 4.0);
        appear_sincos_2pi_batch(a.d, a.o_x, a.o_y, n);
        for (i = 0; i < n; ++i) { float s, c; appear_sincos_2pi(a.d[i], &s, &c);
            tb_cmp("sincos s", i, a.o_x[i], s); tb_cmp("sincos c", i, a.o_y[i], c); }
    }

    h_case("batch: lambert_sample_batch == appear_lambert_sample");
    tb_bad = 0;
    {
        appear_lambert m[2];
        m[0] = appear_lambert_make(appear_spectrum_rgb(0.2f, 0.5f, 0.9f));
        m[1] = appear_lambert_make(appear_spectrum_splat(-1.0f)); /* invalid */
        for (p = 0; p < 2; ++p) {
            appear_lambert_sample_batch(&m[p], a.wo_x, a.wo_y, a.wo_z, a.u1, a.u2, a.o_x, a.o_y, a.o_z, a.o_p, a.o_w, a.o_fl, n);
            for (i = 0; i < n; ++i) { appear_bsdf_record s;
                appear_lambert_sample(&m[p], TB_WO(&a, i), 0.0f, a.u1[i], a.u2[i], &s); tb_cmp_bsdf("lambert", &a, n, i, &s); }
        }
    }

    /* a model's eval, pdf and (uc-free) sample batches against its scalar calls, bit for bit */
#define TB_EVAL_PDF_SAMPLE_U2(model, M)                                                                       \
    do {                                                                                                      \
        appear_##model##_eval_batch(&(M), a.wo_x, a.wo_y, a.wo_z, a.wi_x, a.wi_y, a.wi_z, a.o_w, n);          \
        appear_##model##_pdf_batch(&(M), a.wo_x, a.wo_y, a.wo_z, a.wi_x, a.wi_y, a.wi_z, a.o_p, n);           \
        for (i = 0; i < n; ++i) { int k; appear_spectrum f = appear_##model##_eval(&(M), TB_WO(&a, i), TB_WI(&a, i)); \
            for (k = 0; k < S_; ++k) tb_cmp(#model " eval", i, a.o_w[k * n + i], f.v[k]);                 \
            tb_cmp(#model " pdf", i, a.o_p[i], appear_##model##_pdf(&(M), TB_WO(&a, i), TB_WI(&a, i))); }   \
        appear_##model##_sample_batch(&(M), a.wo_x, a.wo_y, a.wo_z, a.u1, a.u2, a.o_x, a.o_y, a.o_z, a.o_p, \
                                      a.o_w, a.o_fl, n);                                                      \
        for (i = 0; i < n; ++i) { appear_bsdf_record s;                                                       \
            appear_##model##_sample(&(M), TB_WO(&a, i), 0.0f, a.u1[i], a.u2[i], &s);                          \
            tb_cmp_bsdf(#model, &a, n, i, &s); }                                                              \
    } while (0)
    h_case("batch: eon_eval_batch, eon_pdf_batch, eon_sample_batch == appear_eon_eval, _pdf, _sample");
    tb_bad = 0;
    {
        appear_eon m[4];
        m[0] = appear_eon_make(appear_spectrum_rgb(0.2f, 0.5f, 0.9f), 0.7f);
        m[1] = appear_eon_make_sampled(appear_spectrum_splat(1.0f), 1.0f, APPEAR_EON_SAMPLE_COSINE);
        m[2] = appear_eon_make(appear_spectrum_splat(0.6f), 0.0f);
        m[3] = appear_eon_make(appear_spectrum_splat(0.5f), 1.5f); /* invalid */
        for (p = 0; p < 4; ++p) TB_EVAL_PDF_SAMPLE_U2(eon, m[p]);
    }

    h_case("batch: sheen_eval_batch, sheen_pdf_batch, sheen_sample_batch == appear_sheen_eval, _pdf, _sample");
    tb_bad = 0;
    {
        appear_sheen m[3];
        m[0] = appear_sheen_make(appear_spectrum_rgb(0.9f, 0.6f, 0.3f), 0.4f);
        m[1] = appear_sheen_make(appear_spectrum_splat(1.0f), 0.005f);
        m[2] = appear_sheen_make(appear_spectrum_splat(0.5f), 0.0f); /* invalid */
        for (p = 0; p < 3; ++p) TB_EVAL_PDF_SAMPLE_U2(sheen, m[p]);
    }

    h_case("batch: hg_sample_batch, hg_eval_batch == appear_hg_sample, appear_hg_eval");
    tb_bad = 0;
    {
        const float gs[] = { 0.0f, 0.3f, -0.7f, 0.999f, -0.99999f, 1.0f, -1.0f, 1.5f };
        for (p = 0; p < (int)(sizeof gs / sizeof gs[0]); ++p) {
            appear_hg_sample_batch_g(gs[p], a.wo_x, a.wo_y, a.wo_z, a.u1, a.u2, a.o_x, a.o_y, a.o_z, a.o_p, n);
            for (i = 0; i < n; ++i) { appear_phase_record s;
                appear_hg_sample_g(gs[p], TB_WO(&a, i), a.u1[i], a.u2[i], &s);
                tb_cmp("hg sample", i, a.o_x[i], s.wi.x); tb_cmp("hg sample", i, a.o_y[i], s.wi.y);
                tb_cmp("hg sample", i, a.o_z[i], s.wi.z); tb_cmp("hg sample pdf", i, a.o_p[i], s.pdf); }
            {   /* both forms of the core (lanes = 1: what vectorising builds run), whatever
                   APPEAR_BATCH_LANES this build has; private (appear__hg_sample_xyz) on purpose:
                   the public batch call runs only this build's form */
                int lanes;
                for (lanes = 0; lanes < 2; ++lanes) for (i = 0; i < n; ++i) {
                    appear_phase_record s; float x, y, z, q;
                    appear__hg_sample_xyz(lanes, appear__hg_sample_ok(gs[p], a.wo_x[i], a.wo_y[i], a.wo_z[i], a.u1[i], a.u2[i]),
                                          gs[p], a.wo_x[i], a.wo_y[i], a.wo_z[i], a.u1[i], a.u2[i], &x, &y, &z, &q);
                    appear_hg_sample_g(gs[p], TB_WO(&a, i), a.u1[i], a.u2[i], &s);
                    tb_cmp("hg sample core", i, x, s.wi.x); tb_cmp("hg sample core", i, y, s.wi.y);
                    tb_cmp("hg sample core", i, z, s.wi.z); tb_cmp("hg sample core pdf", i, q, s.pdf);
                    /* and the sampler's pdf is exactly hg_eval at the returned direction */
                    if (s.flags & APPEAR_LOBE_GLOSSY) tb_cmp("hg sample pdf == eval", i, s.pdf, appear_hg_eval_g(gs[p], TB_WO(&a, i), s.wi));
                }
            }
            appear_hg_eval_batch_g(gs[p], a.wo_x, a.wo_y, a.wo_z, a.wi_x, a.wi_y, a.wi_z, a.o_p, n);
            for (i = 0; i < n; ++i) tb_cmp("hg eval", i, a.o_p[i], appear_hg_eval_g(gs[p], TB_WO(&a, i), TB_WI(&a, i)));
            {   /* the model forms (appear_hg_make) are the g forms */
                appear_hg hm = appear_hg_make(gs[p]);
                appear_hg_eval_batch(&hm, a.wo_x, a.wo_y, a.wo_z, a.wi_x, a.wi_y, a.wi_z, a.o_p, n);
                for (i = 0; i < n; ++i) tb_cmp("hg eval (model)", i, a.o_p[i], appear_hg_eval(&hm, TB_WO(&a, i), TB_WI(&a, i)));
                appear_hg_sample_batch(&hm, a.wo_x, a.wo_y, a.wo_z, a.u1, a.u2, a.o_x, a.o_y, a.o_z, a.o_p, n);
                for (i = 0; i < n; ++i) { appear_phase_record s;
                    appear_hg_sample(&hm, TB_WO(&a, i), a.u1[i], a.u2[i], &s);
                    tb_cmp("hg sample (model)", i, a.o_x[i], s.wi.x); tb_cmp("hg sample (model) pdf", i, a.o_p[i], s.pdf);
                    tb_cmp("hg pdf (model) == pdf_g", i, appear_hg_pdf(&hm, TB_WO(&a, i), TB_WI(&a, i)),
                           appear_hg_pdf_g(gs[p], TB_WO(&a, i), TB_WI(&a, i))); }
            }
        }
    }

#ifndef APPEAR_NO_MICROFACET
    {
        /* alpha pairs: ordinary, anisotropic, tiny, smooth, out of range, NaN */
        const float al[][2] = { { 0.3f, 0.3f }, { 0.05f, 0.6f }, { 1.0f, 1.0f }, { 1e-4f, 1e-4f }, { 0.0f, 0.0f },
                                { 2.5f, 0.1f }, { -1.0f, 0.3f }, { 1e-30f, 0.5f } };
        const int na = (int)(sizeof al / sizeof al[0]);
        float nan = 0.0f; nan = nan / nan;

        h_case("batch: ggx_sample_visible_batch (branch-free twin) == appear_ggx_sample_visible");
        tb_bad = 0;
        for (p = 0; p <= na; ++p) {
            float ax = p < na ? al[p][0] : nan, ay = p < na ? al[p][1] : 0.3f;
            appear_ggx_sample_visible_batch(ax, ay, a.wo_x, a.wo_y, a.wo_z, a.u1, a.u2, a.o_x, a.o_y, a.o_z, n);
            for (i = 0; i < n; ++i) { appear_vec3 m = appear_ggx_sample_visible(ax, ay, TB_WO(&a, i), a.u1[i], a.u2[i]);
                tb_cmp("ggx vis x", i, a.o_x[i], m.x); tb_cmp("ggx vis y", i, a.o_y[i], m.y); tb_cmp("ggx vis z", i, a.o_z[i], m.z); }
        }
        H_CHECK(tb_bad == 0, "ggx_sample_visible_batch: %ld mismatching values", tb_bad);

        h_case("batch: beckmann_sample_visible_batch == appear_beckmann_sample_visible");
        tb_bad = 0;
        for (p = 0; p < na; p += 2) {
            int nn = n / 8; /* the Newton solve is slow; a subset */
            appear_beckmann_sample_visible_batch(al[p][0], al[p][1], a.wo_x, a.wo_y, a.wo_z, a.u1, a.u2, a.o_x, a.o_y, a.o_z, nn);
            for (i = 0; i < nn; ++i) { appear_vec3 m = appear_beckmann_sample_visible(al[p][0], al[p][1], TB_WO(&a, i), a.u1[i], a.u2[i]);
                tb_cmp("beckmann vis x", i, a.o_x[i], m.x); tb_cmp("beckmann vis y", i, a.o_y[i], m.y); tb_cmp("beckmann vis z", i, a.o_z[i], m.z); }
        }

        h_case("batch: conductor and dielectric sample/eval/pdf batches == scalar");
        tb_bad = 0;
        for (p = 0; p < na; p += 1) {
            int type = p & 1 ? APPEAR_BECKMANN : APPEAR_GGX;
            int samp = p == 2 ? APPEAR_SAMPLE_BOUNDED : p == 5 || p == 3 ? APPEAR_SAMPLE_FULL_D : APPEAR_SAMPLE_VISIBLE;
            int nn = type == APPEAR_BECKMANN ? n / 8 : n;
            appear_microfacet d = appear_microfacet_make(type, al[p][0], al[p][1], samp);
            appear_conductor c = appear_conductor_make(d, appear_spectrum_rgb(0.2f, 0.9f, 1.1f), appear_spectrum_rgb(3.9f, 2.4f, 2.2f));
            const float etas[] = { 1.5f, 1.0f, 1.0f / 1.33f };
            int e;
            appear_conductor_sample_batch(&c, a.wo_x, a.wo_y, a.wo_z, a.uc, a.u1, a.u2, a.o_x, a.o_y, a.o_z, a.o_p, a.o_w, a.o_fl, nn);
            for (i = 0; i < nn; ++i) { appear_bsdf_record s;
                appear_conductor_sample(&c, TB_WO(&a, i), a.uc[i], a.u1[i], a.u2[i], &s); tb_cmp_bsdf("conductor sample", &a, nn, i, &s); }
            appear_conductor_eval_batch(&c, a.wo_x, a.wo_y, a.wo_z, a.wi_x, a.wi_y, a.wi_z, a.o_w, nn);
            appear_conductor_pdf_batch(&c, a.wo_x, a.wo_y, a.wo_z, a.wi_x, a.wi_y, a.wi_z, a.o_p, nn);
            for (i = 0; i < nn; ++i) { int k; appear_spectrum f = appear_conductor_eval(&c, TB_WO(&a, i), TB_WI(&a, i));
                for (k = 0; k < S_; ++k) tb_cmp("conductor eval", i, a.o_w[k * nn + i], f.v[k]);
                tb_cmp("conductor pdf", i, a.o_p[i], appear_conductor_pdf(&c, TB_WO(&a, i), TB_WI(&a, i))); }
            /* both forms of the eval/pdf loops (lanes = 1: branch-free, what vectorising
               builds run; 0: scalar style), whatever APPEAR_BATCH_LANES this build has;
               complex-IOR, F82 and constant (F0) Fresnel; private (appear__*_batch_loop) on
               purpose: the public batch calls run only this build's form */
            {
                int lanes, f82;
                for (f82 = 0; f82 < 3; ++f82) for (lanes = 0; lanes < 2; ++lanes) {
                    appear_spectrum f0 = appear_spectrum_rgb(0.9f, 0.6f, 0.3f);
                    appear_conductor cc =
                        f82 == 2 ? appear_conductor_make_reflectance(d, f0)
                        : f82    ? appear_conductor_make_f82(d, f0, appear_spectrum_rgb(0.8f, 1.0f, 0.5f))
                                 : c;
                    appear__conductor_batch_loop(lanes, cc.d.type, cc.d.sampling, cc.fresnel, 1, &cc, a.wo_x, a.wo_y, a.wo_z, a.wi_x, a.wi_y, a.wi_z, a.o_w, nn);
                    appear__conductor_batch_loop(lanes, cc.d.type, cc.d.sampling, cc.fresnel, 0, &cc, a.wo_x, a.wo_y, a.wo_z, a.wi_x, a.wi_y, a.wi_z, a.o_p, nn);
                    for (i = 0; i < nn; ++i) { int k; appear_spectrum f = appear_conductor_eval(&cc, TB_WO(&a, i), TB_WI(&a, i));
                        for (k = 0; k < S_; ++k) tb_cmp(lanes ? "conductor eval (lanes)" : "conductor eval (no lanes)", i, a.o_w[k * nn + i], f.v[k]);
                        tb_cmp(lanes ? "conductor pdf (lanes)" : "conductor pdf (no lanes)", i, a.o_p[i], appear_conductor_pdf(&cc, TB_WO(&a, i), TB_WI(&a, i))); }
                }
                for (e = 0; e < 3; ++e) for (lanes = 0; lanes < 2; ++lanes) {
                    appear_dielectric m = appear_dielectric_make(appear_microfacet_make(type, al[p][0], al[p][1], p == 3 ? APPEAR_SAMPLE_FULL_D : APPEAR_SAMPLE_VISIBLE), etas[e]);
                    appear__dielectric_batch_loop(lanes, m.d.type, 1, &m, a.wo_x, a.wo_y, a.wo_z, a.wi_x, a.wi_y, a.wi_z, a.o_w, nn);
                    appear__dielectric_batch_loop(lanes, m.d.type, 0, &m, a.wo_x, a.wo_y, a.wo_z, a.wi_x, a.wi_y, a.wi_z, a.o_p, nn);
                    for (i = 0; i < nn; ++i) { int k; appear_spectrum f = appear_dielectric_eval(&m, TB_WO(&a, i), TB_WI(&a, i));
                        for (k = 0; k < S_; ++k) tb_cmp(lanes ? "dielectric eval (lanes)" : "dielectric eval (no lanes)", i, a.o_w[k * nn + i], f.v[k]);
                        tb_cmp(lanes ? "dielectric pdf (lanes)" : "dielectric pdf (no lanes)", i, a.o_p[i], appear_dielectric_pdf(&m, TB_WO(&a, i), TB_WI(&a, i))); }
                }
            }
            for (e = 0; e < 3; ++e) {
                appear_dielectric m = appear_dielectric_make(appear_microfacet_make(type, al[p][0], al[p][1], APPEAR_SAMPLE_VISIBLE), etas[e]);
                appear_dielectric_sample_batch(&m, a.wo_x, a.wo_y, a.wo_z, a.uc, a.u1, a.u2, a.o_x, a.o_y, a.o_z, a.o_p, a.o_w, a.o_fl, nn);
                for (i = 0; i < nn; ++i) { appear_bsdf_record s;
                    appear_dielectric_sample(&m, TB_WO(&a, i), a.uc[i], a.u1[i], a.u2[i], &s); tb_cmp_bsdf("dielectric sample", &a, nn, i, &s); }
                appear_dielectric_eval_batch(&m, a.wo_x, a.wo_y, a.wo_z, a.wi_x, a.wi_y, a.wi_z, a.o_w, nn);
                appear_dielectric_pdf_batch(&m, a.wo_x, a.wo_y, a.wo_z, a.wi_x, a.wi_y, a.wi_z, a.o_p, nn);
                for (i = 0; i < nn; ++i) { int k; appear_spectrum f = appear_dielectric_eval(&m, TB_WO(&a, i), TB_WI(&a, i));
                    for (k = 0; k < S_; ++k) tb_cmp("dielectric eval", i, a.o_w[k * nn + i], f.v[k]);
                    tb_cmp("dielectric pdf", i, a.o_p[i], appear_dielectric_pdf(&m, TB_WO(&a, i), TB_WI(&a, i))); }
            }
        }
    }
#endif

#ifndef APPEAR_NO_WARD
    h_case("batch: ward_sample_batch == appear_ward_sample");
    tb_bad = 0;
    {
        const float al[][2] = { { 0.2f, 0.2f }, { 0.05f, 0.5f }, { 1e-5f, 1e-5f }, { -1.0f, 0.2f } };
        int v;
        for (p = 0; p < 4; ++p) for (v = 0; v < 3; ++v) {
            appear_ward m = appear_ward_make(appear_spectrum_rgb(0.1f, 0.2f, 0.3f), appear_spectrum_splat(0.5f), al[p][0], al[p][1], (appear_ward_variant)v);
            appear_ward_sample_batch(&m, a.wo_x, a.wo_y, a.wo_z, a.uc, a.u1, a.u2, a.o_x, a.o_y, a.o_z, a.o_p, a.o_w, a.o_fl, n);
            for (i = 0; i < n; ++i) { appear_bsdf_record s;
                appear_ward_sample(&m, TB_WO(&a, i), a.uc[i], a.u1[i], a.u2[i], &s); tb_cmp_bsdf("ward sample", &a, n, i, &s); }
            /* the branch-free form (lanes = 1), whatever APPEAR_BATCH_LANES is here: private
               (appear__ward_sample_xyz, its weight from appear__ward_f1) on purpose */
            for (i = 0; i < n; ++i) {
                appear_bsdf_record s; float x, y, z, pd, l, w; int mi, k; unsigned fl;
                appear__ward_sample_xyz(1, &m, a.wo_x[i], a.wo_y[i], a.wo_z[i], a.uc[i], a.u1[i], a.u2[i], &x, &y, &z, &pd, &l, &w, &mi, &fl);
                appear_ward_sample(&m, TB_WO(&a, i), a.uc[i], a.u1[i], a.u2[i], &s);
                tb_cmp("ward lanes x", i, x, s.wi.x); tb_cmp("ward lanes y", i, y, s.wi.y); tb_cmp("ward lanes z", i, z, s.wi.z);
                tb_cmp("ward lanes pdf", i, pd, s.pdf);
                for (k = 0; k < S_; ++k)
                    tb_cmp("ward lanes weight", i, appear__cos_weight_m(APPEAR__LANES, appear__ward_f1(1, mi, m.rho_d_pi.v[k], m.rho_s.v[k], l), w,
                                                                       pd > 0.0f ? pd : 1.0f), s.weight.v[k]);
                if (fl != s.flags) { if (!tb_bad) h_fail("ward lanes flags %d: %u != %u", i, fl, s.flags); ++tb_bad; }
            }
        }
    }
#endif

#ifndef APPEAR_NO_MEDIA
    h_case("batch: homogeneous_sample_batch == appear_homogeneous_sample");
    tb_bad = 0;
    {
        const float sg[][3] = { { 1.0f, 1.0f, 1.0f }, { 0.5f, 2.0f, 8.0f }, { 0.0f, 1.0f, 1e30f }, { -1.0f, 1.0f, 1.0f } };
        for (p = 0; p < 4; ++p) {
            appear_spectrum st = appear_spectrum_splat(sg[p][0]);
            int k;
            for (k = 0; k < S_; ++k) st.v[k] = sg[p][k < 3 ? k : 2];
            appear_homogeneous_sample_batch(st, a.d, a.uc, a.u1, a.o_x, a.o_sc, a.o_p, a.o_w, n);
            for (i = 0; i < n; ++i) { appear_medium_sample s;
                appear_homogeneous_sample(st, a.d[i], a.uc[i], a.u1[i], &s);
                tb_cmp("homogeneous t", i, a.o_x[i], s.t); tb_cmp("homogeneous pdf", i, a.o_p[i], s.pdf);
                for (k = 0; k < S_; ++k) tb_cmp("homogeneous weight", i, a.o_w[k * n + i], s.weight.v[k]);
                if (a.o_sc[i] != s.scattered) { if (!tb_bad) h_fail("homogeneous scattered %d: %d != %d", i, a.o_sc[i], s.scattered); ++tb_bad; } }
        }
    }
#endif
    tb_free(&a);
}
