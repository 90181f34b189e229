/* tests/gen/gen_aniso_dielectric.c - writes the anisotropic correction table of appear.h's GGX
   dielectric (appear_dielectric_albedo_aniso, the energy compensation of anisotropic rough
   dielectrics): SECTION tables (grep >>tables), between the lines BEGIN / END GENERATED ANISO
   DIELECTRIC TABLES; the lookup that follows the block is hand-written:
       cc -O2 -Wall -I. tests/gen/gen_aniso_dielectric.c -o build/gen_aniso_dielectric -lm
       ./build/gen_aniso_dielectric > build/aniso_dielectric_tables.h   (single process)
     or in P parallel parts (each node is computed by exactly one part):
       ./build/gen_aniso_dielectric part 0 2 > build/ad0 & ./build/gen_aniso_dielectric part 1 2 > build/ad1
       ./build/gen_aniso_dielectric assemble build/ad0 build/ad1 > build/aniso_dielectric_tables.h
   then
       python3 tests/gen/splice.py build/aniso_dielectric_tables.h
   68040 nodes at 28657 lattice points each: about 4 CPU minutes.
   What is stored. E(wo; ax, ay, e) = R + e^2 T, the directional albedo of the single-scattering
   anisotropic GGX dielectric of relative index e (n beyond / n on wo's side), integrated in double
   by ar_albedo_aniso_e (tests/gen/albedo_ref.h), divided by what appear.h reads for it without the
   table: its isotropic table (appear_dielectric_albedo) at wo's projected roughness
   (appear__alpha_proj); from inside (e < 1) the F = 1 conductor's anisotropic albedo times the
   isotropic inside table's E / E_cond at a groove surface's index ratio and cosine
   (appear__ad_base_in: the shadowing part, and the total reflection of wo's component along the
   grooves; the F = 1 ratio alone had cut the mean |error| inside over 1000 random points 5.7e-3 ->
   3.9e-3; from outside it made E worse, 2.0e-3 -> 4.0e-3, so not there); the factor K = E / E_iso
   is stored as round(K * 8192) (K < 8). Then the same for the reflection lobe alone lit from
   outside, R over appear.h's appear_dielectric_reflect_albedo. So this generator reads appear.h's
   isotropic tables: regenerate after they change. The factor, not E: while the axes were chosen,
   over 2000 random points, a 5-linear read of K erred 2.9e-3 on average, one of E itself 4.4e-3
   (the largest errors alike, 0.08-0.09, where one alpha is below a tenth of the other); wo's
   stretched coordinates, which serve the conductor's table, erred about 1e-2, more nodes or not
   (they crowd every node toward normal incidence where b / a is small, and the Fresnel factors see
   wo's own angle). The accuracy of the table compiled: the test "anisotropic dielectric albedo" in
   tests/test_multiscatter.c.
   Axes (AR_AD_* in albedo_ref.h), with a = max(ax, ay) (the lookup swaps x and y when ay > ax), b =
   min(ax, ay): mu = |wo.z| (ar_node_mu, node 0 at 1e-4), |cos| of wo's azimuth from the a axis (x;
   inside, piecewise linear with a knee where wy^2 = e^2: ar_node_ad_cx), rho = b / a = x^2 (0:
   1e-6), a = 2 x^2 (a = 0: K = 1, smooth), e (AR_AD_EO nodes outside, e = 1 + 2 x^2 up to 3, then
   AR_AD_EI inside down to 1/3, the isotropic table's axes), then AR_AD_EO outside nodes again for
   R.
   Output: K[e][alpha][rho][c][mu] flat (e: E's AR_AD_EO + AR_AD_EI nodes of AR_AD_RHO rho and AR_AD_MU mu
   nodes, then R's AR_AD_EO of AR_AD_RRHO and AR_AD_RMU), 16
   values a line. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define APPEAR_IMPLEMENTATION
#include "appear.h"
#define AR_ANISO
#define AR_ANISO_ONLY
#define AR_ANISO_DIEL
#define AR_NO_INSIDE_NODES
#define AR_COND_NODES /* (ar_node_aniso's mu axis) */
#include "albedo_ref.h"
#include "gen_nodes.h"

#define AR_GEN_N 150 /* lattice of the first Fibonacci number >= 150^2: 28657 points */
#define N_E (AR_AD_MU * AR_AD_C * AR_AD_RHO * AR_AD_A * (AR_AD_EO + AR_AD_EI)) /* E's blocks */
#define N_ALL (N_E + AR_AD_RMU * AR_AD_C * AR_AD_RRHO * AR_AD_A * AR_AD_EO)     /* then R's */
#define PER_LINE 16

static unsigned value(int n)
{
    int refl = n >= N_E, m = refl ? n - N_E : n; /* R: its own rho and mu axes */
    int nr = refl ? AR_AD_RRHO : AR_AD_RHO, nm = refl ? AR_AD_RMU : AR_AD_MU;
    int i = m % nm, l = m / nm % AR_AD_C, k = m / (nm * AR_AD_C) % nr;
    int j = m / (nm * AR_AD_C * nr) % AR_AD_A, q = m / (nm * AR_AD_C * nr * AR_AD_A);
    double a, b, e;
    q += refl ? AR_AD_EO + AR_AD_EI : 0;
    a = ar_node_alpha(j, AR_AD_A), b = a * ar_node_ad_rho(k, nr), e = ar_node_ad_e(q);
    double mu = ar_node_mu(i, nm), x, sx, E, K;
    float base;
    /* (the e = 1 nodes: appear_dielectric_albedo gives 1 at e = 1 exactly, the pass-through; a
       float beside it reads the isotropic table's own e = 1 nodes, the rough limit, which a lookup
       just off e = 1 mixes) */
    mu = mu < 1e-4 ? 1e-4 : mu;
    x = ar_node_ad_cx(l, mu, e, q >= AR_AD_EO && !refl);
    appear_vec3 wo;
    if (a == 0.0) return 8192u; /* smooth: no correction */
    sx = sqrt(fmax(0.0, 1.0 - mu * mu));
    wo = appear_vec3_make((float)(sx * x), (float)(sx * sqrt(1.0 - x * x)), (float)mu);
    if (refl) {
        E = ar_albedo_aniso_refl(a, b, mu, x * x, e, AR_GEN_N);
        base = appear_dielectric_reflect_albedo(APPEAR_GGX, appear__alpha_proj((float)a, (float)b, wo), (float)e,
                                                (float)mu);
    } else {
        appear__ad_frame f = appear__ad_frame_of((float)a, (float)b, wo);
        float ap = appear__alpha_proj((float)a, (float)b, wo);
        E = ar_albedo_aniso_e(a, b, mu, x * x, e, AR_GEN_N);
        float ef = q == 0 ? nextafterf(1.0f, 2.0f) : q == AR_AD_EO ? nextafterf(1.0f, 0.0f) : (float)e;
        base = appear__ad_base(&f, ap, ef); /* what the lookup multiplies K by */
    }
    K = base > 0.0f ? E / base : 1.0; /* (R at e = 1: 0 over 0) */
    K = K < 0.0 ? 0.0 : K > 65535.0 / 8192.0 ? 65535.0 / 8192.0 : K;
    return (unsigned)(K * 8192.0 + 0.5);
}

int main(int argc, char **argv)
{
    static unsigned v[N_ALL];
    static char seen[N_ALL];
    int n, r;
    (void)ar_node_rho; /* (the conductor's nodes: albedo_ref.h's, unused here) */
    (void)ar_node_aniso;
    (void)ar_node_ce_out;
    r = gen_nodes(argc, argv, N_ALL, value, v, seen);
    if (r <= 0) return r < 0;
    printf("/* BEGIN GENERATED ANISO DIELECTRIC TABLES (tests/gen/gen_aniso_dielectric.c; do not edit) */\n");
    printf("#define APPEAR__AD_MU %d\n#define APPEAR__AD_C %d\n#define APPEAR__AD_RHO %d\n#define APPEAR__AD_RRHO %d\n"
           "#define APPEAR__AD_RMU %d\n#define APPEAR__AD_A %d\n#define APPEAR__AD_EO %d\n#define APPEAR__AD_EI %d\n",
           AR_AD_MU, AR_AD_C, AR_AD_RHO, AR_AD_RRHO, AR_AD_RMU, AR_AD_A, AR_AD_EO, AR_AD_EI);
    printf("#define APPEAR__AD_DATA { \\\n");
    for (n = 0; n < N_ALL; ++n)
        printf("%u%s%s", v[n], n + 1 < N_ALL ? "," : "", (n + 1) % PER_LINE == 0 || n + 1 == N_ALL ? " \\\n" : "");
    printf("}\n/* END GENERATED ANISO DIELECTRIC TABLES */\n");
    return 0;
}
