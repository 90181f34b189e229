/* tests/fuzz/fuzz.c - libFuzzer drivers over every family of tests/robust.c.
 *
 * One binary, one family per run (APPEAR_FUZZ_FAMILY=name in the environment,
 * default lambert; see the Makefile's `fuzz` target): each input's bytes become the sweep's random choices (eight
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
 *   clang -fsanitize=fuzzer,address,undefined tests/fuzz/fuzz.c -o fuzz -lm
 *   APPEAR_FUZZ_FAMILY=ward ./fuzz tests/fuzz/corpus/ward -max_total_time=300
 */
#define RB_FUZZ 1
#include "../robust.c"

#ifndef RB_FUZZ_N
#define RB_FUZZ_N 64 /* iterations per input: the /8, /16, /64 families still run */
#endif

static void (*g_family)(void);
static const char *g_family_name;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    int k;
    if (!g_family) {
        const char *want = getenv("APPEAR_FUZZ_FAMILY");
        g_family_name = want && *want ? want : "lambert";
        for (k = 0; k < RB_NFAM; ++k)
            if (strcmp(rb_families[k].name, g_family_name) == 0) g_family = rb_families[k].run;
        if (!g_family) {
            fprintf(stderr, "fuzz: unknown family '%s'; one of:", g_family_name);
            for (k = 0; k < RB_NFAM; ++k) fprintf(stderr, " %s", rb_families[k].name);
            fprintf(stderr, "\n");
            exit(2);
        }
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
            fprintf(stderr, "fuzz %s: %s: %s\n", g_family_name, g_groups[k].name, g_groups[k].first);
            abort();
        }
    return 0;
}
