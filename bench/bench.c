/* bench/bench.c - see bench.h */
#define _POSIX_C_SOURCE 199309L
#include "bench.h"
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#ifndef BENCH_BUILD
#define BENCH_BUILD "unknown"
#endif

volatile float b_sink;
static FILE *g_csv;

int b_quick(void) { const char *q = getenv("APPEAR_BENCH_QUICK"); return q && q[0] == '1'; }

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e9 + ts.tv_nsec;
}

static int dcmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

double b_time(void (*fn)(void *ctx), void *ctx, long n_items)
{
    enum { RUNS = 9 };
    double t[RUNS];
    int r, runs = b_quick() ? 3 : RUNS;
    fn(ctx); /* warm up caches and branch predictors */
    for (r = 0; r < runs; ++r) {
        double t0 = now_ns();
        fn(ctx);
        t[r] = (now_ns() - t0) / (double)n_items;
    }
    qsort(t, (size_t)runs, sizeof(double), dcmp);
    return t[runs / 2];
}

void b_row(const char *group, const char *name, double ns, double max_err, const char *note)
{
    char err[32];
    if (max_err >= 0) snprintf(err, sizeof err, "%.2e", max_err); else snprintf(err, sizeof err, "-");
    printf("%-10s %-44s %9.2f ns %10.1f M/s  err %-9s %s\n", group, name, ns, 1e3 / ns, err, note ? note : "");
    fflush(stdout);
    if (!g_csv) {
        char path[128];
        mkdir("bench/out", 0777);
        snprintf(path, sizeof path, "bench/out/bench_%s.csv", BENCH_BUILD);
        g_csv = fopen(path, "w");
        if (g_csv) fprintf(g_csv, "build,group,name,ns_per_call,max_err,note\n");
    }
    if (g_csv) { fprintf(g_csv, "%s,%s,\"%s\",%.4f,%.4g,\"%s\"\n", BENCH_BUILD, group, name, ns, max_err, note ? note : ""); fflush(g_csv); }
}

void b_note(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    printf("# ");
    vprintf(fmt, ap);
    printf("\n");
    va_end(ap);
}

b_rng b_rng_make(uint64_t seed) { b_rng r; r.s = seed * 0x9E3779B97F4A7C15ull + 1; return r; }
static uint64_t next64(b_rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
double b_rand(b_rng *r) { return (double)(next64(r) >> 11) * (1.0 / 9007199254740992.0); }
float b_randf(b_rng *r) { return (float)(next64(r) >> 40) * (1.0f / 16777216.0f); }
appear_vec3 b_rand_dir(b_rng *r)
{
    double z = 1.0 - 2.0 * b_rand(r), p = 6.283185307179586 * b_rand(r), s = sqrt(fmax(0.0, 1.0 - z * z));
    return appear_vec3_make((float)(s * cos(p)), (float)(s * sin(p)), (float)z);
}
appear_vec3 b_rand_hemi(b_rng *r)
{
    appear_vec3 v = b_rand_dir(r);
    v.z = fabsf(v.z);
    return v;
}
