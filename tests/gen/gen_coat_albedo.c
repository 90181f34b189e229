/* tests/gen/gen_coat_albedo.c - writes the reflection-only albedo tables of
   appear.h's rough dielectric seen from outside (the coat's interface):
   SECTION tables (grep >>tables), between the lines BEGIN / END GENERATED
   COAT ALBEDO TABLES, after the albedo tables of tests/gen/gen_albedo.c and
   their lookups; the accessors and the two lookups that follow the block
   (appear_dielectric_reflect_albedo, _avg) are hand-written:
       cc -O2 -Wall -I. tests/gen/gen_coat_albedo.c -o build/gen_coat_albedo -lm
       ./build/gen_coat_albedo > build/coat_albedo_tables.h     (single process)
     or in P parallel parts (each node is computed by exactly one part):
       ./build/gen_coat_albedo part 0 2 > build/cr0 & ./build/gen_coat_albedo part 1 2 > build/cr1
       ./build/gen_coat_albedo assemble build/cr0 build/cr1 > build/coat_albedo_tables.h
   then
       python3 tests/gen/splice.py build/coat_albedo_tables.h
   (splice.py finds the block by its BEGIN line; it refuses a block outside
   SECTION tables). 61440 nodes of R at 46368 lattice points each and 1920
   averages of 32 such integrals: 582 CPU seconds, 12.5 minutes of wall
   time in 2 parts on a loaded 2-core machine.
   Node counts: AR_R_* in albedo_ref.h (the lookups read the generated
   APPEAR__CR_* counts; tests/test_multiscatter.c checks they agree). The
   interpolation error: tests/gen/scan_coat_albedo.c.
   R(mu, alpha, e) = integral of f_R(wo, wi) cos(theta_i) dwi over the upper
   hemisphere, the reflection lobe alone of the single-scattering dielectric
   (appear_dielectric) with wo outside, e = n_inside / n_outside >= 1: in
   double by tests/gen/albedo_ref.h (ar_albedo_refl, the Fibonacci lattice
   of ar_albedo, 46368 points), stored as round(R * 65535) in unsigned short.
   Axes: those of gen_albedo.c's outside table (ar_node_mu, ar_node_alpha,
   ar_node_e_out), x = index / (nodes - 1):
     mu:    (sqrt(mu) + mu) / 2 = x   (node 0 computed at mu = 1e-4)
     alpha  = 2 x^2                    (node 0: the smooth limit, R = F(mu))
     e      = 1 + 2 x^2                (e = 1: R = 0, index matched)
   Hemispherical average R_avg(alpha, e) = 2 int_0^1 R(mu) mu dmu, from the
   integrator (not from the table) by 32-point Gauss-Legendre in s =
   sqrt(mu) (mu = s^2: R bends fastest near grazing), same 16-bit storage.
   Output: R[type][eta][alpha][mu] flat per type (GGX, Beckmann), then
   R_avg[type][eta][alpha]; 16 values a line (at most 99 columns). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define AR_NO_INSIDE_NODES
#include "albedo_ref.h"
#include "gen_nodes.h"

#define AR_GEN_N 215 /* lattice of the first Fibonacci number >= 215^2: 46368 points */
#define N_GL 32      /* Gauss-Legendre points of the mu average */
#define N_R (AR_R_ETA * AR_R_A * AR_R_MU)
#define N_AVG (AR_R_ETA * AR_R_A)
#define N_ALL (2 * (N_R + N_AVG))
#define PER_LINE 16

/* Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n, in double) */
static void gauss_legendre(int n, double *x, double *w)
{
    int i, it, k;
    for (i = 0; i < n; ++i) {
        double z = cos(M_PI * (i + 0.75) / (n + 0.5)), p1 = 1.0, p2, p3, dp = 1.0;
        for (it = 0; it < 100; ++it) {
            double dz;
            p1 = 1.0; p2 = 0.0;
            for (k = 1; k <= n; ++k) { p3 = p2; p2 = p1; p1 = ((2 * k - 1) * z * p2 - (k - 1) * p3) / k; }
            dp = n * (z * p1 - p2) / (z * z - 1.0);
            dz = p1 / dp;
            z -= dz;
            if (fabs(dz) < 1e-15) break;
        }
        x[i] = 0.5 * (1.0 - z);
        w[i] = 1.0 / ((1.0 - z * z) * dp * dp);
    }
}
static double refl(int t, double alpha, double mu, double e)
{
    double ct;
    if (alpha == 0.0) return ar_fresnel(mu, e, &ct); /* the smooth limit */
    return ar_albedo_refl(t, alpha, mu, e, AR_GEN_N);
}
static unsigned value(int n)
{
    double v;
    int t = n / (N_R + N_AVG);
    n %= N_R + N_AVG;
    if (n < N_R) {
        double e = ar_node_e_out(n / (AR_R_A * AR_R_MU), AR_R_ETA), mu;
        double alpha = ar_node_alpha(n / AR_R_MU % AR_R_A, AR_R_A);
        mu = ar_node_mu(n % AR_R_MU, AR_R_MU);
        v = refl(t, alpha, mu < 1e-4 ? 1e-4 : mu, e);
    } else {
        double x[N_GL], w[N_GL], e, alpha;
        int g;
        n -= N_R;
        e = ar_node_e_out(n / AR_R_A, AR_R_ETA);
        alpha = ar_node_alpha(n % AR_R_A, AR_R_A);
        gauss_legendre(N_GL, x, w);
        /* 2 int R(mu) mu dmu = 4 int R(s^2) s^3 ds */
        for (v = 0.0, g = 0; g < N_GL; ++g) v += w[g] * 4.0 * x[g] * x[g] * x[g] * refl(t, alpha, x[g] * x[g], e);
    }
    v = v < 0 ? 0 : v > 1 ? 1 : v;
    return (unsigned)(v * 65535.0 + 0.5);
}
static void print_block(const unsigned *v, int count)
{
    int i;
    for (i = 0; i < count; ++i)
        printf("%u%s%s", v[i], i + 1 < count ? "," : "", (i + 1) % PER_LINE == 0 || i + 1 == count ? " \\\n" : "");
}

int main(int argc, char **argv)
{
    static unsigned v[N_ALL];
    static char seen[N_ALL];
    int t, r = gen_nodes(argc, argv, N_ALL, value, v, seen);
    if (r <= 0) return r < 0;
    printf("/* BEGIN GENERATED COAT ALBEDO TABLES (tests/gen/gen_coat_albedo.c; do not edit) */\n");
    printf("#define APPEAR__CR_MU %d\n#define APPEAR__CR_A %d\n#define APPEAR__CR_ETA %d\n", AR_R_MU, AR_R_A, AR_R_ETA);
    printf("#define APPEAR__CR_DATA { \\\n");
    for (t = 0; t < 2; ++t) {
        printf("{ \\\n");
        print_block(v + t * (N_R + N_AVG), N_R);
        printf("}%s \\\n", t ? "" : ",");
    }
    printf("}\n#define APPEAR__CR_AVG_DATA { \\\n");
    for (t = 0; t < 2; ++t) {
        printf("{ \\\n");
        print_block(v + t * (N_R + N_AVG) + N_R, N_AVG);
        printf("}%s \\\n", t ? "" : ",");
    }
    printf("}\n/* END GENERATED COAT ALBEDO TABLES */\n");
    return 0;
}
