/* tests/profiles.h - the six density profiles of Georgiev et al. 2019
   (Integral formulations of volumetric transmittance, Sec. 7) on x in
   [0, 1], with their optical depths in closed form and their exact bounds:
   the media tests' ground truth (tests/test_media.c, test_media_chromatic.c). */
#ifndef APPEAR_TEST_PROFILES_H
#define APPEAR_TEST_PROFILES_H
#include <math.h>
#if defined(__GNUC__) || defined(__clang__)
#define PROF_FN static __attribute__((unused))
#else
#define PROF_FN static
#endif

enum { P_CONST, P_COS, P_BUMP, P_HOLE, P_RAMP_UP, P_RAMP_DOWN, P_COUNT };
static const char *const prof_name[P_COUNT] = { "constant", "cosine", "bump", "hole", "ramp_up", "ramp_down" };
#define BUMP_S 0.1

PROF_FN double prof_sigma(int p, double x)
{
    double g = exp(-(x - 0.5) * (x - 0.5) / (2.0 * BUMP_S * BUMP_S));
    switch (p) {
    case P_CONST: return 2.0;
    case P_COS: return 1.5 * cos(20.0 * x + 0.8) + 2.0;
    case P_BUMP: return 0.5 + 4.0 * g;
    case P_HOLE: return 3.0 - 2.9 * g;
    case P_RAMP_UP: return 0.2 + 3.8 * x;
    default: return 4.0 - 3.8 * x;
    }
}
/* optical depth from 0 to x, closed form */
PROF_FN double prof_tau(int p, double x)
{
    double k = BUMP_S * sqrt(3.14159265358979323846 / 2.0);
    double G = k * (erf((x - 0.5) / (BUMP_S * sqrt(2.0))) + erf(0.5 / (BUMP_S * sqrt(2.0))));
    switch (p) {
    case P_CONST: return 2.0 * x;
    case P_COS: return 2.0 * x + 1.5 / 20.0 * (sin(20.0 * x + 0.8) - sin(0.8));
    case P_BUMP: return 0.5 * x + 4.0 * G;
    case P_HOLE: return 3.0 * x - 2.9 * G;
    case P_RAMP_UP: return 0.2 * x + 1.9 * x * x;
    default: return 4.0 * x - 1.9 * x * x;
    }
}
/* exact bounds on [0, 1], by the formulas */
PROF_FN void prof_bounds(int p, double *mx, double *mn)
{
    switch (p) {
    case P_CONST: *mx = 2.0; *mn = 2.0; break;
    case P_COS: *mx = 3.5; *mn = 0.5; break;
    case P_BUMP: *mx = 4.5; *mn = 0.5 + 4.0 * exp(-12.5); break;
    case P_HOLE: *mx = 3.0 - 2.9 * exp(-12.5); *mn = 0.1; break;
    case P_RAMP_UP: *mx = 4.0; *mn = 0.2; break;
    default: *mx = 4.0; *mn = 0.2; break;
    }
}
#endif
