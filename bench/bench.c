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
#if defined(BENCH_CALLGRIND)
#include <valgrind/callgrind.h>
#endif

#ifndef BENCH_BUILD
#define BENCH_BUILD "unknown"
#endif

volatile float b_sink;
static FILE *g_csv;
static const char *g_filters[8]; /* row filters (b_add_filter) */
static int g_nfilters;

int b_quick(void) { const char *q = getenv("APPEAR_BENCH_QUICK"); return q && q[0] == '1'; }

/* on-CPU time of this (single) thread: time the scheduler gives other
   processes on a shared machine is not counted (wall-clock time was, and
   made the figures depend on the machine's load) */
static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e9 + ts.tv_nsec;
}

static int dcmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* Under callgrind (the Makefile builds with -DBENCH_CALLGRIND when
   <valgrind/callgrind.h> exists and runs valgrind --tool=callgrind
   --instr-atstart=no): each b_time call runs its loop once uninstrumented
   (warm-up, lazy binding), then once instrumented between
   CALLGRIND_ZERO_STATS and CALLGRIND_DUMP_STATS_AT("bt <seq>"), so the dump
   file <seq> holds exactly the instructions of that loop. b_row finds the
   b_time call whose returned value it was given (rows often time two
   loops before printing both) and writes group,name,seq,n into
   bench/out/callgrind_<build>.csv; bench/report.py divides the dump's
   total Ir by n. Times returned under valgrind are meaningless. */
static int g_cg = -1;
#if defined(BENCH_CALLGRIND)
enum { B_REC = 64 };
static long g_seq;
static struct { double ret; long seq, n; } g_rec[B_REC];
#endif

static int under_callgrind(void)
{
#if defined(BENCH_CALLGRIND)
    if (g_cg < 0) g_cg = RUNNING_ON_VALGRIND ? 1 : 0;
#else
    g_cg = 0;
#endif
    return g_cg;
}

double b_time(void (*fn)(void *ctx), void *ctx, long n_items)
{
    enum { RUNS = 9 };
    double t[RUNS];
    int r, runs = b_quick() ? 3 : RUNS;
    fn(ctx); /* warm up caches and branch predictors */
    if (under_callgrind()) {
#if defined(BENCH_CALLGRIND)
        char label[32];
        double t0, ret;
        ++g_seq;
        snprintf(label, sizeof label, "bt %ld", g_seq);
        t0 = now_ns();
        CALLGRIND_START_INSTRUMENTATION;
        CALLGRIND_ZERO_STATS;
        fn(ctx);
        CALLGRIND_DUMP_STATS_AT(label);
        CALLGRIND_STOP_INSTRUMENTATION;
        ret = (now_ns() - t0) / (double)n_items + 1e-9 * (double)g_seq; /* unique */
        g_rec[g_seq % B_REC].ret = ret; g_rec[g_seq % B_REC].seq = g_seq; g_rec[g_seq % B_REC].n = n_items;
        return ret;
#endif
    }
    for (r = 0; r < runs; ++r) {
        double t0 = now_ns();
        fn(ctx);
        t[r] = (now_ns() - t0) / (double)n_items;
    }
    qsort(t, (size_t)runs, sizeof(double), dcmp);
    return t[runs / 2];
}

/* Two loops timed in alternation (a, b, a, b, ...), so that a change of
   machine load between them hits both: *ta, *tb are the medians of each
   (ns per item) and the return value the median of the per-pair ratios
   ta / tb, the figure to quote when comparing the two. swap: the order of
   a and b is swapped every other run (so that neither always runs second,
   after the other warmed the caches). Under callgrind: two b_time calls
   (instruction counts do not need pairing). */
static double time_pair(void (*fa)(void *ctx), void *ca, void (*fb)(void *ctx), void *cb, long n_items,
                        int max_runs, int swap, double *ta, double *tb)
{
    enum { RUNS_MAX = 21 };
    double a[RUNS_MAX], b[RUNS_MAX], q[RUNS_MAX];
    int r, runs = b_quick() ? 3 : max_runs;
    if (under_callgrind()) {
        *ta = b_time(fa, ca, n_items);
        *tb = b_time(fb, cb, n_items);
        return *ta / *tb;
    }
    fa(ca); fb(cb);
    for (r = 0; r < runs; ++r) {
        double t0, t1, t2;
        if (swap && (r & 1)) {
            t0 = now_ns(); fb(cb); t1 = now_ns(); fa(ca); t2 = now_ns();
            b[r] = (t1 - t0) / (double)n_items; a[r] = (t2 - t1) / (double)n_items;
        } else {
            t0 = now_ns(); fa(ca); t1 = now_ns(); fb(cb); t2 = now_ns();
            a[r] = (t1 - t0) / (double)n_items; b[r] = (t2 - t1) / (double)n_items;
        }
        q[r] = a[r] / b[r];
    }
    qsort(a, (size_t)runs, sizeof(double), dcmp);
    qsort(b, (size_t)runs, sizeof(double), dcmp);
    qsort(q, (size_t)runs, sizeof(double), dcmp);
    *ta = a[runs / 2]; *tb = b[runs / 2];
    return q[runs / 2];
}
double b_time_pair(void (*fa)(void *ctx), void *ca, void (*fb)(void *ctx), void *cb, long n_items, double *ta,
                   double *tb)
{ return time_pair(fa, ca, fb, cb, n_items, 15, 0, ta, tb); }
/* latency ratios are what other workers quote: more runs, order swapped */
double b_time_latency_pair(void (*fa)(void *ctx), void *ca, void (*fb)(void *ctx), void *cb, long n_calls,
                           double *ta, double *tb)
{ return time_pair(fa, ca, fb, cb, n_calls, 21, 1, ta, tb); }

void b_add_filter(const char *substring)
{
    if (substring && *substring && g_nfilters < 8) g_filters[g_nfilters++] = substring;
}
int b_filter_match(const char *name)
{
    const char *env = getenv("APPEAR_BENCH_FILTER");
    int i;
    if (env && *env && !strstr(name, env)) return 0;
    if (!g_nfilters) return 1;
    for (i = 0; i < g_nfilters; ++i)
        if (strstr(name, g_filters[i])) return 1;
    return 0;
}

static void csv_field(FILE *f, const char *s) /* quoted, inner quotes doubled */
{
    fputc('"', f);
    for (; s && *s; ++s) { if (*s == '"') fputc('"', f); fputc(*s, f); }
    fputc('"', f);
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
        /* a filtered run (b_add_filter / APPEAR_BENCH_FILTER) writes its own file, so timing one row
           does not overwrite the CSV of a full run that report.py reads */
        const char *env = getenv("APPEAR_BENCH_FILTER");
        snprintf(path, sizeof path, "bench/out/%s_%s%s.csv", under_callgrind() ? "callgrind" : "bench", BENCH_BUILD,
                 (g_nfilters || (env && *env)) ? "_filtered" : "");
        g_csv = fopen(path, "w");
        if (g_csv && g_cg) fprintf(g_csv, "build,group,name,seq,n\n");
        else if (g_csv) fprintf(g_csv, "build,group,name,ns_per_call,max_err,note\n");
    }
    if (!g_csv) return;
    fprintf(g_csv, "%s,%s,", BENCH_BUILD, group);
    csv_field(g_csv, name);
    if (g_cg) {
        long seq = -1, n = 0;
#if defined(BENCH_CALLGRIND)
        long k;
        for (k = 0; k < B_REC; ++k) /* the most recent b_time that returned ns */
            if (g_rec[k].seq > seq && g_rec[k].ret == ns) { seq = g_rec[k].seq; n = g_rec[k].n; }
#endif
        fprintf(g_csv, ",%ld,%ld\n", seq, n);
    } else {
        fprintf(g_csv, ",%.4f,%.4g,", ns, max_err);
        csv_field(g_csv, note);
        fputc('\n', g_csv);
    }
    fflush(g_csv);
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
