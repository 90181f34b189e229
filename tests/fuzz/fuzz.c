/* tests/fuzz/fuzz.c - libFuzzer drivers over every family of tests/robust.c.
 *
 * One binary per family (-DFUZZ_FAMILY='"name"', see the Makefile's `fuzz`
 * target): each input's bytes become the sweep's random choices (eight
 * bytes per choice: raw float bit patterns, parameters, directions, random
 * numbers, n of a batch; a splitmix continuation once they run out), the
 * family runs RB_FUZZ_N iterations, and any violation of the contract that
 * robust.c checks aborts with its message, which libFuzzer reports as a
 * crash and saves as a reproducer. The contract: every value and pdf finite
 * and >= 0; a failed sample zeroed; a successful one with unit wi, pdf > 0,
 * weight = f |cos| / pdf, and (non-delta lobes) pdf() > 0, pdf() = s.pdf and
 * eval() = s.f at its own direction; batch = scalar bit for bit; trackers
 * that terminate within their lookup budget with finite T.
 *
 *   clang -fsanitize=fuzzer,address,undefined -DFUZZ_FAMILY='"ward"' tests/fuzz/fuzz.c
 *   ./fuzz_ward tests/fuzz/corpus/ward -max_total_time=300
 */
#define RB_FUZZ 1
#include "../robust.c"

#ifndef FUZZ_FAMILY
#define FUZZ_FAMILY "lambert"
#endif
#ifndef RB_FUZZ_N
#define RB_FUZZ_N 64 /* iterations per input: the /8, /16, /64 families still run */
#endif

static void (*g_family)(void);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    int k;
    if (!g_family) {
        for (k = 0; k < RB_NFAM; ++k)
            if (strcmp(rb_families[k].name, FUZZ_FAMILY) == 0) g_family = rb_families[k].run;
        if (!g_family) { fprintf(stderr, "fuzz: unknown family %s\n", FUZZ_FAMILY); abort(); }
    }
    g_fz = data; g_fzn = size; g_fzi = 0;
    g_s = 12345; /* the continuation: the same for every input, so a finding replays */
    for (k = 0; k < 8 && (size_t)k < size; ++k) g_s = g_s * 131u + data[k];
    memset(&g_last, 0, sizeof g_last);
    g_ngroups = 0;
    g_n = RB_FUZZ_N;
    g_family();
    for (k = 0; k < g_ngroups; ++k)
        if (g_groups[k].bad) {
            fprintf(stderr, "fuzz %s: %s: %s\n", FUZZ_FAMILY, g_groups[k].name, g_groups[k].first);
            abort();
        }
    return 0;
}
