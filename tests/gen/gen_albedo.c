/* tests/gen/gen_albedo.c - writes the albedo tables of appear.h's energy
   compensation (SECTION compensation reads them; they live in the trailing
   generated part, SECTION tables, grep >>tables, between the lines
   BEGIN / END GENERATED ALBEDO TABLES, before the table accessors and the
   two lookups, which are hand-written):
       cc -O2 -I. tests/gen/gen_albedo.c -o build/gen_albedo -lm
       ./build/gen_albedo > build/albedo_tables.h          (single process)
     or in P parallel parts (each node is computed by exactly one part):
       ./build/gen_albedo part 0 2 > build/ab0 & ./build/gen_albedo part 1 2 > build/ab1
       ./build/gen_albedo assemble build/ab0 build/ab1 > build/albedo_tables.h
     (or "part P NP inside" for the e < 1 tables only, assembled after the
     files with the other nodes: later files override)
   then
       python3 tests/gen/splice.py build/albedo_tables.h
   (which replaces the BEGIN ... END block inside SECTION tables and nothing
   else; it refuses a block found anywhere else in the file).
   (about 28k nodes at 4.6e4 lattice points each: ~10 CPU minutes.)
   Directional albedo of the single-scattering isotropic models, in double
   (tests/gen/albedo_ref.h, Fibonacci-lattice quadrature), stored as
   round(E * 65535) (appear.h keeps them in unsigned short, the conductor's
   in float: its bicubic read mixes 16 entries).
   Axes (ar_node_* in albedo_ref.h; the lookup code in appear.h inverts
   them), x = index / (nodes - 1) in [0, 1]:
     mu:    (sqrt(mu) + mu) / 2 = x      (node 0 computed at mu = 1e-4)
     alpha  = 2 x^2                       (alpha in [0, 2])
     inside side  (e <= 1):  (w + sqrt(w)) / 2 = x, w = 3 (1 - e) / 2  (e in [1/3, 1])
   except the conductor's table and the dielectric's from outside (below).
   e = n(other side) / n(wo side). The e = 1 nodes hold the rough model's
   limit e -> 1 (the transmission lobe still loses energy to shadowing);
   appear.h bypasses the table at exactly eta = 1 (a smooth pass-through).
   Output: 16 values a line (99 columns at most, the header's width; a
   layout that no longer matches the old one line by line also keeps git's
   merges from anchoring on the moved block).
   Conductor (F = 1): E[type][alpha][mu], 32 x 32, on axes of its own (ar_node_calpha, ar_node_cmu
   in albedo_ref.h: log-like toward 0, where the shadowing's knee alpha ~ mu lies; appear.h reads
   it bicubically).
   Dielectric, R + e^2 T: one flat block per type, outside table
   [eta][alpha][mu] then inside table [eta][alpha][mu]; the inside table holds E / E_cond (F = 1,
   the same alpha and mu) times 4096, not E (value() below). The outside table, 24 x 20 x 12, has
   the conductor's mu and alpha axes, read bicubically, and e - 1 on its alpha axis
   (ar_node_ce_out), read linearly (on throwaway tables of exact nodes, GGX, alpha 0.005 .. 1, mu
   0.017 .. 1, e 1 .. 3: largest relative error 2.2e-3, was 3.0e-2 on 16 x 12 x 12 trilinear on
   the sqrt axes; Beckmann 3.3e-3). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define AR_COND_NODES
#define AR_NO_E_OUT
#include "albedo_ref.h"
#include "gen_nodes.h"

#define AR_GEN_N 215 /* lattice of the first Fibonacci number >= 215^2: 46368 points */
#define N_COND (2 * AR_C_A * AR_C_MU)
#define N_OUT (AR_O_ETA * AR_O_A * AR_O_MU)
#define N_IN (AR_I_ETA * AR_I_A * AR_I_MU)
#define N_ALL (N_COND + 2 * (N_OUT + N_IN))
#define PER_LINE 16 /* values per line of the output */

/* node n in output order -> (type, alpha, mu, e); e < 0: conductor */
static void node(int n, int *t, double *alpha, double *mu, double *e)
{
    if (n < N_COND) {
        *t = n / (AR_C_A * AR_C_MU); n %= AR_C_A * AR_C_MU;
        *alpha = ar_node_calpha(n / AR_C_MU, AR_C_A); *mu = ar_node_cmu(n % AR_C_MU, AR_C_MU); *e = -1.0;
        return;
    }
    n -= N_COND;
    *t = n / (N_OUT + N_IN); n %= N_OUT + N_IN;
    if (n < N_OUT) {
        *e = ar_node_ce_out(n / (AR_O_A * AR_O_MU), AR_O_ETA); n %= AR_O_A * AR_O_MU;
        *alpha = ar_node_calpha(n / AR_O_MU, AR_O_A); *mu = ar_node_cmu(n % AR_O_MU, AR_O_MU);
    } else {
        n -= N_OUT;
        *e = ar_node_e_in(n / (AR_I_A * AR_I_MU), AR_I_ETA); n %= AR_I_A * AR_I_MU;
        *alpha = ar_node_alpha(n / AR_I_MU, AR_I_A); *mu = ar_node_mu(n % AR_I_MU, AR_I_MU);
    }
}
static unsigned value(int n)
{
    int t, in = n >= N_COND && (n - N_COND) % (N_OUT + N_IN) >= N_OUT;
    double alpha, mu, e, E, K;
    node(n, &t, &alpha, &mu, &e);
    mu = mu < 1e-4 ? 1e-4 : mu;
    /* alpha = 0 is the smooth limit: albedo 1 */
    E = alpha == 0.0 ? 1.0 : ar_albedo(t, alpha, mu, e, AR_GEN_N);
    E = E < 0 ? 0 : E > 1 ? 1 : E;
    if (!in) return (unsigned)(E * 65535.0 + 0.5);
    /* inside: E over the conductor's E (F = 1) at the same alpha and mu, which shares its
       shadowing knee; the ratio is read linearly and multiplied by the conductor's bicubic read
       (at alpha 0.032, mu 0.15, e 1/3, the coated glass's traced point, E's own trilinear read
       erred 4.1e-3, the ratio's 1.3e-4); in [0.01, 13.2] (large where E_cond is small: alpha 2,
       e 1), stored as round(K * 4096) */
    K = alpha == 0.0 ? 1.0 : E / ar_albedo(t, alpha, mu, -1.0, AR_GEN_N);
    K = K > 65535.0 / 4096.0 ? 65535.0 / 4096.0 : K;
    return (unsigned)(K * 4096.0 + 0.5);
}

int main(int argc, char **argv)
{
    static unsigned v[N_ALL];
    static char seen[N_ALL];
    int n, t, j, r;
    if (argc == 5 && !strcmp(argv[1], "part") && !strcmp(argv[4], "inside")) {
        /* "part P NP inside": only the inside (e < 1) blocks, for a rerun after a change of that
           table alone (assemble reads its files in order, later values override earlier ones) */
        int p = atoi(argv[2]), np = atoi(argv[3]);
        for (n = p; n < N_ALL; n += np) {
            if (n < N_COND || (n - N_COND) % (N_OUT + N_IN) < N_OUT) continue;
            printf("%d %u\n", n, value(n));
            fflush(stdout);
        }
        return 0;
    }
    r = gen_nodes(argc, argv, N_ALL, value, v, seen);
    if (r <= 0) return r < 0;
    printf("/* BEGIN GENERATED ALBEDO TABLES (tests/gen/gen_albedo.c; do not edit) */\n");
    printf("#define APPEAR__EC_N_MU %d\n#define APPEAR__EC_N_A %d\n", AR_C_MU, AR_C_A);
    printf("#define APPEAR__EC_O_MU %d\n#define APPEAR__EC_O_A %d\n#define APPEAR__EC_O_ETA %d\n", AR_O_MU, AR_O_A, AR_O_ETA);
    printf("#define APPEAR__EC_I_MU %d\n#define APPEAR__EC_I_A %d\n#define APPEAR__EC_I_ETA %d\n", AR_I_MU, AR_I_A, AR_I_ETA);
    /* PER_LINE values a line (at most 99 columns: the header's width limit) */
    printf("#define APPEAR__EC_COND_DATA { \\\n");
    for (t = 0, n = 0; t < 2; ++t) {
        printf("{ \\\n");
        for (j = 0; j < AR_C_A; ++j) {
            int i;
            printf("{");
            for (i = 0; i < AR_C_MU; ++i)
                printf("%u%s%s", v[n++], i + 1 < AR_C_MU ? "," : "",
                       (i + 1) % PER_LINE == 0 && i + 1 < AR_C_MU ? " \\\n" : "");
            printf("}%s \\\n", j + 1 < AR_C_A ? "," : "");
        }
        printf("}%s \\\n", t ? "" : ",");
    }
    printf("}\n#define APPEAR__EC_DIEL_DATA { \\\n");
    for (t = 0; t < 2; ++t) {
        int i;
        printf("{ \\\n");
        for (i = 0; i < N_OUT + N_IN; ++i)
            printf("%u%s%s", v[n++], i + 1 < N_OUT + N_IN ? "," : "",
                   (i + 1) % PER_LINE == 0 || i + 1 == N_OUT + N_IN ? " \\\n" : "");
        printf("}%s \\\n", t ? "" : ",");
    }
    printf("}\n/* END GENERATED ALBEDO TABLES */\n");
    return 0;
}
