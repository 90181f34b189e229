/* bench/main.c - runs every bench_<name> function (or those matching argv). */
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

int main(int argc, char **argv)
{
    size_t i;
    for (i = 0; i < sizeof benches / sizeof benches[0]; ++i) {
        int run = argc < 2, a;
        for (a = 1; a < argc; ++a) run |= strstr(benches[i].name, argv[a]) != NULL;
        if (run) benches[i].fn();
    }
    return 0;
}
