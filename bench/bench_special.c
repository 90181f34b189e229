/* bench/bench_special.c - ns per call of appear.h's own special functions
   against libm, in one run, and whether a loop over each vectorises.
   For every function three loops over the same pre-drawn inputs:
     ours      the appear__ function (libm route unless APPEAR_USE_LIBM),
     ours-nv   the same loop with auto-vectorisation disabled (gcc
               optimize("no-tree-vectorize") / clang loop pragma),
     libm      the C library's float function.
   The note gives "vec x<ours-nv / ours>": a ratio well above 1 means the
   loop vectorised in this build (the Makefile builds -O2 and -O3
   -march=native -fno-math-errno; at -O2 gcc does not vectorise at all and
   sqrtf keeps its errno branch). max_err is the max relative error of ours
   against double libm on the same inputs (absolute for sincos, atan2). */
#include "bench.h"
#include <math.h>
#include <stdio.h>

#define BS_N 65536
static float bs_x[BS_N], bs_y[BS_N], bs_out[BS_N];

/* The _nv twin: an empty asm statement in the loop body stops the
   vectoriser (gcc and clang) and nothing else. (Not gcc's
   optimize("no-tree-vectorize") attribute: gcc then refuses to inline the
   appear__ functions into the loop, option mismatch, and the figure is not
   the scalar cost.) */
#if defined(__GNUC__)
#define BS_NOVEC_BODY __asm__ __volatile__("");
#else
#define BS_NOVEC_BODY
#endif
#define BS_NOVEC_ATTR

/* loops over the inputs: out[i] = expr(x[i], y[i]) (an output array, not a
   float sum: a float reduction does not vectorise without -ffast-math); BS_LOOP also makes the
   _nv twin with auto-vectorisation disabled */
#define BS_LOOPL(name, expr) \
    static void name(void *ctx) { int i; (void)ctx; \
        for (i = 0; i < BS_N; ++i) { float x = bs_x[i]; float y = bs_y[i]; (void)y; bs_out[i] = (expr); } \
        b_sink = bs_out[BS_N / 2]; }
#define BS_LOOP1(name, expr) \
    static void name(void *ctx) { int i; (void)ctx; \
        for (i = 0; i < BS_N; ++i) { float x = bs_x[i]; float y = bs_y[i]; (void)y; bs_out[i] = (expr); } \
        b_sink = bs_out[BS_N / 2]; } \
    BS_NOVEC_ATTR static void name##_nv(void *ctx) { int i; (void)ctx; \
        for (i = 0; i < BS_N; ++i) { float x = bs_x[i]; float y = bs_y[i]; (void)y; BS_NOVEC_BODY bs_out[i] = (expr); } \
        b_sink = bs_out[BS_N / 2]; }

static float bs_sc_ours(float u) { float s, c; appear_sincos_2pi(u, &s, &c); return s + c; }
static float bs_sc_libm(float u) { float a = 6.28318530717958647692f * u; return sinf(a) + cosf(a); }

BS_LOOP1(bs_sincos, bs_sc_ours(x))
BS_LOOPL(bs_sincos_l, bs_sc_libm(x))
BS_LOOP1(bs_exp, appear__exp(x))
BS_LOOPL(bs_exp_l, expf(x))
BS_LOOP1(bs_log, appear__log(x))
BS_LOOPL(bs_log_l, logf(x))
BS_LOOP1(bs_pow, appear__pow(x, y))
BS_LOOPL(bs_pow_l, powf(x, y))
BS_LOOP1(bs_erf, appear__erf(x))
BS_LOOPL(bs_erf_l, erff(x))
BS_LOOP1(bs_erfc, appear__erfc(x))
BS_LOOPL(bs_erfc_l, erfcf(x))
BS_LOOP1(bs_erfinv, appear__erfinv(x))
BS_LOOP1(bs_atan2, appear__atan2(y, x))
BS_LOOPL(bs_atan2_l, atan2f(y, x))
BS_LOOP1(bs_cbrt, appear__cbrt(x))
BS_LOOPL(bs_cbrt_l, cbrtf(x))

typedef void (*bs_fn)(void *);
typedef double (*bs_err_fn)(float x, float y);

static double bs_e_sincos(float x, float y) { float s, c; double t = 6.283185307179586 * x; (void)y;
    appear_sincos_2pi(x, &s, &c); return fmax(fabs(s - sin(t)), fabs(c - cos(t))); }
static double bs_rel(double g, double r) /* relative where r is a normal float */
{ return fabs(r) >= 1.1754943508222875e-38 ? fabs(g - r) / fabs(r) : 0.0; }
static double bs_e_exp(float x, float y) { (void)y; return bs_rel(appear__exp(x), exp((double)x)); }
static double bs_e_log(float x, float y) { (void)y; return bs_rel(appear__log(x), log((double)x)); }
static double bs_e_pow(float x, float y) { return bs_rel(appear__pow(x, y), pow((double)x, (double)y)); }
static double bs_e_erf(float x, float y) { (void)y; return bs_rel(appear__erf(x), erf((double)x)); }
static double bs_e_erfc(float x, float y) { (void)y; return bs_rel(appear__erfc(x), erfc((double)x)); }
static double bs_e_erfinv(float x, float y) { float g = appear__erfinv(x); (void)y; /* erf(g) ~ x: residual / slope */
    return fabs(erf((double)g) - x) / (1.1283791670955126 * exp(-(double)g * g)) / fmax(fabs((double)g), 1e-30); }
static double bs_e_atan2(float x, float y) { return fabs(appear__atan2(y, x) - atan2((double)y, (double)x)); }
static double bs_e_cbrt(float x, float y) { (void)y; return bs_rel(appear__cbrt(x), cbrt((double)x)); }

/* double references of the libm loops' outputs (the loop stores expr(x, y)
   in bs_out): the libm row's error, relative (absolute for sincos, whose
   loop stores sin + cos, and atan2) */
static double bs_r_sincos(float x, float y) { double t = 6.283185307179586 * x; (void)y; return sin(t) + cos(t); }
static double bs_r_exp(float x, float y) { (void)y; return exp((double)x); }
static double bs_r_log(float x, float y) { (void)y; return log((double)x); }
static double bs_r_pow(float x, float y) { return pow((double)x, (double)y); }
static double bs_r_erf(float x, float y) { (void)y; return erf((double)x); }
static double bs_r_erfc(float x, float y) { (void)y; return erfc((double)x); }
static double bs_r_atan2(float x, float y) { return atan2((double)y, (double)x); }
static double bs_r_cbrt(float x, float y) { (void)y; return cbrt((double)x); }
typedef double (*bs_ref_fn)(float x, float y);
static bs_ref_fn g_ref;
static int g_ref_abs;

static void bs_row(const char *name, bs_fn ours, bs_fn ours_nv, bs_fn libm, bs_err_fn err, const char *range)
{
    double t_o = b_time(ours, 0, BS_N), t_nv = b_time(ours_nv, 0, BS_N), t_l = -1.0, e = 0.0, e_l = -1.0;
    char note[160]; int i;
    for (i = 0; i < BS_N; ++i) { double d = err(bs_x[i], bs_y[i]); e = d > e ? d : e; }
    if (libm) {
        t_l = b_time(libm, 0, BS_N);
        for (i = 0, e_l = 0.0; g_ref && i < BS_N; ++i) {
            double r = g_ref(bs_x[i], bs_y[i]), d = g_ref_abs ? fabs(bs_out[i] - r) : bs_rel(bs_out[i], r);
            e_l = d > e_l ? d : e_l;
        }
    }
    snprintf(note, sizeof note, "%s; vec x%.1f%s; libm %.2f ns (ours %.1fx faster)", range, t_nv / t_o,
             t_nv / t_o > 1.5 ? " (vectorised)" : " (scalar)", t_l, t_l > 0 ? t_l / t_o : 0.0);
    if (!libm) snprintf(note, sizeof note, "%s; vec x%.1f%s; no libm erfinv", range, t_nv / t_o,
                        t_nv / t_o > 1.5 ? " (vectorised)" : " (scalar)");
    b_row("special", name, t_o, e, note);
    snprintf(note, sizeof note, "%s, auto-vectorisation disabled", name);
    b_row("special", note, t_nv, -1.0, "");
    if (libm) { snprintf(note, sizeof note, "%s libm", name); b_row("special", note, t_l, e_l, "libm float"); }
}

static void bs_fill(b_rng *r, double lo, double hi, double ylo, double yhi)
{
    int i;
    for (i = 0; i < BS_N; ++i) {
        bs_x[i] = (float)(lo + (hi - lo) * b_rand(r));
        bs_y[i] = (float)(ylo + (yhi - ylo) * b_rand(r));
    }
}

void bench_special(void)
{
    b_rng r = b_rng_make(42);
    int i;
    b_note("special functions: ours vs libm, %d inputs drawn before timing; "
           "'vec xR' = time with auto-vectorisation disabled / time as built", BS_N);
    bs_fill(&r, 0, 1, 0, 1);        g_ref = bs_r_sincos; g_ref_abs = 1; bs_row("sincos_2pi", bs_sincos, bs_sincos_nv, bs_sincos_l, bs_e_sincos, "u in [0,1), libm sinf+cosf");
    bs_fill(&r, -20, 5, 0, 1);      g_ref = bs_r_exp; g_ref_abs = 0; bs_row("exp", bs_exp, bs_exp_nv, bs_exp_l, bs_e_exp, "x in [-20,5]");
    bs_fill(&r, 1e-6, 10, 0, 1);    g_ref = bs_r_log; g_ref_abs = 0; bs_row("log", bs_log, bs_log_nv, bs_log_l, bs_e_log, "x in (0,10]");
    bs_fill(&r, 1e-3, 1, 0, 100);   g_ref = bs_r_pow; g_ref_abs = 0; bs_row("pow", bs_pow, bs_pow_nv, bs_pow_l, bs_e_pow, "x in (0,1], y in [0,100]");
    bs_fill(&r, -4, 4, 0, 1);       g_ref = bs_r_erf; g_ref_abs = 0; bs_row("erf", bs_erf, bs_erf_nv, bs_erf_l, bs_e_erf, "x in [-4,4]");
    bs_fill(&r, -2, 8, 0, 1);       g_ref = bs_r_erfc; g_ref_abs = 0; bs_row("erfc", bs_erfc, bs_erfc_nv, bs_erfc_l, bs_e_erfc, "x in [-2,8]");
    bs_fill(&r, -1, 1, 0, 1);       bs_row("erfinv", bs_erfinv, bs_erfinv_nv, 0, bs_e_erfinv, "x in (-1,1)");
    for (i = 0; i < BS_N; ++i) { appear_vec3 d = b_rand_dir(&r); bs_x[i] = d.x; bs_y[i] = d.y; }
    g_ref = bs_r_atan2; g_ref_abs = 1; bs_row("atan2", bs_atan2, bs_atan2_nv, bs_atan2_l, bs_e_atan2, "unit directions");
    bs_fill(&r, 0, 1000, 0, 1);     g_ref = bs_r_cbrt; g_ref_abs = 0; bs_row("cbrt", bs_cbrt, bs_cbrt_nv, bs_cbrt_l, bs_e_cbrt, "x in [0,1000]");
}
