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
 */
#ifndef APPEAR_BENCH_H
#define APPEAR_BENCH_H
#include "../appear.h"
#include <stdint.h>

extern volatile float b_sink;
double b_time(void (*fn)(void *ctx), void *ctx, long n_items); /* median ns per item over several runs */
/* a and b timed in alternation: medians *ta, *tb; returns the median of the per-pair ratios ta / tb */
double b_time_pair(void (*fa)(void *ctx), void *ca, void (*fb)(void *ctx), void *cb, long n_items, double *ta,
                   double *tb);
void   b_row(const char *group, const char *name, double ns, double max_err, const char *note);
void   b_note(const char *fmt, ...);                            /* free text line in the output */
int    b_quick(void);                                           /* 1 under APPEAR_BENCH_QUICK=1 */

typedef struct { uint64_t s; } b_rng;
b_rng  b_rng_make(uint64_t seed);
double b_rand(b_rng *r);   /* [0,1), 53 bits */
float  b_randf(b_rng *r);  /* [0,1) */
appear_vec3 b_rand_dir(b_rng *r);
appear_vec3 b_rand_hemi(b_rng *r); /* upper hemisphere, uniform */

#endif
