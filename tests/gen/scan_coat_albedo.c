/* tests/gen/scan_coat_albedo.c - a dense measure of the interpolation error
   of appear_dielectric_reflect_albedo (the float lookup of appear.h) against
   the double integrator of tests/gen/albedo_ref.h (lattice 64^2 = 4181
   points, within ~3e-5 of the generator's 46368), at N uniform random
   points in mu 0.02..1, alpha 0.02..2, eta 1.05..3 (or a box given):
       cc -O2 -Wall -I. tests/gen/scan_coat_albedo.c -o build/scan_coat_albedo -lm
       ./build/scan_coat_albedo 100000 1
       ./build/scan_coat_albedo 20000 2 0.02 0.05 0.02 0.15 1.05 3   (alpha, mu, eta ranges)
   Prints the maximum, the mean and the share above 1e-3 and 2e-3, split
   into the points with alpha < 0.05 and mu < 0.15 (where R bends at the
   shadowing's onset, alpha ~ mu / 4) and the others. About 0.4 ms a point. */
#include "../../appear.h"
#include <stdio.h>
#include <stdlib.h>
#define AR_NO_INSIDE_NODES
#define AR_NO_NODES
#include "albedo_ref.h"

static unsigned long long g_s;
static double rnd(void)
{
    g_s = g_s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(g_s >> 11) / 9007199254740992.0;
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 10000, i, cnt[2] = { 0, 0 }, o1[2] = { 0, 0 }, o2[2] = { 0, 0 };
    double a0 = 0.02, a1 = 2, m0 = 0.02, m1 = 1, e0 = 1.05, e1 = 3, w[2] = { 0, 0 }, sum[2] = { 0, 0 }, at[2][4];
    int g;
    g_s = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
    if (argc > 8) { a0 = atof(argv[3]); a1 = atof(argv[4]); m0 = atof(argv[5]); m1 = atof(argv[6]); e0 = atof(argv[7]); e1 = atof(argv[8]); }
    for (i = 0; i < n; ++i) {
        int t = (int)(i & 1);
        double mu = m0 + (m1 - m0) * rnd(), al = a0 + (a1 - a0) * rnd(), e = e0 + (e1 - e0) * rnd();
        double ref = ar_albedo_refl(t, al, mu, e, 64);
        double d = fabs(appear_dielectric_reflect_albedo(t, (float)al, (float)e, (float)mu) - ref);
        g = al < 0.05 && mu < 0.15;
        ++cnt[g]; sum[g] += d; o1[g] += d > 1e-3; o2[g] += d > 2e-3;
        if (d > w[g]) { w[g] = d; at[g][0] = t; at[g][1] = mu; at[g][2] = al; at[g][3] = e; }
    }
    for (g = 0; g < 2; ++g)
        if (cnt[g])
            printf("%s: %ld points, max %.3g (%s mu %.4f alpha %.4f eta %.4f), mean %.3g, > 1e-3: %.3f%%, > 2e-3: %.3f%%\n",
                   g ? "alpha < 0.05 and mu < 0.15" : "elsewhere", cnt[g], w[g], at[g][0] ? "beckmann" : "ggx", at[g][1],
                   at[g][2], at[g][3], sum[g] / cnt[g], 100.0 * o1[g] / cnt[g], 100.0 * o2[g] / cnt[g]);
    printf("all: max %.3g, > 2e-3: %.3f%% of %ld (table %d x %d x %d)\n", w[0] > w[1] ? w[0] : w[1],
           100.0 * (o2[0] + o2[1]) / n, n, APPEAR__CR_MU, APPEAR__CR_A, APPEAR__CR_ETA);
    return 0;
}
