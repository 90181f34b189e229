/* tests/gen/gen_nodes.h - the node driver of a table generator whose nodes are one unsigned each
   (tests/gen/gen_coat_albedo.c, tests/gen/gen_aniso_albedo.c): its three modes,
       prog                        every node, in one process
       prog part P NP              the nodes n = P, P + NP, ... as lines "n value" (each node is
                                   computed by exactly one of NP parts)
       prog assemble F1 F2 ...     the parts' files read back (later files override)
   gen_nodes() returns 1 when v[0 .. count) holds every node (computed or assembled: the caller
   writes its table), 0 when a part was printed (the caller is done), -1 on an error (a file that
   cannot be read, nodes missing: reported on stderr). seen: count bytes, zeroed. */
#ifndef GEN_NODES_H
#define GEN_NODES_H
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int gen_nodes(int argc, char **argv, int count, unsigned (*value)(int), unsigned *v, char *seen)
{
    int n;
    if (argc == 4 && !strcmp(argv[1], "part")) {
        int p = atoi(argv[2]), np = atoi(argv[3]);
        for (n = p; n < count; n += np) {
            printf("%d %u\n", n, value(n));
            fflush(stdout);
        }
        return 0;
    }
    if (argc >= 3 && !strcmp(argv[1], "assemble")) {
        int a, got = 0;
        for (a = 2; a < argc; ++a) {
            FILE *f = fopen(argv[a], "r");
            unsigned x;
            if (!f) { fprintf(stderr, "cannot read %s\n", argv[a]); return -1; }
            while (fscanf(f, "%d %u", &n, &x) == 2)
                if (n >= 0 && n < count) { got += !seen[n]; seen[n] = 1; v[n] = x; }
            fclose(f);
        }
        if (got != count) { fprintf(stderr, "incomplete: %d of %d nodes\n", got, count); return -1; }
        return 1;
    }
    for (n = 0; n < count; ++n) v[n] = value(n);
    return 1;
}
#endif
