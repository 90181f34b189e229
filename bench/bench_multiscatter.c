/* bench/bench_multiscatter.c - speed against energy error: single
   scattering, albedo-scaling compensation, Heitz 2016 random walk.
   GGX conductor with F = 1 and a lossless GGX dielectric (eta 1.5); error =
   |directional albedo - 1| at the inputs' wo (white furnace), estimated by
   the mean sample weight (R + e^2 T for the dielectric) over the timed inputs. */
#include "bench.h"
#include <math.h>
#include <stdio.h>

enum { MS_N = 4096 };
typedef struct {
    appear_conductor c;
    appear_dielectric d;
    appear_vec3 wo[MS_N], wi[MS_N];
    float u[MS_N][3];
} ms_ctx;
static ms_ctx ms;

static void run_ss_eval(void *p) { ms_ctx *c = (ms_ctx *)p; float a = 0; int i; for (i = 0; i < MS_N; ++i) a += appear_conductor_eval(&c->c, c->wo[i], c->wi[i]).v[0]; b_sink = a; }
static void run_comp_eval(void *p) { ms_ctx *c = (ms_ctx *)p; float a = 0; int i; for (i = 0; i < MS_N; ++i) a += appear_conductor_comp_eval(&c->c, c->wo[i], c->wi[i]).v[0]; b_sink = a; }
static void run_ms_eval(void *p) { ms_ctx *c = (ms_ctx *)p; float a = 0; int i; appear_rng r = appear_rng_make(1); for (i = 0; i < MS_N; ++i) a += appear_conductor_ms_eval(&c->c, c->wo[i], c->wi[i], &r).v[0]; b_sink = a; }
static void run_ss_sample(void *p) { ms_ctx *c = (ms_ctx *)p; float a = 0; int i; appear_bsdf_sample s; for (i = 0; i < MS_N; ++i) { if (appear_conductor_sample(&c->c, c->wo[i], c->u[i][0], c->u[i][1], c->u[i][2], &s)) a += s.weight.v[0]; } b_sink = a; }
static void run_comp_sample(void *p) { ms_ctx *c = (ms_ctx *)p; float a = 0; int i; appear_bsdf_sample s; for (i = 0; i < MS_N; ++i) { if (appear_conductor_comp_sample(&c->c, c->wo[i], c->u[i][0], c->u[i][1], c->u[i][2], &s)) a += s.weight.v[0]; } b_sink = a; }
static void run_ms_sample(void *p) { ms_ctx *c = (ms_ctx *)p; float a = 0; int i; appear_bsdf_sample s; appear_rng r = appear_rng_make(2); for (i = 0; i < MS_N; ++i) { if (appear_conductor_ms_sample(&c->c, c->wo[i], &r, &s)) a += s.weight.v[0]; } b_sink = a; }
static void run_dss_sample(void *p) { ms_ctx *c = (ms_ctx *)p; float a = 0; int i; appear_bsdf_sample s; for (i = 0; i < MS_N; ++i) { if (appear_dielectric_sample(&c->d, c->wo[i], c->u[i][0], c->u[i][1], c->u[i][2], &s)) a += s.weight.v[0]; } b_sink = a; }
static void run_dcomp_sample(void *p) { ms_ctx *c = (ms_ctx *)p; float a = 0; int i; appear_bsdf_sample s; for (i = 0; i < MS_N; ++i) { if (appear_dielectric_comp_sample(&c->d, c->wo[i], c->u[i][0], c->u[i][1], c->u[i][2], &s)) a += s.weight.v[0]; } b_sink = a; }
static void run_dms_sample(void *p) { ms_ctx *c = (ms_ctx *)p; float a = 0; int i; appear_bsdf_sample s; appear_rng r = appear_rng_make(3); for (i = 0; i < MS_N; ++i) { if (appear_dielectric_ms_sample(&c->d, c->wo[i], &r, &s)) a += s.weight.v[0]; } b_sink = a; }
static void run_dms_eval(void *p) { ms_ctx *c = (ms_ctx *)p; float a = 0; int i; appear_rng r = appear_rng_make(4); for (i = 0; i < MS_N; ++i) a += appear_dielectric_ms_eval(&c->d, c->wo[i], c->wi[i], &r).v[0]; b_sink = a; }

/* furnace error by the mean flux weight of kind k (0 single, 1 compensated, 2 walk) over reps x MS_N samples */
static double ms_err(int diel, int k, int reps)
{
    b_rng r = b_rng_make(99);
    appear_rng ar = appear_rng_make(5);
    double sum = 0;
    long n = 0;
    int rep, i;
    for (rep = 0; rep < reps; ++rep)
        for (i = 0; i < MS_N; ++i, ++n) {
            appear_bsdf_sample s;
            int ok;
            float u0 = b_randf(&r), u1 = b_randf(&r), u2 = b_randf(&r);
            if (!diel) ok = k == 0 ? appear_conductor_sample(&ms.c, ms.wo[i], u0, u1, u2, &s)
                          : k == 1 ? appear_conductor_comp_sample(&ms.c, ms.wo[i], u0, u1, u2, &s)
                                   : appear_conductor_ms_sample(&ms.c, ms.wo[i], &ar, &s);
            else ok = k == 0 ? appear_dielectric_sample(&ms.d, ms.wo[i], u0, u1, u2, &s)
                    : k == 1 ? appear_dielectric_comp_sample(&ms.d, ms.wo[i], u0, u1, u2, &s)
                             : appear_dielectric_ms_sample(&ms.d, ms.wo[i], &ar, &s);
            if (ok) sum += s.weight.v[0] * ((s.flags & APPEAR_LOBE_TRANSMISSION) ? s.eta * s.eta : 1.0f);
        }
    return fabs(sum / n - 1);
}

void bench_multiscatter(void)
{
    b_rng r = b_rng_make(7);
    int i, reps = b_quick() ? 2 : 16;
    appear_microfacet mf = appear_microfacet_make(APPEAR_GGX, 1.0f, 1.0f, APPEAR_SAMPLE_VISIBLE);
    char note[160];
    ms.c = appear_conductor_make_f82(mf, appear_spectrum_splat(1.0f), appear_spectrum_splat(1.0f));
    ms.d = appear_dielectric_make(mf, 1.5f);
    for (i = 0; i < MS_N; ++i) {
        ms.wo[i] = b_rand_hemi(&r);
        ms.wi[i] = b_rand_hemi(&r);
        ms.u[i][0] = b_randf(&r); ms.u[i][1] = b_randf(&r); ms.u[i][2] = b_randf(&r);
    }
    b_note("multiscatter: GGX alpha 1, wo uniform on the hemisphere; err = mean |albedo - 1| (furnace, F = 1 / lossless), MC error ~%.0e",
           1.0 / sqrt((double)reps * MS_N));
    sprintf(note, "err: furnace; walk: <= %d bounces", APPEAR_MS_MAX_BOUNCES);
    b_row("multiscatter", "conductor eval single scattering", b_time(run_ss_eval, &ms, MS_N), ms_err(0, 0, reps), note);
    b_row("multiscatter", "conductor eval compensated", b_time(run_comp_eval, &ms, MS_N), ms_err(0, 1, reps), note);
    b_row("multiscatter", "conductor eval random walk (1 estimate = 2 walks)", b_time(run_ms_eval, &ms, MS_N), ms_err(0, 2, reps), note);
    b_row("multiscatter", "conductor sample single scattering", b_time(run_ss_sample, &ms, MS_N), ms_err(0, 0, reps), note);
    b_row("multiscatter", "conductor sample compensated", b_time(run_comp_sample, &ms, MS_N), ms_err(0, 1, reps), note);
    b_row("multiscatter", "conductor sample random walk", b_time(run_ms_sample, &ms, MS_N), ms_err(0, 2, reps), note);
    b_row("multiscatter", "dielectric sample single scattering", b_time(run_dss_sample, &ms, MS_N), ms_err(1, 0, reps), note);
    b_row("multiscatter", "dielectric sample compensated", b_time(run_dcomp_sample, &ms, MS_N), ms_err(1, 1, reps), note);
    b_row("multiscatter", "dielectric sample random walk", b_time(run_dms_sample, &ms, MS_N), ms_err(1, 2, reps), note);
    b_row("multiscatter", "dielectric eval random walk (1 estimate = 2 walks)", b_time(run_dms_eval, &ms, MS_N), -1, "");
}
