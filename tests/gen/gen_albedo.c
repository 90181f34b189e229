/* tests/gen/gen_albedo.c - writes the albedo tables of appear.h's energy
   compensation (section multiscatter) to stdout:
       cc -O2 -I. tests/gen/gen_albedo.c -o build/gen_albedo -lm
       ./build/gen_albedo > build/albedo_tables.h
       python3 tests/gen/splice.py build/albedo_tables.h
   Directional albedo of the single-scattering isotropic models, in double
   (tests/gen/albedo_ref.h), stored as round(E * 65535) in unsigned short.
   Axes (the lookup code in appear.h inverts them):
     mu    = cos theta_o:  i / (N_MU - 1)            (node 0 computed at 1e-4)
     alpha = 2 x^2,  x = j / (N_A - 1)               (alpha in [0, 2])
     eta'  = 1 + 2 k / (N_ETA - 1)                   (eta' in [1, 3])
   Conductor (F = 1): E[type][alpha][mu].
   Dielectric, R + e^2 T: E[type][side][eta'][alpha][mu], side 0: e = eta'
   (wo in the lower-index medium), side 1: e = 1 / eta'. */
#include <stdio.h>
#include "albedo_ref.h"

#define N_MU 32
#define N_A 32
#define D_MU 16
#define D_A 16
#define D_ETA 16

static double node_mu(int i, int n) { return i == 0 ? 1e-4 : (double)i / (n - 1); }
static double node_alpha(int j, int n) { double x = (double)j / (n - 1); return 2.0 * x * x; }

static unsigned q16(double e)
{
    e = e < 0 ? 0 : e > 1 ? 1 : e;
    return (unsigned)(e * 65535.0 + 0.5);
}
/* alpha = 0 is the smooth limit: albedo 1 (conductor) or 1 (dielectric) */
static double albedo(int type, double alpha, double mu, double e, int n)
{
    if (alpha == 0.0) return 1.0;
    if (e > 0.0 && e == 1.0) return 1.0;
    return ar_albedo(type, alpha, mu, e, n);
}

int main(void)
{
    int t, s, k, j, i, col;
    printf("/* BEGIN GENERATED ALBEDO TABLES (tests/gen/gen_albedo.c; do not edit) */\n");
    printf("#define APPEAR__EC_N_MU %d\n#define APPEAR__EC_N_A %d\n", N_MU, N_A);
    printf("#define APPEAR__EC_D_MU %d\n#define APPEAR__EC_D_A %d\n#define APPEAR__EC_D_ETA %d\n", D_MU, D_A, D_ETA);
    printf("#define APPEAR__EC_COND_DATA { \\\n");
    for (t = 0; t < 2; ++t) {
        printf("{ \\\n");
        for (j = 0; j < N_A; ++j) {
            printf("{");
            for (i = 0; i < N_MU; ++i) printf("%u%s", q16(albedo(t, node_alpha(j, N_A), node_mu(i, N_MU), -1.0, 256)), i + 1 < N_MU ? "," : "");
            printf("}%s \\\n", j + 1 < N_A ? "," : "");
        }
        printf("}%s \\\n", t ? "" : ",");
        fflush(stdout);
    }
    printf("}\n");
    printf("#define APPEAR__EC_DIEL_DATA { \\\n");
    for (t = 0; t < 2; ++t) {
        printf("{ \\\n");
        for (s = 0; s < 2; ++s) {
            printf("{ \\\n");
            for (k = 0; k < D_ETA; ++k) {
                double ep = 1.0 + 2.0 * k / (D_ETA - 1), e = s == 0 ? ep : 1.0 / ep;
                printf("{");
                for (j = 0; j < D_A; ++j) {
                    printf("{");
                    for (i = 0, col = 0; i < D_MU; ++i, ++col)
                        printf("%u%s", q16(albedo(t, node_alpha(j, D_A), node_mu(i, D_MU), e, 192)), i + 1 < D_MU ? "," : "");
                    printf("}%s", j + 1 < D_A ? "," : "");
                }
                printf("}%s \\\n", k + 1 < D_ETA ? "," : "");
                fflush(stdout);
            }
            printf("}%s \\\n", s ? "" : ",");
        }
        printf("}%s \\\n", t ? "" : ",");
    }
    printf("}\n/* END GENERATED ALBEDO TABLES */\n");
    return 0;
}
