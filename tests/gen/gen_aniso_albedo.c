/* tests/gen/gen_aniso_albedo.c - writes the anisotropic albedo table of
   appear.h's GGX conductor with F = 1 (appear_conductor_albedo_aniso, the
   energy compensation of anisotropic lobes): SECTION tables (grep
   >>tables), between the lines BEGIN / END GENERATED ANISO ALBEDO TABLES;
   the accessor and the lookup that follow the block are hand-written:
       cc -O2 -Wall -I. tests/gen/gen_aniso_albedo.c -o build/gen_aniso_albedo -lm
       ./build/gen_aniso_albedo > build/aniso_albedo_tables.h      (single process)
     or in P parallel parts (each node is computed by exactly one part):
       ./build/gen_aniso_albedo part 0 2 > build/an0 & ./build/gen_aniso_albedo part 1 2 > build/an1
       ./build/gen_aniso_albedo assemble build/an0 build/an1 > build/aniso_albedo_tables.h
   then
       python3 tests/gen/splice.py build/aniso_albedo_tables.h
   42240 nodes at 28657 lattice points each: about 110 CPU seconds.
   E(wo; ax, ay) = integral of f cos over the upper hemisphere of the
   single-scattering anisotropic GGX conductor with F = 1, in double by
   ar_albedo_aniso (tests/gen/albedo_ref.h), stored as round(E * 65535).
   Coordinates (albedo_ref.h, ar_node_aniso). With a = max(ax, ay) along x
   (a lookup swaps x and y when ay > ax), b = min(ax, ay), rho = b / a and
   wo squashed along y by s = rho^(3/4), u = (wo.x, s wo.y, wo.z) / |.|.
   Axes, x = index / (nodes - 1):
     alpha a        = 2 x^2                      (a = 0: E = 1, smooth)
     rho:           (sqrt(rho) + rho) / 2 = x    (node 0 computed at 1e-6,
                                                  the limit b -> 0; one node
                                                  more beyond 1, for the cubic
                                                  read of the last cell)
     c = u.x^2 / (u.x^2 + u.y^2) = x             (cos^2 of u's azimuth)
     m = u.z:       the conductor's mu axis      (ar_node_cmu; node 0 at 1e-4)
   appear.h reads it cubically in all four at a lobe's fixed alphas (a
   slice made at make()) and quadrilinearly where the alphas come with the
   call (appear_conductor_albedo_aniso). The interpolation error:
   tests/test_multiscatter.c ("anisotropic albedo").
   Output: E[alpha][rho][c][m] flat, 16 values a line. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define AR_NO_INSIDE_NODES
#define AR_ANISO
#define AR_ANISO_ONLY
#define AR_COND_NODES
#include "albedo_ref.h"
#include "gen_nodes.h"

#define AR_GEN_N 150 /* lattice of the first Fibonacci number >= 150^2: 28657 points */
#define N_ALL (AR_AN_A * (AR_AN_RHO + 1) * AR_AN_C * AR_AN_MU)
#define PER_LINE 16

static unsigned value(int n)
{
    int i = n % AR_AN_MU, l = n / AR_AN_MU % AR_AN_C, k = n / (AR_AN_MU * AR_AN_C) % (AR_AN_RHO + 1);
    int j = n / (AR_AN_MU * AR_AN_C * (AR_AN_RHO + 1));
    double a = ar_node_alpha(j, AR_AN_A), mu, c, E;
    ar_node_aniso(a, k, l, i, &mu, &c);
    E = a == 0.0 ? 1.0 : ar_albedo_aniso(a, a * ar_node_rho(k), mu, c, AR_GEN_N);
    E = E < 0 ? 0 : E > 1 ? 1 : E;
    return (unsigned)(E * 65535.0 + 0.5);
}

int main(int argc, char **argv)
{
    static unsigned v[N_ALL];
    static char seen[N_ALL];
    int n, r;
    (void)ar_node_mu; /* (albedo_ref.h's other axes, unused here) */
    (void)ar_node_ce_out;
    r = gen_nodes(argc, argv, N_ALL, value, v, seen);
    if (r <= 0) return r < 0;
    printf("/* BEGIN GENERATED ANISO ALBEDO TABLES (tests/gen/gen_aniso_albedo.c; do not edit) */\n");
    printf("#define APPEAR__AN_MU %d\n#define APPEAR__AN_A %d\n#define APPEAR__AN_RHO %d\n#define APPEAR__AN_C %d\n",
           AR_AN_MU, AR_AN_A, AR_AN_RHO, AR_AN_C);
    printf("#define APPEAR__AN_DATA { \\\n");
    for (n = 0; n < N_ALL; ++n)
        printf("%u%s%s", v[n], n + 1 < N_ALL ? "," : "", (n + 1) % PER_LINE == 0 || n + 1 == N_ALL ? " \\\n" : "");
    printf("}\n/* END GENERATED ANISO ALBEDO TABLES */\n");
    return 0;
}
