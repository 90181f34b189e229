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
   30720 nodes at 28657 lattice points each: about 80 CPU seconds.
   E(wo; ax, ay) = integral of f cos over the upper hemisphere of the
   single-scattering anisotropic GGX conductor with F = 1, in double by
   ar_albedo_aniso (tests/gen/albedo_ref.h), stored as round(E * 65535).
   Coordinates. With a = max(ax, ay) along x (a lookup swaps x and y when
   ay > ax) and b = min(ax, ay), the table is read at wo's stretched
   direction v = (a wo.x, b wo.y, wo.z) / |.|, the direction whose
   isotropic unit-roughness configuration the masking of wo sees: along
   the smooth axis at grazing, where E changes by 0.4 within a degree of
   wo's azimuth (a = 0.9, b = 0.09), v's coordinates move slowly. Axes,
   x = index / (nodes - 1):
     mu_v = v.z:    (sqrt(mu_v) + mu_v) / 2 = x  (node 0 computed at 1e-4)
     alpha a        = 2 x^2                      (a = 0: E = 1, smooth)
     rho = b / a:   (sqrt(rho) + rho) / 2 = x    (rho = 0: computed at 1e-6,
                                                  the limit b -> 0 at fixed v;
                                                  x = sqrt(rho) until the twenty-
                                                  second session: OpenPBR's metal
                                                  at alpha (1, 0.63) erred 4.8e-3
                                                  there, 7.5e-4 now)
     c_v = v.x^2 / (v.x^2 + v.y^2) = x          (cos^2 of v's azimuth)
   wo = (v.x / a, v.y / b, v.z) / |.| at a node. The interpolation error:
   tests/test_multiscatter.c ("anisotropic albedo").
   Output: E[alpha][rho][c_v][mu_v] flat, 16 values a line. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define AR_NO_INSIDE_NODES
#define AR_ANISO
#define AR_ANISO_ONLY
#include "albedo_ref.h"
#include "gen_nodes.h"

#define AR_GEN_N 150 /* lattice of the first Fibonacci number >= 150^2: 28657 points */
#define N_ALL (AR_AN_A * AR_AN_RHO * AR_AN_C * AR_AN_MU)
#define PER_LINE 16

static unsigned value(int n)
{
    int i = n % AR_AN_MU, l = n / AR_AN_MU % AR_AN_C, k = n / (AR_AN_MU * AR_AN_C) % AR_AN_RHO;
    int j = n / (AR_AN_MU * AR_AN_C * AR_AN_RHO);
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
    int n, r = gen_nodes(argc, argv, N_ALL, value, v, seen);
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
