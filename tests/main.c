/* tests/main.c - runs every suite (or those whose name contains argv[1]) and
   prints the closing line "N passed, M failed". The suite list is generated
   by the Makefile from the `void suite_<name>(void)` definitions. */
#include "harness.h"
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define X(f) void f(void);
#include "suites.h"
#undef X

typedef struct { const char *name; void (*fn)(void); } suite;
static const suite suites[] = {
#define X(f) { #f, f },
#include "suites.h"
#undef X
};

int main(int argc, char **argv)
{
    size_t i;
    for (i = 0; i < sizeof suites / sizeof suites[0]; ++i) {
        int run = argc < 2;
        int a;
        for (a = 1; a < argc; ++a) run |= strstr(suites[i].name, argv[a]) != NULL;
        if (run) {
            clock_t t0 = clock();
            printf("-- %s\n", suites[i].name);
            fflush(stdout);
            suites[i].fn();
            /* APPEAR_TEST_TIMES=1: each suite's CPU seconds, to keep CI within its budget */
            if (getenv("APPEAR_TEST_TIMES"))
                fprintf(stderr, "time %-28s %7.1f s\n", suites[i].name, (double)(clock() - t0) / CLOCKS_PER_SEC);
        }
    }
    return h_finish();
}
