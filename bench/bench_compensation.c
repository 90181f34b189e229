/* bench/bench_compensation.c - energy compensation (Turquin 2019 albedo
   scaling), thin-film conductor and thin dielectric: ns per call of every
   eval/pdf/sample, and the speed-against-error figure of energy
   compensation: the white-furnace albedo of a lossless (F = 1) GGX
   conductor, uncompensated vs compensated, estimated from the sample
   weights (E(mu) = mean weight, 4096 samples per mu, 16 mu values); error =
   max over mu of |1 - E(mu)| (the compensated figure includes the Monte
   Carlo noise: about 1e-2 at the grazing mu = 1/32, where 1/E amplifies
   it; bench_multiscatter.c gives the deterministic figure, ~1e-3). No
   random-walk reference (Heitz 2016) is needed: the furnace value 1 is
   the exact target for F = 1 (the random walk is benched in
   bench_multiscatter.c). */
#include "bench.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { N = 1 << 14 };
typedef struct {
    float u1[N], u2[N], uc[N], mu[N];
    appear_vec3 wo[N], wi[N];
} inputs;
static inputs *g_in;
static appear_conductor g_c;
static appear_dielectric g_d;
static appear_thinfilm_conductor g_tf;
static appear_thin_dielectric g_thin;
static appear_thinfilm g_film;

#define MS_LOOP(name, body) \
    static void name(void *ctx) { float acc = 0; int i; (void)ctx; \
        for (i = 0; i < N; ++i) { body } b_sink = acc; }
#define WO g_in->wo[i]
#define WI g_in->wi[i]

MS_LOOP(run_c_eval, acc += appear_conductor_eval(&g_c, WO, WI).v[0];)
MS_LOOP(run_c_comp_eval, acc += appear_conductor_comp_eval(&g_c, WO, WI).v[0];)
MS_LOOP(run_c_comp_pdf, acc += appear_conductor_comp_pdf(&g_c, WO, WI);)
MS_LOOP(run_c_comp_sample, appear_bsdf_record s; appear_conductor_comp_sample(&g_c, WO, g_in->uc[i], g_in->u1[i], g_in->u2[i], &s);
        acc += s.weight.v[0] + s.wi.x;)
MS_LOOP(run_c_scale, acc += appear_conductor_comp_scale(&g_c, WO).v[0];)
MS_LOOP(run_alb_c, acc += appear_conductor_albedo(APPEAR_GGX, 0.5f, g_in->mu[i]);)
MS_LOOP(run_alb_d, acc += appear_dielectric_albedo(APPEAR_GGX, 0.5f, 1.5f, g_in->mu[i]);)
MS_LOOP(run_d_comp_eval, acc += appear_dielectric_comp_eval(&g_d, WO, WI).v[0];)
MS_LOOP(run_d_comp_pdf, acc += appear_dielectric_comp_pdf(&g_d, WO, WI);)
MS_LOOP(run_d_comp_sample, appear_bsdf_record s; appear_dielectric_comp_sample(&g_d, WO, g_in->uc[i], g_in->u1[i], g_in->u2[i], &s);
        acc += s.weight.v[0] + s.wi.x;)
MS_LOOP(run_d_scale, acc += appear_dielectric_comp_scale(&g_d, WO);)
MS_LOOP(run_tf_eval, acc += appear_thinfilm_conductor_eval(&g_tf, WO, WI).v[0];)
MS_LOOP(run_tf_pdf, acc += appear_thinfilm_conductor_pdf(&g_tf, WO, WI);)
MS_LOOP(run_tf_sample, appear_bsdf_record s; appear_thinfilm_conductor_sample(&g_tf, WO, g_in->uc[i], g_in->u1[i], g_in->u2[i], &s);
        acc += s.weight.v[0] + s.wi.x;)
MS_LOOP(run_tf_airy, acc += appear_thinfilm_airy(g_in->mu[i], 550.0f, 1.33f, 300.0f, 0.2f, 3.0f);)
MS_LOOP(run_tf_rgb, acc += appear_thinfilm_rgb(g_in->mu[i], 1.33f, 300.0f, appear_spectrum_splat(0.2f), appear_spectrum_splat(3.0f)).v[1];)
MS_LOOP(run_tf_F, acc += appear_thinfilm_reflectance(&g_film, g_in->mu[i]).v[1];)
MS_LOOP(run_thin_eval, acc += appear_thin_dielectric_eval(&g_thin, WO, WI).v[0];)
MS_LOOP(run_thin_pdf, acc += appear_thin_dielectric_pdf(&g_thin, WO, WI);)
MS_LOOP(run_thin_sample, appear_bsdf_record s; appear_thin_dielectric_sample(&g_thin, WO, g_in->uc[i], g_in->u1[i], g_in->u2[i], &s);
        acc += s.weight.v[0] + s.wi.x;)

/* max over mu of |1 - E(mu)|, E = mean sample weight of a lossless conductor */
static double furnace_err(const appear_conductor *c, int comp)
{
    double worst = 0;
    int k, j;
    b_rng r = b_rng_make(77);
    for (k = 0; k < 16; ++k) {
        float mu = (k + 0.5f) / 16.0f;
        appear_vec3 wo = appear_vec3_make(sqrtf(1.0f - mu * mu), 0.0f, mu);
        double e = 0;
        int n = b_quick() ? 1024 : 4096;
        for (j = 0; j < n; ++j) {
            appear_bsdf_record s;
            int ok = comp ? appear_conductor_comp_sample(c, wo, b_randf(&r), b_randf(&r), b_randf(&r), &s)
                          : appear_conductor_sample(c, wo, b_randf(&r), b_randf(&r), b_randf(&r), &s);
            if (ok) e += s.weight.v[0];
        }
        e /= n;
        worst = fmax(worst, fabs(1.0 - e));
    }
    return worst;
}

void bench_compensation(void)
{
    b_rng r = b_rng_make(31);
    int i, k;
    static const float alphas[] = { 0.2f, 0.5f, 1.0f };
    g_in = (inputs *)malloc(sizeof(inputs));
    for (i = 0; i < N; ++i) {
        g_in->u1[i] = b_randf(&r); g_in->u2[i] = b_randf(&r); g_in->uc[i] = b_randf(&r);
        g_in->mu[i] = b_randf(&r);
        g_in->wo[i] = b_rand_hemi(&r); g_in->wi[i] = b_rand_hemi(&r);
    }
    g_d = appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, 0.5f, 0.5f, APPEAR_SAMPLE_VISIBLE), 1.5f);
    g_film = appear_thinfilm_make_rgb(1.33f, 300.0f, appear_spectrum_splat(0.2f), appear_spectrum_splat(3.0f));
    g_tf = appear_thinfilm_conductor_make(appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE), g_film);
    g_thin = appear_thin_dielectric_make(1.5f);
    b_note("multiscatter: energy compensation (albedo scaling), thin film, thin dielectric; GGX, %d inputs; "
           "err of comp rows = max_mu |1 - furnace albedo| of a lossless conductor", N);
    for (k = 0; k < 3; ++k) {
        char name[96];
        double e0, e1;
        g_c = appear_conductor_make_f82(appear_microfacet_make(APPEAR_GGX, alphas[k], alphas[k], APPEAR_SAMPLE_VISIBLE),
                                        appear_spectrum_splat(1.0f), appear_spectrum_splat(1.0f));
        e0 = furnace_err(&g_c, 0); e1 = furnace_err(&g_c, 1);
        snprintf(name, sizeof name, "conductor eval, no compensation (a=%g)", alphas[k]);
        b_row("energy", name, b_time(run_c_eval, 0, N), e0, "err = energy lost, max over mu");
        snprintf(name, sizeof name, "conductor_comp_eval (a=%g)", alphas[k]);
        b_row("energy", name, b_time(run_c_comp_eval, 0, N), e1, "err = |1 - furnace| incl. MC noise (~1e-2 at mu = 1/32)");
    }
    b_row("energy", "conductor_comp_pdf", b_time(run_c_comp_pdf, 0, N), -1, "");
    b_row("energy", "conductor_comp_sample", b_time(run_c_comp_sample, 0, N), -1, "");
    b_row("energy", "conductor_ms_scale", b_time(run_c_scale, 0, N), -1, "");
    b_row("energy", "ms_albedo_conductor (table)", b_time(run_alb_c, 0, N), -1, "32x32 bicubic (Catmull-Rom) on axes of its own");
    b_row("energy", "ms_albedo_dielectric (table)", b_time(run_alb_d, 0, N), -1, "e < 1: 24x20x21 of E / E_cond, trilinear, times its read; e >= 1: 24x20x12, bicubic in mu, alpha");
    b_row("energy", "dielectric_comp_eval", b_time(run_d_comp_eval, 0, N), -1, "");
    b_row("energy", "dielectric_comp_pdf", b_time(run_d_comp_pdf, 0, N), -1, "");
    b_row("energy", "dielectric_comp_sample", b_time(run_d_comp_sample, 0, N), -1, "");
    b_row("energy", "dielectric_ms_scale", b_time(run_d_scale, 0, N), -1, "");
    b_row("thinfilm", "thinfilm_conductor eval", b_time(run_tf_eval, 0, N), -1, "RGB mode, 300 nm, n 1.33");
    b_row("thinfilm", "thinfilm_conductor pdf", b_time(run_tf_pdf, 0, N), -1, "");
    b_row("thinfilm", "thinfilm_conductor sample", b_time(run_tf_sample, 0, N), -1, "");
    b_row("thinfilm", "thinfilm_airy (one wavelength)", b_time(run_tf_airy, 0, N), -1, "");
    b_row("thinfilm", "thinfilm_rgb", b_time(run_tf_rgb, 0, N), -1, "");
    b_row("thinfilm", "thinfilm_F (made film)", b_time(run_tf_F, 0, N), -1, "");
    b_row("thin", "thin_dielectric eval", b_time(run_thin_eval, 0, N), -1, "delta: always 0");
    b_row("thin", "thin_dielectric pdf", b_time(run_thin_pdf, 0, N), -1, "delta: always 0");
    b_row("thin", "thin_dielectric sample", b_time(run_thin_sample, 0, N), -1, "");
    free(g_in);
}
