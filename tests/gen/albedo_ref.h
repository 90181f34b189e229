/* tests/gen/albedo_ref.h - double-precision reference integrator for the
   directional albedo of single-scattering microfacet models (isotropic;
   the anisotropic GGX conductor and dielectric under AR_ANISO),
   shared by tests/gen/gen_albedo.c (which writes the tables compiled into
   appear.h) and tests/test_multiscatter.c (which recomputes table nodes).
   Written from the papers, independent of appear.h's float code:
   D and Lambda [Heitz14, Eq. 83-86], height-correlated G2 [Heitz14, Eq. 99],
   GGX visible normals [Heitz18, Sec. 3-4], Beckmann by D(m) cos sampling
   [Walter07, Eq. 28], exact dielectric Fresnel [BW99 1.5]. */
#ifndef APPEAR_ALBEDO_REF_H
#define APPEAR_ALBEDO_REF_H
#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* unpolarised dielectric Fresnel, c = cos to the facet (> 0), e = n_t/n_i */
static double ar_fresnel(double c, double e, double *cos_t)
{
    double s2t = (1.0 - c * c) / (e * e), ct, rs, rp;
    if (s2t >= 1.0) { *cos_t = 0; return 1.0; }
    ct = sqrt(1.0 - s2t);
    rs = (c - e * ct) / (c + e * ct);
    rp = (e * c - ct) / (e * c + ct);
    *cos_t = ct;
    return 0.5 * (rs * rs + rp * rp);
}
#define AR_REFL 1  /* the lobes an integration counts: reflection, */
#define AR_TRANS 2 /* e^2 x transmission */
#ifndef AR_ANISO_ONLY /* (tests/gen/gen_aniso_albedo.c: the anisotropic conductor alone) */
static double ar_lambda(int beckmann, double alpha, double mu)
{
    double s2 = fmax(0.0, 1.0 - mu * mu), t2;
    if (s2 == 0.0) return 0.0;
    t2 = s2 / (mu * mu);
    if (!beckmann) return 0.5 * (-1.0 + sqrt(1.0 + alpha * alpha * t2));
    {
        double a = 1.0 / (alpha * sqrt(t2));
        return 0.5 * (exp(-a * a) / (a * sqrt(M_PI)) - erfc(a));
    }
}
/* GGX visible normal for wo = (sx, 0, mu) [Heitz18, Listing 1]. */
static void ar_ggx_vndf(double alpha, double sx, double mu, double u1, double u2, double m[3])
{
    double vx = alpha * sx, vz = mu, l = sqrt(vx * vx + vz * vz);
    double T1[3], T2[3], r = sqrt(u1), phi = 2 * M_PI * u2, t1, t2, s, n[3], nz;
    vx /= l; vz /= l;
    if (vx > 0) { T1[0] = 0; T1[1] = 1; T1[2] = 0; } else { T1[0] = 1; T1[1] = 0; T1[2] = 0; }
    /* T2 = V x T1 */
    T2[0] = 0 * T1[2] - vz * T1[1]; T2[1] = vz * T1[0] - vx * T1[2]; T2[2] = vx * T1[1] - 0 * T1[0];
    t1 = r * cos(phi); t2 = r * sin(phi);
    s = 0.5 * (1.0 + vz);
    t2 = (1.0 - s) * sqrt(fmax(0.0, 1.0 - t1 * t1)) + s * t2;
    nz = sqrt(fmax(0.0, 1.0 - t1 * t1 - t2 * t2));
    n[0] = t1 * T1[0] + t2 * T2[0] + nz * vx;
    n[1] = t1 * T1[1] + t2 * T2[1];
    n[2] = t1 * T1[2] + t2 * T2[2] + nz * vz;
    n[0] *= alpha; n[1] *= alpha; n[2] = fmax(n[2], 0.0);
    l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    m[0] = n[0] / l; m[1] = n[1] / l; m[2] = n[2] / l;
}
/* Directional albedo at cos(theta_o) = mu of the single-scattering model:
   conductor with F = 1 (e <= 0), or dielectric with relative index e
   (n(other side) / n(wo side)), counting R + e^2 T (the flux).
   Rank-1 Fibonacci lattice with N points in the sampler's unit square
   (u1 warped), N the first Fibonacci number >= n^2, generator the one
   before it [Sloan & Joe 1994, Ch. 5 (Fibonacci lattices)]. The
   integrand has jumps (rays leaving below the horizon, total internal
   reflection); at mu = 1 they lie on lines u1 = const, where an n x n
   product midpoint rule converges erratically (1e-2 relative at n = 256
   for Beckmann inside at alpha = 2); the lattice, whose rows are not
   aligned with them, reaches about 1e-4 with 3e4 points.
   lobes: AR_REFL (reflection alone), AR_TRANS (e^2 T alone) or both;
   ar_albedo and ar_albedo_refl below are the two uses. */
static double ar_albedo_lobes(int beckmann, double alpha, double mu, double e, int n, int lobes)
{
    double sx = sqrt(fmax(0.0, 1.0 - mu * mu)), lo = ar_lambda(beckmann, alpha, mu), acc = 0.0;
    long i, N = 2, G = 1;
    while (N < (long)n * n) { long t2 = N + G; G = N; N = t2; }
    for (i = 0; i < N; ++i) {
        /* u1 = 1 - (1-t)^4 clusters the points near u1 = 1, where both
           samplers put the grazing microfacets that lose the energy */
        double t = (i + 0.5) / N, omt = 1.0 - t, jac = 4.0 * omt * omt * omt;
        double u1 = 1.0 - omt * omt * omt * omt, u2 = fmod(fmod((double)i * G, (double)N) / N + 0.5 / N + 0.3183098861837907, 1.0);
        double m[3], c, w, F = 1.0, ct = 0.0, wr[3];
        if (!beckmann) {
            ar_ggx_vndf(alpha, sx, mu, u1, u2, m);
            w = 1.0 + lo; /* weight D_wo-sampled: (1 + Lo) G2 */
        } else {
            double sl = alpha * sqrt(-4.0 * log(omt)), phi = 2 * M_PI * u2, cz = 1.0 / sqrt(1.0 + sl * sl);
            m[0] = sl * cos(phi) * cz; m[1] = sl * sin(phi) * cz; m[2] = cz;
            w = 0.0; /* set below: (wo.m) / (mu m.z) G2 */
        }
        c = sx * m[0] + mu * m[2];
        if (c <= 0.0) continue;
        if (beckmann) w = c / (mu * m[2]);
        if (e > 0.0) F = ar_fresnel(c, e, &ct);
        wr[2] = 2 * c * m[2] - mu;
        w *= jac;
        if ((lobes & AR_REFL) && wr[2] > 0.0) acc += w * F / (1.0 + lo + ar_lambda(beckmann, alpha, wr[2]));
        if ((lobes & AR_TRANS) && F < 1.0) {
            double wtz = -mu / e + (c / e - ct) * m[2];
            if (wtz < 0.0) acc += w * (1.0 - F) / (1.0 + lo + ar_lambda(beckmann, alpha, -wtz));
        }
    }
    return acc / (double)N;
}
#endif
#ifdef AR_ANISO /* (its users define it: no unused functions elsewhere) */
/* Directional albedo of the anisotropic GGX conductor with F = 1 (e <= 0)
   or dielectric of relative index e (R + e^2 T, as ar_albedo) at wo =
   (sx sqrt(c), sx sqrt(1 - c), mu), sx = sqrt(1 - mu^2): c = cos^2 of wo's
   azimuth from the x axis, roughness ax along x, ay along y (either may be
   0). Visible normals by the stretch of [Heitz18, Listing 1] (wo stretched
   to the unit-roughness configuration, the hemisphere's projected disk
   sampled there, the normal unstretched); weight (1 + L_o) G2, L the
   anisotropic Lambda [Heitz14, Eq. 86] with the projected roughness
   sqrt(ax^2 cos^2 + ay^2 sin^2) (of -w for a transmitted w: the same);
   the lattice and warp of ar_albedo_lobes; lobes as there. (a function
   of its own: the isotropic code above stays as written; e <= 0 gives the
   conductor's bits of before the dielectric joined: F = 1 multiplies
   exactly.) */
static double ar_lambda_aniso(double ax, double ay, const double w[3])
{
    double t2 = (ax * ax * w[0] * w[0] + ay * ay * w[1] * w[1]) / (w[2] * w[2]);
    return 0.5 * (-1.0 + sqrt(1.0 + t2));
}
static double ar_albedo_aniso_lobes(double ax, double ay, double mu, double c, double e, int n, int lobes)
{
    double sx = sqrt(fmax(0.0, 1.0 - mu * mu)), wo[3], v[3], T1[3], T2[3], l, lo, acc = 0.0;
    long i, N = 2, G = 1;
    wo[0] = sx * sqrt(c); wo[1] = sx * sqrt(fmax(0.0, 1.0 - c)); wo[2] = mu;
    lo = ar_lambda_aniso(ax, ay, wo);
    v[0] = ax * wo[0]; v[1] = ay * wo[1]; v[2] = mu;
    l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= l; v[1] /= l; v[2] /= l;
    l = sqrt(v[0] * v[0] + v[1] * v[1]);
    if (l > 0.0) { T1[0] = -v[1] / l; T1[1] = v[0] / l; } else { T1[0] = 1.0; T1[1] = 0.0; }
    T1[2] = 0.0;
    T2[0] = v[1] * T1[2] - v[2] * T1[1]; T2[1] = v[2] * T1[0] - v[0] * T1[2]; T2[2] = v[0] * T1[1] - v[1] * T1[0];
    while (N < (long)n * n) { long t2 = N + G; G = N; N = t2; }
    for (i = 0; i < N; ++i) {
        double t = (i + 0.5) / N, omt = 1.0 - t, jac = 4.0 * omt * omt * omt;
        double u1 = 1.0 - omt * omt * omt * omt, u2 = fmod(fmod((double)i * G, (double)N) / N + 0.5 / N + 0.3183098861837907, 1.0);
        double r = sqrt(u1), ph = 2 * M_PI * u2, t1 = r * cos(ph), t2 = r * sin(ph), s = 0.5 * (1.0 + v[2]);
        double h[3], m[3], cm, wr[3], F = 1.0, ct = 0.0;
        int k;
        t2 = (1.0 - s) * sqrt(fmax(0.0, 1.0 - t1 * t1)) + s * t2;
        l = sqrt(fmax(0.0, 1.0 - t1 * t1 - t2 * t2));
        for (k = 0; k < 3; ++k) h[k] = t1 * T1[k] + t2 * T2[k] + l * v[k];
        m[0] = ax * h[0]; m[1] = ay * h[1]; m[2] = fmax(h[2], 0.0);
        cm = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        if (!(cm > 0.0)) continue;
        for (k = 0; k < 3; ++k) m[k] /= cm;
        cm = wo[0] * m[0] + wo[1] * m[1] + wo[2] * m[2];
        if (cm <= 0.0) continue;
        if (e > 0.0) F = ar_fresnel(cm, e, &ct);
        for (k = 0; k < 3; ++k) wr[k] = 2.0 * cm * m[k] - wo[k];
        if (wr[2] > 0.0 && (lobes & AR_REFL)) acc += jac * F * (1.0 + lo) / (1.0 + lo + ar_lambda_aniso(ax, ay, wr));
        if (F < 1.0 && (lobes & AR_TRANS)) { /* the refracted direction, mirrored up for its masking */
            double wt[3];
            for (k = 0; k < 3; ++k) wt[k] = wo[k] / e - (cm / e - ct) * m[k];
            if (wt[2] > 0.0) acc += jac * (1.0 - F) * (1.0 + lo) / (1.0 + lo + ar_lambda_aniso(ax, ay, wt));
        }
    }
    return acc / (double)N;
}
#define ar_albedo_aniso(ax, ay, mu, c, n) ar_albedo_aniso_lobes(ax, ay, mu, c, 0.0, n, AR_REFL)
#define ar_albedo_aniso_e(ax, ay, mu, c, e, n) ar_albedo_aniso_lobes(ax, ay, mu, c, e, n, AR_REFL | AR_TRANS)
#define ar_albedo_aniso_refl(ax, ay, mu, c, e, n) ar_albedo_aniso_lobes(ax, ay, mu, c, e, n, AR_REFL)
#endif
/* (macros, not functions: a user of one has no unused other) */
/* R + e^2 T (the dielectric's whole flux; F = 1 conductor for e <= 0) */
#define ar_albedo(beckmann, alpha, mu, e, n) ar_albedo_lobes(beckmann, alpha, mu, e, n, AR_REFL | AR_TRANS)
/* R alone: the reflection lobe of the dielectric, e > 0 (the coat's
   interface seen from outside, e >= 1: tests/gen/gen_coat_albedo.c) */
#define ar_albedo_refl(beckmann, alpha, mu, e, n) ar_albedo_lobes(beckmann, alpha, mu, e, n, AR_REFL)

/* Table layout shared by tests/gen/gen_albedo.c (which writes the tables)
   and tests/test_multiscatter.c (which checks them); the lookup code in
   appear.h inverts these axes. x = i / (n - 1). */
#define AR_C_MU 32 /* conductor */
#define AR_C_A 32
#define AR_O_MU 24 /* dielectric, wo in the lower-index medium (e >= 1; the conductor's axes) */
#define AR_O_A 20
#define AR_O_ETA 12
#define AR_I_MU 24 /* dielectric, wo in the higher-index medium (e <= 1) */
#define AR_I_A 20
#define AR_I_ETA 21
/* reflection alone (tests/gen/gen_coat_albedo.c), wo outside (e >= 1),
   the axes of AR_O_*: at alpha < 0.05 and mu < 0.15 (the shadowing's
   knee moves with alpha / mu) R bends sharply; 16 x 12 x 12 nodes miss
   it by up to 2e-2, these by up to 6e-3, 1.8e-3 elsewhere (mu >= 0.02) */
#define AR_R_MU 32
#define AR_R_A 40
#define AR_R_ETA 24
#ifndef AR_NO_NODES /* (a user of ar_albedo alone defines it: no unused functions) */
/* mu axis: x = (sqrt(mu) + mu) / 2 (nodes crowd toward grazing, where E
   changes fastest), inverted: sqrt(mu) = (sqrt(1 + 8 x) - 1) / 2 */
static double ar_node_mu(int i, int n) { double x = (double)i / (n - 1), r = 0.5 * (sqrt(1.0 + 8.0 * x) - 1.0); return r * r; }
static double ar_node_alpha(int j, int n) { double x = (double)j / (n - 1); return 2.0 * x * x; }
/* The conductor's table (AR_C_*) has axes of its own, read bicubically by appear.h: with v = mu
   or v = alpha / 2 in [0, 1], x = 0.3 r(v) + 0.7 s(v), r(v) = 1.01 v / (v + 0.01) (log-like: a
   node every ~15% of v down to v ~ 0.003, where the shadowing's knee at alpha ~ mu lies when
   both are small) and s(v) = (sqrt(v) + v) / 2 for mu, sqrt(v) for alpha (the old axes, which
   keep nodes at the large end). appear.h's appear__ec_cxmu / appear__ec_cxalpha compute x;
   here it is inverted by bisection (its users define AR_COND_NODES: no unused functions). */
#ifdef AR_COND_NODES
static double ar_cx(double v, int is_mu)
{
    return 0.3 * 1.01 * v / (v + 0.01) + 0.7 * (is_mu ? 0.5 * (sqrt(v) + v) : sqrt(v));
}
static double ar_cx_inv(double x, int is_mu)
{
    double lo = 0.0, hi = 1.0;
    int k;
    for (k = 0; k < 64; ++k) {
        double m = 0.5 * (lo + hi);
        if (ar_cx(m, is_mu) < x) lo = m; else hi = m;
    }
    return 0.5 * (lo + hi);
}
static double ar_node_cmu(int i, int n)
{
    return i ? (i == n - 1 ? 1.0 : ar_cx_inv((double)i / (n - 1), 1)) : 0.0;
}
static double ar_node_calpha(int j, int n)
{
    return j ? (j == n - 1 ? 2.0 : 2.0 * ar_cx_inv((double)j / (n - 1), 0)) : 0.0;
}
/* the dielectric's table from outside (AR_O_*) has the conductor's mu and alpha axes and e - 1 on
   the alpha axis (e in [1, 3]: nodes every ~15% of e - 1 down to ~0.006, where the transmission
   at grazing changes fastest) */
static double ar_node_ce_out(int k, int n) { return 1.0 + ar_node_calpha(k, n); }
#endif
#if !defined(AR_ANISO_ONLY) && !defined(AR_NO_E_OUT) /* (tests/gen/gen_albedo.c: unused there) */
static double ar_node_e_out(int k, int n) { double x = (double)k / (n - 1); return 1.0 + 2.0 * x * x; }
#endif
/* inside e axis: x = (w + sqrt(w)) / 2, w = 3 (1 - e) / 2 (nodes crowd
   toward e = 1, where the critical angle moves fastest with e; a user
   of the e >= 1 axes alone defines AR_NO_INSIDE_NODES) */
#ifdef AR_ANISO
/* the anisotropic conductor's table (tests/gen/gen_aniso_albedo.c): with a >= b the lobe's alphas
   along x and y and rho = b / a, its axes are alpha a (ar_node_alpha), rho with (sqrt(rho) + rho) /
   2 = x (node 0: 1e-6, the limit b -> 0 at fixed coordinates; AR_AN_RHO nodes in [0, 1] and one
   beyond, at x = 1 + 1 / (AR_AN_RHO - 1), rho ~ 1.19, which the cubic read of the last cell takes
   where it would extrapolate: E bends most there), and two coordinates of wo squashed along y by
   s = rho^(3/4), u = (wo.x, s wo.y, wo.z) / |.|: c = u.x^2 / (u.x^2 + u.y^2) = x (cos^2 of its
   azimuth; 1 where u.z = 1) and m = u.z on the conductor's mu axis (ar_node_cmu: crowded toward
   grazing and toward the shadowing's knee). The stretched direction (a wo.x, b wo.y, wo.z) of the
   tables up to the twenty-fourth session crowded wo's cosines into its last cell where a is
   small (at a = 0.24 its cosines 0.5 .. 1 lie within v.z 0.94 .. 1; 2.4e-3 error there) and its
   azimuths toward c = 1 where rho is moderate. The squash keeps resolution in both and at small
   rho still follows the smooth axis (on throwaway virtual tables, cubic in all four, 800 points
   of the test's distribution: s = rho^(3/4) erred at most 1.9e-3, mean 8.7e-5; s = sqrt(rho)
   1.4e-2 at grazing along the smooth axis of rho 0.08; s = rho 4.1e-3; the stretched axes
   2.9e-3, mean 3.9e-4). ar_node_aniso turns a node into wo's (mu, c). Requires
   AR_COND_NODES. */
#define AR_AN_MU 32
#define AR_AN_A 24
#define AR_AN_RHO 10
#define AR_AN_C 5
static double ar_node_rho(int k) /* k = 0 .. AR_AN_RHO (the last beyond 1) */
{
    double x = (double)k / (AR_AN_RHO - 1), r = 0.5 * (sqrt(1.0 + 8.0 * x) - 1.0); /* r = sqrt(rho) */
    return k ? r * r : 1e-6;
}
static void ar_node_aniso(double a, int k, int l, int i, double *mu, double *c)
{
    double s = pow(ar_node_rho(k), 0.75), m = ar_node_cmu(i, AR_AN_MU), cu = (double)l / (AR_AN_C - 1), su, x, y, q;
    (void)a; /* (the coordinates do not depend on the alpha) */
    m = m < 1e-4 ? 1e-4 : m;
    su = sqrt(fmax(0.0, 1.0 - m * m));
    x = su * sqrt(cu);
    y = su * sqrt(1.0 - cu) / s;
    q = x * x + y * y;
    *mu = m / sqrt(q + m * m);
    *c = q > 0.0 ? x * x / q : 1.0;
}
/* the anisotropic dielectric's table (tests/gen/gen_aniso_dielectric.c): the factor K that
   carries appear.h's isotropic albedo, read at wo's projected roughness, over to the anisotropic
   lobe; axes in wo's own coordinates (the stretched ones of the conductor's table crowd every
   node toward normal incidence where b is small, and the Fresnel factors see wo's true angle):
   mu = wo.z (ar_node_mu), the azimuth's |cos| from the rougher axis = x (AR_AD_C; inside,
   piecewise linear with a knee, ar_node_ad_cx), rho = b / a =
   x^2 (node 0: 1e-6), alpha a (ar_node_alpha), e: AR_AD_EO nodes e = 1 + 2 x^2 (outside, as
   ar_node_e_out), then AR_AD_EI nodes of ar_node_e_in's axis (inside); then AR_AD_EO nodes of
   the outside axis again for the reflection alone (R, over appear.h's coat table's R).
   Node counts (twenty-fifth session), chosen on virtual tables (K exact at the nodes, read
   5-linearly; 200 random points, alpha 0.05..1.5, b / a uniform, eta 1.1..2.5, both sides):
   6 alpha and 4 outside e nodes erred up to 0.062 (mean 2.6e-3), 5 e 0.023 (1.5e-3), 7 alpha and
   5 e 0.017 (1.4e-3: these). 8 inside e nodes moved the worst point of OpenPBR's strong-anisotropy
   glass (b / a 0.1, inside, mu 0.1, 45 degrees) from 0.026 to 0.039; 13 azimuth, 9 rho or 14 mu
   nodes left it within 20%; an azimuth squashed by rho^p as the conductor's (p 0.25 .. 0.75) read
   0.36 at anisotropy 1 on this rho axis. The block of R alone has AR_AD_RRHO rho nodes of its
   own (twenty-seventh session): along the smoother axis at mu ~ 0.3, where R of a strong
   anisotropy is 3-6 times its value at normal incidence, K falls 1.06 -> 0.86 between rho 0.02
   and 0.3, which 6 nodes cut short (R 1.8e-3 low at b / a 0.1; appear.h reads it with a cubic
   along mu as well), and AR_AD_RMU mu nodes (12: mu 0.03 falls in an inner cell, read cubic). */
#define AR_AD_MU 10
#define AR_AD_C 9
#define AR_AD_RHO 6
#define AR_AD_RRHO 7
#define AR_AD_RMU 12
#define AR_AD_A 7
#define AR_AD_EO 5
#define AR_AD_EI 6
#ifdef AR_ANISO_DIEL
/* rho node k of n (AR_AD_RHO for E, AR_AD_RRHO for R) */
static double ar_node_ad_rho(int k, int n) { double x = (double)k / (n - 1); return k ? x * x : 1e-6; }
static double ar_node_ad_e(int k)
{
    double x, r;
    if (k >= AR_AD_EO + AR_AD_EI) k -= AR_AD_EO + AR_AD_EI; /* R alone: the outside axis */
    if (k < AR_AD_EO) { x = (double)k / (AR_AD_EO - 1); return 1.0 + 2.0 * x * x; }
    x = (double)(k - AR_AD_EO) / (AR_AD_EI - 1); r = 0.5 * (sqrt(1.0 + 8.0 * x) - 1.0);
    return 1.0 - r * r / 1.5;
}
/* the azimuth's node l as |cos| from the a axis: outside, l / (AR_AD_C - 1); inside, the inverse of
   appear.h's appear__ad_c_in at (mu, e) (its knee, where wy^2 = e^2, on c = APPEAR__AD_CK) */
static double ar_node_ad_cx(int l, double mu, double e, int in)
{
    double c = (double)l / (AR_AD_C - 1), x;
    if (!in) return c;
    x = appear__ad_knee((float)(1.0 - mu * mu), (float)e);
    if (c <= APPEAR__AD_CK) return x * c / APPEAR__AD_CK;
    return x + (c - APPEAR__AD_CK) / (1.0 - APPEAR__AD_CK) * (1.0 - x);
}
#endif
#endif
#ifndef AR_NO_INSIDE_NODES
static double ar_node_e_in(int k, int n) { double x = (double)k / (n - 1), r = 0.5 * (sqrt(1.0 + 8.0 * x) - 1.0); return 1.0 - r * r / 1.5; }
#endif
#endif
#endif
