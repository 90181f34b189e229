/* bench/bench.h - the benchmark harness every model's bench reuses.
 *
 * Each bench file bench/bench_<name>.c defines `void bench_<name>(void)`
 * (the Makefile collects them with grep '^void bench_'). A row measures one
 * function: draw the inputs BEFORE timing into arrays, write a loop function
 * `static void run_x(void *ctx)` that calls the function on all n inputs and
 * folds every result into a local accumulator stored to b_sink at the end
 * (defeats dead-code elimination), then
 *
 *     double ns = b_time(run_x, &ctx, n);          // median ns per call
 *     b_row("ggx", "sample_visible (caps)", ns, max_err, "note");
 *
 * b_row prints one table line and appends to bench/out/bench_<build>.csv,
 * where <build> is the compile configuration (O2, O3native). max_err < 0
 * means "not measured". Compare implementations only inside one run.
 *
 * Latency (bench/bench_latency.c, group `latency`): each call's input is
 * derived from the previous call's output, the function behind a
 * non-inlined wrapper. b_time / b_time_latency_pair time such a
 * dependent-chain loop (the pair: appear and its baseline in alternation,
 * the order swapped every other run; median of the per-pair ratios).
 * Row filter: `./build/bench_O2 latency hg` runs only the latency rows
 * whose name contains "hg" (main.c: an argument that names no bench group
 * is a row filter; `--filter=WORD` or APPEAR_BENCH_FILTER=WORD for a word
 * that is also a group name, e.g. ward). b_filter_match(name) tells a
 * bench whether to run a row (1 when no filter is set). A filtered run
 * writes bench/out/bench_<build>_filtered.csv, not the full run's CSV.
 */
#ifndef APPEAR_BENCH_H
#define APPEAR_BENCH_H
#include "../appear.h"
#include <math.h>
#include <stdint.h>

extern volatile float b_sink;
double b_time(void (*fn)(void *ctx), void *ctx, long n_items); /* median ns per item over several runs */
/* a and b timed in alternation: medians *ta, *tb; returns the median of the per-pair ratios ta / tb */
double b_time_pair(void (*fa)(void *ctx), void *ca, void (*fb)(void *ctx), void *cb, long n_items, double *ta,
                   double *tb);
void   b_row(const char *group, const char *name, double ns, double max_err, const char *note);
void   b_note(const char *fmt, ...);                            /* free text line in the output */
int    b_quick(void);                                           /* 1 under APPEAR_BENCH_QUICK=1 */
/* a and b alternated (order swapped every other run): medians *ta, *tb;
   returns the median of the per-pair ratios ta / tb */
double b_time_latency_pair(void (*fa)(void *ctx), void *ca, void (*fb)(void *ctx), void *cb, long n_calls,
                           double *ta, double *tb);
void   b_add_filter(const char *substring);  /* row filter (any of up to 8 substrings) */
int    b_filter_match(const char *name);      /* 1: run this row (no filter, or a substring matches) */

/* Latency chains over a pair of directions (bench_layered.c, bench_openpbr.c): each call's wo and
   wi come from the previous call's output. b_chain_next(w, a, side): a rotation of w by a, on the
   side given (+1 above the surface, -1 below). B_CHAIN_RUN(name, ctx_t, n, wi_side, body...)
   defines `static void name(void *vc)`: n calls of body, which reads c (a ctx_t * whose u[i][0],
   u[i][1] drive the chain), wo, wi and i, and sets float v (folded into b_sink, and into the next
   wo); wi_side, an expression in c and i, puts the next wi above (1.0f) or below (-1.0f). */
static inline appear_vec3 b_chain_next(appear_vec3 w, float a, float side)
{
    float c = 0.25f + 0.7f * a, s = sqrtf(1.0f - c * c), p = 6.2831853f * a + w.x;
    return appear_vec3_make(s * cosf(p), s * sinf(p), side * c);
}
#define B_CHAIN_RUN(name, ctx_t, n, wi_side, ...)                                                  \
    static void name(void *vc)                                                                     \
    {                                                                                              \
        ctx_t *c = (ctx_t *)vc;                                                                    \
        appear_vec3 wo = appear_vec3_make(0.6f, 0.0f, 0.8f), wi = appear_vec3_make(0.0f, 0.6f, 0.8f); \
        float acc = 0.0f;                                                                          \
        long i;                                                                                    \
        for (i = 0; i < (n); ++i) {                                                                \
            float v;                                                                               \
            __VA_ARGS__;                                                                           \
            acc += v;                                                                              \
            wo = b_chain_next(wo, c->u[i][0] + v * 1e-30f, 1.0f);                                  \
            wi = b_chain_next(wi, c->u[i][1], (wi_side));                                          \
        }                                                                                          \
        b_sink = acc;                                                                              \
    }

typedef struct { uint64_t s; } b_rng;
b_rng  b_rng_make(uint64_t seed);
double b_rand(b_rng *r);   /* [0,1), 53 bits */
float  b_randf(b_rng *r);  /* [0,1) */
appear_vec3 b_rand_dir(b_rng *r);
appear_vec3 b_rand_hemi(b_rng *r); /* upper hemisphere, uniform */

#endif
