/* bench/main.c - runs every bench_<name> function (or those matching argv).
   Arguments: a word contained in a bench function's name selects that group
   (e.g. `latency` -> bench_latency); a word that names no group is a row
   filter for the groups that honour b_filter_match (bench_latency):
   `./build/bench_O2 latency hg` times only the latency rows whose name
   contains "hg". `--filter=WORD` makes any word a row filter (for words
   that are also group names, e.g. --filter=ward); so does
   APPEAR_BENCH_FILTER=WORD. Filters alone (no group word) run `latency`. */
#include "bench.h"
#include <stdio.h>
#include <string.h>

#define X(f) void f(void);
#include "benches.h"
#undef X

typedef struct { const char *name; void (*fn)(void); } bench;
static const bench benches[] = {
#define X(f) { #f, f },
#include "benches.h"
#undef X
};
#define NB (sizeof benches / sizeof benches[0])

int main(int argc, char **argv)
{
    size_t i;
    int a, ngroups = 0, nfilters = 0;
    static char sel[NB];
    for (a = 1; a < argc; ++a) {
        int hit = 0;
        if (strncmp(argv[a], "--filter=", 9) == 0) { b_add_filter(argv[a] + 9); ++nfilters; continue; }
        for (i = 0; i < NB; ++i)
            if (strstr(benches[i].name, argv[a])) { sel[i] = 1; hit = 1; }
        if (hit) ++ngroups;
        else { b_add_filter(argv[a]); ++nfilters; }
    }
    for (i = 0; i < NB; ++i) {
        int run = ngroups ? sel[i] : (nfilters ? strcmp(benches[i].name, "bench_latency") == 0 : 1);
        if (run) benches[i].fn();
    }
    return 0;
}
