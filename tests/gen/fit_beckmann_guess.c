/* Fits the correction of the Beckmann visible-slope start (appear.h, appear__beckmann_sample_vis).
   W. Jakob's start [HdE14, implementation notes] x_J(theta, u) = erfinv(erf c - (1 + erf c)
   (1 - u)^k(theta)) is off by up to 0.15 (median 0.02); this program fits
   delta(theta, u) = sum_ij a_ij theta^i u^j ~ x_J - x_exact (i >= 1: x_J is exact at
   normal incidence, the Gaussian) by least squares over theta in (0, pi/2) and u in (0, 1) (a
   uniform grid, plus tail points u in [1e-7, 0.1] and 1 - u in [1e-7, 0.01] weighted 1/50: tail
   samples are rare, and the solver's bracket handles them), with x_exact a bisection in double of
   F(x) = p erfc(-x) + q exp(-x^2) = u F(c), p = sqrt(pi) z / 2, q = r / 2, c = z / r.
   x_J is computed in float by appear.h's own erfinv. Prints the coefficients as the C rows of
   appear.h (row i: the polynomial in u that multiplies theta^i) and the fit's error.
   Build and run: cc -std=c99 -O2 -I. tests/gen/fit_beckmann_guess.c -lm -o fit && ./fit [DT DU]
   (default 4 2, the degrees appear.h uses). */
#include "appear.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PI 3.14159265358979323846
#define NT 100
#define NU 300
#define MAXB 36

static double F_d(double p, double q, double x) { return p * erfc(-x) + q * exp(-x * x); }

static double x_exact(double theta, double u)
{
    double r = sin(theta), z = cos(theta), p = 0.5 * sqrt(PI) * z, q = 0.5 * r;
    double c = fmin(z / r, 40.0), N = F_d(p, q, c), lo = -40.0, hi = c;
    int k;
    for (k = 0; k < 200; ++k) {
        double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        if (F_d(p, q, mid) < u * N) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

static double x_jakob(double theta, double u)
{
    double c = cos(theta) / sin(theta), ec = erf(c);
    double k = 1.0 + theta * (-0.876 + theta * (0.4265 - 0.0594 * theta));
    return appear__erfinv_s((float)(ec - (1.0 + ec) * pow(1.0 - u, k)));
}

static int g_dt = 4, g_du = 2;

static void basis(double theta, double u, double *phi)
{
    int i, j, n = 0;
    for (i = 1; i <= g_dt; ++i)
        for (j = 0; j <= g_du; ++j) phi[n++] = pow(theta, i) * pow(u, j);
}

static double g_a[NT * NU][MAXB + 1];              /* the basis, then the right-hand side */

int main(int argc, char **argv)
{
    double coef[MAXB], phi[MAXB], worst = 0.0, worst0 = 0.0;
    int nb, m = 0, i, j, k, below[2] = { 0, 0 }, ntest = 100000;
    unsigned long long s = 12345;
    if (argc == 3) { g_dt = atoi(argv[1]); g_du = atoi(argv[2]); }
    nb = g_dt * (g_du + 1);
    if (nb > MAXB) return 1;
    for (i = 0; i < NT; ++i)
        for (j = 0; j < NU; ++j) {
            double theta = PI / 2 * (0.5 - 0.5 * cos(PI * (i + 0.5) / NT));
            double u = j < 200   ? (j + 0.5) / 200
                       : j < 250 ? pow(10, -1.0 - 6.0 * (j - 200) / 50)
                                 : 1 - pow(10, -2.0 - 5.0 * (j - 250) / 50);
            double w = j < 200 ? 1.0 : 0.02;
            basis(theta, u, g_a[m]);
            g_a[m][nb] = x_jakob(theta, u) - x_exact(theta, u);
            for (k = 0; k <= nb; ++k) g_a[m][k] *= w;
            ++m;
        }
    for (k = 0; k < nb; ++k) {                        /* Householder QR, then back substitution */
        double sg = 0.0, u0, vn, d;
        int l;
        for (i = k; i < m; ++i) sg += g_a[i][k] * g_a[i][k];
        sg = g_a[k][k] > 0 ? -sqrt(sg) : sqrt(sg);
        u0 = g_a[k][k] - sg; g_a[k][k] = sg; vn = u0 * u0;
        for (i = k + 1; i < m; ++i) vn += g_a[i][k] * g_a[i][k];
        for (l = k + 1; l <= nb; ++l) {               /* column nb: the right-hand side */
            d = u0 * g_a[k][l];
            for (i = k + 1; i < m; ++i) d += g_a[i][k] * g_a[i][l];
            d = 2.0 * d / vn; g_a[k][l] -= d * u0;
            for (i = k + 1; i < m; ++i) g_a[i][l] -= d * g_a[i][k];
        }
    }
    for (k = nb - 1; k >= 0; --k) {
        double t = g_a[k][nb];
        for (j = k + 1; j < nb; ++j) t -= g_a[k][j] * coef[j];
        coef[k] = t / g_a[k][k];
    }
    for (i = 0; i < ntest; ++i) {                     /* the corrected start at random (theta, u) */
        double theta, u, x, xj, d = 0.0, e;
        s ^= s << 13; s ^= s >> 7; s ^= s << 17; theta = PI / 2 * ((s >> 11) * 0x1p-53);
        s ^= s << 13; s ^= s >> 7; s ^= s << 17; u = (s >> 11) * 0x1p-53;
        x = x_exact(theta, u); xj = x_jakob(theta, u);
        basis(theta, u, phi);
        for (k = 0; k < nb; ++k) d += coef[k] * phi[k];
        e = fabs(xj - d - x);
        worst = fmax(worst, e); worst0 = fmax(worst0, fabs(xj - x));
        below[0] += e < 0.01; below[1] += e < 0.02;
    }
    printf("/* delta(theta, u), degree %d in theta, %d in u: |start error| max %.3g"
           " (Jakob's alone %.3g), < 0.01 for %.1f%%, < 0.02 for %.1f%% of uniform (theta, u) */\n",
           g_dt, g_du, worst, worst0, 100.0 * below[0] / ntest, 100.0 * below[1] / ntest);
    for (i = 1; i <= g_dt; ++i) {
        printf("  {");
        for (j = 0; j <= g_du; ++j)
            printf(" %.9ef%s", coef[(i - 1) * (g_du + 1) + j], j < g_du ? "," : "");
        printf(" },\n");
    }
    return 0;
}
