/* tests/test_microfacet.c - GGX and Beckmann distributions, Smith masking,
   visible-normal samplers, Fresnel, rough conductor and rough dielectric.

   Second forms used as references (all in double, written from the papers
   independently of the header's float code):
     D, Lambda with tan(theta) [Walter07 Eq. 27/33, Heitz14 Eq. 83/86],
     Beckmann Lambda with libm erfc, dielectric Fresnel through cos_t,
     conductor Fresnel with C99 complex arithmetic.
   The rough conductor's and dielectric's chi-square, pdf integral, sample
   consistency, furnace, reciprocity (eta^2 rule) and adversarial inputs
   are rows of tests/test_models.c; the normal samplers' chi-square runs in
   the battery's domain (tests/battery.h bt_chi2_domain). */
#include "battery.h"
#include <complex.h>
#undef I /* the complex unit is spelt _Complex_I below */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI_D 3.14159265358979323846

#ifndef APPEAR_NO_MICROFACET

static const float g_alphas[] = { 1e-4f, 1e-3f, 0.01f, 0.05f, 0.125f, 0.5f, 1.0f, 1.5f, 2.0f };
static const float g_cos[] = { 1.0f, 0.5f, 1e-2f, 1e-4f, 1e-6f, 0.0f };
#define NA ((int)(sizeof g_alphas / sizeof g_alphas[0]))
#define NC ((int)(sizeof g_cos / sizeof g_cos[0]))
static const float g_aniso[][2] = { { 0.2f, 0.05f }, { 0.05f, 0.6f } };
static const float g_etas[] = { 1.0f / 2.4f, 1.0f / 1.5f, 1.0f / 1.0001f, 1.0f, 1.0001f, 1.5f, 2.4f };
#define NE ((int)(sizeof g_etas / sizeof g_etas[0]))

/* wo at cos theta = c, azimuth phi (float, unit) */
static appear_vec3 dir_cos(float c, double phi)
{
    double s = sqrt(fmax(0.0, 1.0 - (double)c * c));
    return appear_vec3_make((float)(s * cos(phi)), (float)(s * sin(phi)), c);
}

/* ------------------------------------------------------------------------ */
/* Double references                                                         */
/* ------------------------------------------------------------------------ */

static double ggx_D_d(double ax, double ay, appear_vec3 m)
{
    double x = m.x, y = m.y, z = m.z, c2, t2;
    if (z <= 0) return 0;
    c2 = z * z;
    t2 = (x * x / (ax * ax) + y * y / (ay * ay)) / c2; /* tan^2 theta (cos^2 phi/ax^2 + sin^2 phi/ay^2) */
    return 1.0 / (PI_D * ax * ay * c2 * c2 * (1 + t2) * (1 + t2));
}
static double beck_D_d(double ax, double ay, appear_vec3 m)
{
    double x = m.x, y = m.y, z = m.z, c2, t2;
    if (z <= 0) return 0;
    c2 = z * z;
    t2 = (x * x / (ax * ax) + y * y / (ay * ay)) / c2;
    return exp(-t2) / (PI_D * ax * ay * c2 * c2);
}
static double ggx_lambda_d(double ax, double ay, appear_vec3 w)
{
    double z2 = (double)w.z * w.z, a2t2 = (ax * ax * w.x * w.x + ay * ay * w.y * w.y) / z2;
    return (-1.0 + sqrt(1.0 + a2t2)) / 2.0;
}
static double beck_lambda_d(double ax, double ay, appear_vec3 w)
{
    double a = fabs((double)w.z) / sqrt(ax * ax * w.x * w.x + ay * ay * w.y * w.y);
    if (a > 25) return 0;
    return (exp(-a * a) / (a * sqrt(PI_D)) - erfc(a)) / 2.0;
}
static double fresnel_cond_d(double c, double eta, double k)
{
    double complex n = eta + _Complex_I * k, ct, rs, rp;
    double s2 = 1 - c * c;
    ct = csqrt(1.0 - s2 / (n * n));
    rs = (c - n * ct) / (c + n * ct);
    rp = (n * c - ct) / (n * c + ct);
    return 0.5 * (creal(rs * conj(rs)) + creal(rp * conj(rp)));
}

/* ------------------------------------------------------------------------ */
/* The normal samplers behind one interface (for chi2)                       */
/* ------------------------------------------------------------------------ */

enum { K_GGX_VIS, K_BECK_VIS, K_GGX_FULL, K_BECK_FULL };
typedef struct { int kind; float ax, ay; appear_vec3 wo; } mctx;

static int raw_sample(void *ctx, float uc, float u1, float u2, appear_vec3 *w)
{
    mctx *m = (mctx *)ctx;
    (void)uc;
    switch (m->kind) {
    case K_GGX_VIS: *w = appear_ggx_sample_visible(m->ax, m->ay, m->wo, u1, u2); break;
    case K_BECK_VIS: *w = appear_beckmann_sample_visible(m->ax, m->ay, m->wo, u1, u2); break;
    case K_GGX_FULL: *w = appear_ggx_sample_D(m->ax, m->ay, u1, u2); break;
    default: *w = appear_beckmann_sample_D(m->ax, m->ay, u1, u2); break;
    }
    return w->z > 0;
}
static double raw_pdf(void *ctx, appear_vec3 w)
{
    mctx *m = (mctx *)ctx;
    switch (m->kind) {
    case K_GGX_VIS: return appear_ggx_pdf_visible(m->ax, m->ay, m->wo, w);
    case K_BECK_VIS: return appear_beckmann_pdf_visible(m->ax, m->ay, m->wo, w);
    case K_GGX_FULL: return appear_ggx_pdf_D(m->ax, m->ay, w);
    default: return appear_beckmann_pdf_D(m->ax, m->ay, w);
    }
}
/* chi2 in the domain of a pilot run (narrow lobes magnified), 16 x 32 bins,
   250000 samples; quick (sanitizer) mode: every 6th */
static void run_chi2(mctx *m, const char *name)
{
    bt_chi2_domain(name, raw_sample, raw_pdf, m, 250000, 16, 32, 0, 6);
}

/* ------------------------------------------------------------------------ */
/* Suite 1: distributions and masking                                        */
/* ------------------------------------------------------------------------ */

typedef struct { int beck; float ax, ay; appear_vec3 wo; } vctx;
static double vndf_fn(void *ctx, appear_vec3 m)
{
    vctx *v = (vctx *)ctx;
    return v->beck ? appear_beckmann_pdf_visible(v->ax, v->ay, v->wo, m) : appear_ggx_pdf_visible(v->ax, v->ay, v->wo, m);
}
static double dcos_fn(void *ctx, appear_vec3 m)
{
    vctx *v = (vctx *)ctx;
    return v->beck ? appear_beckmann_pdf_D(v->ax, v->ay, m) : appear_ggx_pdf_D(v->ax, v->ay, m);
}

void suite_microfacet_distributions(void)
{
    h_rng r = h_rng_make(31);
    long i, n = h_n(400000);
    int a, c, b;
    double worst;

    h_case("GGX and Beckmann D, Lambda, G1 against double references (float vs double)");
    {
        h_err eD[2] = { h_err_make("ggx_D"), h_err_make("beckmann_D") };
        h_err eL[2] = { h_err_make("ggx_lambda"), h_err_make("beckmann_lambda (exact, erfc)") };
        h_err eG[2] = { h_err_make("ggx_G1"), h_err_make("beckmann_G1") };
        h_err eF = h_err_make("beckmann_lambda_fast (Walter07 fit) as G1");
        for (i = 0; i < n; ++i) {
            float ax = g_alphas[i % NA], ay = (i & 1) ? ax : g_alphas[(i / NA) % NA];
            appear_vec3 w = h_rand_dir(&r);
            double dref, lref;
            if (ay < 1e-3f && ax > 0.1f) ay = 1e-3f; /* avoid D overflow of float in ridges */
            w.z = fabsf(w.z);
            for (b = 0; b < 2; ++b) {
                float D = b ? appear_beckmann_D(ax, ay, w) : appear_ggx_D(ax, ay, w);
                float L = b ? appear_beckmann_lambda(ax, ay, w) : appear_ggx_lambda(ax, ay, w);
                float G = b ? appear_beckmann_G1(ax, ay, w, appear_vec3_make(0, 0, 1)) : appear_ggx_G1(ax, ay, w, appear_vec3_make(0, 0, 1));
                dref = b ? beck_D_d(ax, ay, w) : ggx_D_d(ax, ay, w);
                lref = b ? beck_lambda_d(ax, ay, w) : ggx_lambda_d(ax, ay, w);
                if (dref > 1e-30 && dref < 1e30) h_err_add(&eD[b], D, dref, 1e-30);
                if (lref < 1e30) h_err_add(&eL[b], L, lref, 1.0);
                h_err_add(&eG[b], G, 1.0 / (1.0 + lref), 1e-30);
                if (b) h_err_add(&eF, 1.0 / (1.0 + appear_beckmann_lambda_fast(ax, ay, w)), 1.0 / (1.0 + lref), 1.0);
            }
        }
        for (b = 0; b < 2; ++b) {
            H_CHECK(eD[b].max_rel < 2e-4, "%s max rel err %.3g at ref %.6g", eD[b].name, eD[b].max_rel, eD[b].at_ref);
            H_CHECK(eL[b].max_rel < 1e-5, "%s max err (rel, floor 1) %.3g at ref %.6g", eL[b].name, eL[b].max_rel, eL[b].at_ref);
            H_CHECK(eG[b].max_rel < 1e-5, "%s max rel err %.3g at ref %.6g", eG[b].name, eG[b].max_rel, eG[b].at_ref);
            h_err_report(&eD[b]); h_err_report(&eL[b]); h_err_report(&eG[b]);
        }
        H_CHECK(eF.max_abs < 5e-3, "fast Lambda G1 abs err %.3g", eF.max_abs);
        h_err_report(&eF);
    }

    h_case("Beckmann Lambda: relative accuracy in the far tail (continued fraction, a >= 2.5)");
    {
        h_err e = h_err_make("beckmann_lambda tail a in [2.5, 9]");
        for (i = 0; i < 2000; ++i) {
            double aa = 2.5 + 6.5 * i / 1999.0, th = atan(1.0 / (0.5 * aa));
            appear_vec3 w = appear_vec3_make((float)sin(th), 0, (float)cos(th));
            double ref = beck_lambda_d(0.5, 0.5, w);
            h_err_add(&e, appear_beckmann_lambda(0.5f, 0.5f, w), ref, 1e-37);
        }
        H_CHECK(e.max_rel < 2e-5, "tail rel err %.3g at %.6g", e.max_rel, e.at_ref);
        h_err_report(&e);
    }

    h_case("grazing limits: G1 -> 0 as cos -> 0, Lambda finite, D finite at tiny alpha");
    for (a = 0; a < NA; ++a)
        for (b = 0; b < 2; ++b) {
            float al = g_alphas[a];
            appear_vec3 g0 = appear_vec3_make(1, 0, 0), g1 = appear_normalize(appear_vec3_make(1, 0, 1e-7f));
            appear_vec3 zz = appear_vec3_make(0, 0, 1);
            float G0 = b ? appear_beckmann_G1(al, al, g0, zz) : appear_ggx_G1(al, al, g0, zz);
            float G1v = b ? appear_beckmann_G1(al, al, g1, appear_normalize(appear_vec3_make(0.5f, 0, 1))) : appear_ggx_G1(al, al, g1, appear_normalize(appear_vec3_make(0.5f, 0, 1)));
            float L0 = b ? appear_beckmann_lambda(al, al, g0) : appear_ggx_lambda(al, al, g0);
            float Dz = b ? appear_beckmann_D(al, al, zz) : appear_ggx_D(al, al, zz);
            float Dg = b ? appear_beckmann_D(al, al, g0) : appear_ggx_D(al, al, g0);
            H_CHECK(G0 == 0.0f && G1v >= 0.0f && G1v < 4e-7f / al, "%s alpha %g: G1(grazing) %g, G1(1e-7) %g",
                    b ? "beckmann" : "ggx", al, G0, G1v);
            H_CHECK(H_OK_VALUE(L0) && H_OK_VALUE(Dz) && Dz > 0 && Dg == 0.0f, "%s alpha %g: Lambda %g D(z) %g D(grazing) %g",
                    b ? "beckmann" : "ggx", al, L0, Dz, Dg);
        }

    h_case("weak white furnace [Heitz14]: integral of D_wo(m) dm = 1 (grid of alpha, cos, anisotropy), and of D(m) m.z dm = 1");
    worst = 0;
    for (b = 0; b < 2; ++b)
        for (a = 0; a < NA + 2; ++a)
            for (c = 0; c < NC - 1; ++c) {
                vctx v;
                double I, J;
                if (h_quick() && (a + c) % 4) continue;
                v.beck = b;
                v.ax = a < NA ? g_alphas[a] : g_aniso[a - NA][0];
                v.ay = a < NA ? g_alphas[a] : g_aniso[a - NA][1];
                v.wo = dir_cos(g_cos[c], 0.7);
                I = h_integrate_sphere(vndf_fn, &v, appear_vec3_make(0, 0, 1), 1e-5);
                H_CHECK(fabs(I - 1) < 1e-3, "%s (%g, %g) cos %g: integral D_wo = %.6f", b ? "beckmann" : "ggx", v.ax, v.ay, g_cos[c], I);
                worst = fmax(worst, fabs(I - 1));
                if (c == 0) {
                    J = h_integrate_sphere(dcos_fn, &v, appear_vec3_make(0, 0, 1), 1e-5);
                    H_CHECK(fabs(J - 1) < 1e-3, "%s (%g, %g): integral D cos = %.6f", b ? "beckmann" : "ggx", v.ax, v.ay, J);
                }
            }
    h_measure("weak white furnace", "max |integral D_wo - 1| = %.3g over GGX+Beckmann, 11 alphas x 5 cos", worst);

    h_case("G2 height-correlated: symmetric, <= min(G1o, G1i), >= G1o G1i, side tests");
    worst = 0;
    for (i = 0; i < 100000; ++i) {
        float al = g_alphas[i % NA];
        appear_vec3 wo = h_rand_dir(&r), wi = h_rand_dir(&r), m = appear_vec3_make(0, 0, 1);
        wo.z = fabsf(wo.z); wi.z = fabsf(wi.z);
        for (b = 0; b < 2; ++b) {
            float g2 = b ? appear_beckmann_G2(al, al, wo, wi, m) : appear_ggx_G2(al, al, wo, wi, m);
            float g2s = b ? appear_beckmann_G2(al, al, wi, wo, m) : appear_ggx_G2(al, al, wi, wo, m);
            float go = b ? appear_beckmann_G1(al, al, wo, m) : appear_ggx_G1(al, al, wo, m);
            float gi = b ? appear_beckmann_G1(al, al, wi, m) : appear_ggx_G1(al, al, wi, m);
            /* G2 = 1/(1/Go + 1/Gi - 1) */
            double ref = go > 0 && gi > 0 ? 1.0 / (1.0 / go + 1.0 / gi - 1.0) : 0.0;
            worst = fmax(worst, fabs(g2 - ref));
            H_CHECK(g2 == g2s && g2 <= fminf(go, gi) + 1e-6f && g2 >= go * gi - 1e-6f, "G2 %g G2swap %g G1o %g G1i %g", g2, g2s, go, gi);
        }
    }
    H_CHECK(worst < 1e-5, "G2 vs 1/(1/G1o + 1/G1i - 1): %.3g", worst);
    {
        appear_vec3 wo = appear_normalize(appear_vec3_make(0.9f, 0, 0.3f)), m = appear_normalize(appear_vec3_make(-0.9f, 0, 0.2f));
        H_CHECK(appear_ggx_G1(0.5f, 0.5f, wo, m) == 0.0f && appear_beckmann_G1(0.5f, 0.5f, wo, m) == 0.0f, "back-facing m must be masked");
    }

    h_case("visible-normal samplers: chi-square against pdf_visible / D cos (narrow lobes magnified)");
    {
        static const float al[] = { 1e-3f, 0.05f, 0.5f, 1.5f };
        static const float cs[] = { 1.0f, 0.5f, 1e-2f, 1e-6f };
        char name[128];
        int k;
        for (k = 0; k < 2; ++k)
            for (a = 0; a < 6; ++a)
                for (c = 0; c < 4; ++c) {
                    mctx m;
                    if ((a < 4 && (a + c) % 2) || (a >= 4 && c != 1 && c != 2)) continue; /* a lattice through the grid */
                    memset(&m, 0, sizeof m);
                    m.kind = k ? K_BECK_VIS : K_GGX_VIS;
                    m.ax = a < 4 ? al[a] : g_aniso[a - 4][0];
                    m.ay = a < 4 ? al[a] : g_aniso[a - 4][1];
                    m.wo = dir_cos(cs[c], 0.3);
                    snprintf(name, sizeof name, "%s_vis_a%g_%g_c%g", k ? "beckmann" : "ggx", m.ax, m.ay, cs[c]);
                    run_chi2(&m, name);
                }
        for (k = 0; k < 2; ++k)
            for (a = 0; a < 3; ++a) {
                mctx m;
                static const float fa[][2] = { { 0.01f, 0.01f }, { 0.5f, 0.5f }, { 0.2f, 0.05f } };
                memset(&m, 0, sizeof m);
                m.kind = k ? K_BECK_FULL : K_GGX_FULL;
                m.ax = fa[a][0]; m.ay = fa[a][1];
                m.wo = appear_vec3_make(0, 0, 1);
                snprintf(name, sizeof name, "%s_fullD_a%g_%g", k ? "beckmann" : "ggx", m.ax, m.ay);
                run_chi2(&m, name);
            }
    }

    h_case("Beckmann visible sampler robust at low roughness, cos -> 1 and grazing (no NaN, m.z > 0)");
    {
        long bad = 0;
        static const float cs[] = { 1.0f, 0.99999994f, 0.9999999f, 0.5f, 1e-6f, 1e-30f };
        for (a = 0; a < NA; ++a)
            for (c = 0; c < 6; ++c)
                for (i = 0; i < 2000; ++i) {
                    float u1 = (i == 0) ? 0.0f : (i == 1) ? 1.0f : (i == 2) ? 0.99999994f : h_randf(&r);
                    float u2 = (i == 3) ? 0.0f : (i == 4) ? 1.0f : h_randf(&r);
                    appear_vec3 m = appear_beckmann_sample_visible(g_alphas[a], g_alphas[a], dir_cos(cs[c], 1.1), u1, u2);
                    appear_vec3 mg = appear_ggx_sample_visible(g_alphas[a], g_alphas[a], dir_cos(cs[c], 1.1), u1, u2);
                    if (!(m.z > 0 && appear_is_unit(m))) ++bad;
                    if (!(mg.z > 0 && appear_is_unit(mg)) && !(mg.x == 0 && mg.y == 0 && mg.z == 0)) ++bad;
                }
        H_CHECK(bad == 0, "%ld bad normals", bad);
    }
}

/* ------------------------------------------------------------------------ */
/* Suite 2: Fresnel                                                          */
/* ------------------------------------------------------------------------ */

void suite_microfacet_fresnel(void)
{
    h_rng r = h_rng_make(5);
    long i, n = h_n(400000);
    int e;

    h_case("dielectric Fresnel against the cos_t form in double, both sides, every eta of the grid");
    {
        h_err er = h_err_make("fresnel_dielectric");
        h_err en = h_err_make("fresnel_dielectric eta = 1.0001 (relative)");
        for (i = 0; i < n; ++i) {
            float eta = g_etas[i % NE], c = (float)(2 * h_rand(&r) - 1);
            double ref = h_fresnel_dielectric(c, eta);
            float f = appear_fresnel_dielectric(c, eta);
            h_err_add(&er, f, ref, 1e-3);
            if (eta == 1.0001f || eta == 1.0f / 1.0001f) h_err_add(&en, f, ref, 1e-30);
        }
        /* F has an infinite slope at the critical angle: rounding c^2 in float
           moves F there by up to ~1e-4; elsewhere the error is ~1e-7 */
        H_CHECK(er.max_abs < 1.5e-4, "max abs err %.3g", er.max_abs);
        H_CHECK(en.max_rel < 1e-3, "eta ~ 1: relative error %.3g at ref %.3g (cancellation?)", en.max_rel, en.at_ref);
        h_err_report(&er); h_err_report(&en);
    }
    h_case("dielectric Fresnel limits: eta = 1 -> 0, TIR -> 1 (from inside), grazing -> 1, normal ((e-1)/(e+1))^2");
    for (e = 0; e < NE; ++e) {
        float eta = g_etas[e];
        float f0 = appear_fresnel_dielectric(1.0f, eta), fg = appear_fresnel_dielectric(0.0f, eta);
        double r0 = (eta - 1.0) / (eta + 1.0);
        H_CHECK(fabs(f0 - r0 * r0) < 1e-7 + 1e-5 * r0 * r0, "eta %g normal %g vs %g", eta, f0, r0 * r0);
        H_CHECK(eta == 1.0f ? fg == 0.0f : fg == 1.0f, "eta %g grazing %g", eta, fg);
        if (eta > 1.0f) {
            float ct = sqrtf(1 - 1 / (eta * eta)); /* critical cos from inside */
            H_CHECK(appear_fresnel_dielectric(-ct * 0.999f, eta) == 1.0f && appear_fresnel_dielectric(-fminf(1.0f, ct * 1.01f), eta) < 1.0f,
                    "TIR boundary for eta %g", eta);
            H_CHECK(fabsf(appear_fresnel_dielectric(-0.3f, eta) - appear_fresnel_dielectric(0.3f, 1.0f / eta)) < 1e-7f, "sides");
        }
    }
    h_case("conductor Fresnel against complex arithmetic (gold, aluminium, k = 0 dielectric, random)");
    {
        h_err ec = h_err_make("fresnel_conductor");
        static const float mat[][2] = { { 0.143f, 3.983f }, { 0.374f, 2.386f }, { 1.442f, 1.603f }, /* gold RGB */
                                        { 1.657f, 9.224f }, { 0.880f, 6.270f }, { 0.521f, 4.837f }, /* aluminium */
                                        { 1.5f, 0.0f }, { 1.0f, 0.0f }, { 0.0f, 0.0f } };
        for (i = 0; i < n; ++i) {
            int k = (int)(i % 10);
            float eta = k < 9 ? mat[k][0] : (float)(4 * h_rand(&r)), kk = k < 9 ? mat[k][1] : (float)(10 * h_rand(&r));
            float c = (float)h_rand(&r);
            if (eta == 0 && kk == 0) continue;
            h_err_add(&ec, appear_fresnel_conductor(c, eta, kk), fresnel_cond_d(c, eta, kk), 1e-3);
        }
        H_CHECK(ec.max_abs < 2e-6, "max abs err %.3g at ref %.6g", ec.max_abs, ec.at_ref);
        h_err_report(&ec);
        H_CHECK(fabsf(appear_fresnel_conductor(0.3f, 1.5f, 0.0f) - appear_fresnel_dielectric(0.3f, 1.5f)) < 1e-6f, "k = 0 vs dielectric");
        H_CHECK(appear_fresnel_conductor(0.0f, 0.2f, 3.0f) == 1.0f, "grazing conductor %g", appear_fresnel_conductor(0.0f, 0.2f, 3.0f));
    }
    h_case("Schlick and F82-tint: F(1) = F0, F(0) = 1, F82(1/7) = tint * Schlick(1/7), in [0,1]");
    for (i = 0; i < 2000; ++i) {
        float f0 = (float)h_rand(&r), tint = (float)h_rand(&r);
        float b = appear_fresnel_f82_coef(f0, tint);
        float s = appear_fresnel_schlick(1.0f / 7.0f, f0), f = appear_fresnel_f82(1.0f / 7.0f, f0, b);
        float c = (float)h_rand(&r), fc = appear_fresnel_f82(c, f0, b);
        H_CHECK(fabsf(f - tint * s) < 2e-6f, "f0 %g tint %g: F82 %g vs %g", f0, tint, f, tint * s);
        H_CHECK(fabsf(appear_fresnel_f82(1.0f, f0, b) - f0) < 1e-6f && appear_fresnel_f82(0.0f, f0, b) == 1.0f, "ends");
        H_CHECK(fc >= 0 && fc <= 1, "range %g", fc);
    }
}

/* ------------------------------------------------------------------------ */
/* Suite 3: models                                                           */
/* ------------------------------------------------------------------------ */

static appear_conductor gold(appear_microfacet d)
{
    return appear_conductor_make(d, appear_spectrum_rgb(0.143f, 0.374f, 1.442f), appear_spectrum_rgb(3.983f, 2.386f, 1.603f));
}
void suite_microfacet_models(void)
{
    h_rng r = h_rng_make(77);
    int a, c, t;
    long i;

    h_case("conductor and dielectric eval against Walter07 Eq. 20/21 written in double (float vs double)");
    {
        h_err ec[2] = { h_err_make("conductor eval ggx (gold, green)"), h_err_make("conductor eval beckmann (gold, green)") };
        h_err ed = h_err_make("dielectric eval ggx eta 1.5, wo outside (R and T)");
        for (i = 0; i < h_n(200000); ++i) {
            float al = g_alphas[3 + i % 6];
            appear_vec3 wo = h_rand_dir(&r), wi = h_rand_dir(&r);
            double hv[3], l, h3[3], D, Lo, Li, G2, F, ref;
            appear_vec3 hf;
            int k;
            wo.z = fabsf(wo.z); wi.z = fabsf(wi.z);
            if (wo.z < 1e-3f || wi.z < 1e-3f) continue;
            for (t = 0; t < 2; ++t) {
                appear_conductor cg = gold(appear_microfacet_make(t ? APPEAR_BECKMANN : APPEAR_GGX, al, al, APPEAR_SAMPLE_VISIBLE));
                hv[0] = (double)wo.x + wi.x; hv[1] = (double)wo.y + wi.y; hv[2] = (double)wo.z + wi.z;
                l = sqrt(hv[0] * hv[0] + hv[1] * hv[1] + hv[2] * hv[2]);
                for (k = 0; k < 3; ++k) h3[k] = hv[k] / l;
                hf = appear_vec3_make((float)h3[0], (float)h3[1], (float)h3[2]);
                D = t ? beck_D_d(al, al, hf) : ggx_D_d(al, al, hf);
                Lo = t ? beck_lambda_d(al, al, wo) : ggx_lambda_d(al, al, wo);
                Li = t ? beck_lambda_d(al, al, wi) : ggx_lambda_d(al, al, wi);
                G2 = 1.0 / (1.0 + Lo + Li);
                F = fresnel_cond_d(0.5 * l, 0.374, 2.386);
                ref = F * D * G2 / (4.0 * wo.z * wi.z);
                if (ref > 1e-6) h_err_add(&ec[t], appear_conductor_eval(&cg, wo, wi).v[1], ref, 1e-30);
            }
            {   /* dielectric, wo outside, wi on either side */
                appear_dielectric de = appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, al, al, APPEAR_SAMPLE_VISIBLE), 1.5f);
                double e = 1.5, oh, ih, den;
                appear_vec3 wt = (i & 1) ? appear_vec3_make(wi.x, wi.y, -wi.z) : wi;
                if (wt.z > 0) { hv[0] = (double)wo.x + wt.x; hv[1] = (double)wo.y + wt.y; hv[2] = (double)wo.z + wt.z; }
                else { hv[0] = wo.x + e * wt.x; hv[1] = wo.y + e * wt.y; hv[2] = wo.z + e * wt.z; }
                l = sqrt(hv[0] * hv[0] + hv[1] * hv[1] + hv[2] * hv[2]);
                for (k = 0; k < 3; ++k) h3[k] = (hv[2] < 0 ? -hv[k] : hv[k]) / l;
                hf = appear_vec3_make((float)h3[0], (float)h3[1], (float)h3[2]);
                oh = wo.x * h3[0] + wo.y * h3[1] + wo.z * h3[2];
                ih = wt.x * h3[0] + wt.y * h3[1] + wt.z * h3[2];
                D = ggx_D_d(al, al, hf);
                G2 = 1.0 / (1.0 + ggx_lambda_d(al, al, wo) + ggx_lambda_d(al, al, wt));
                F = h_fresnel_dielectric(oh, e);
                if (wt.z > 0) ref = F * D * G2 / (4.0 * wo.z * wt.z);
                else {
                    den = oh + e * ih;
                    ref = (oh > 0 && ih < 0) ? (1 - F) * D * G2 * fabs(ih) * fabs(oh) / (wo.z * fabs(wt.z) * den * den) : 0.0;
                }
                if (ref > 1e-6 && l > 0.05) h_err_add(&ed, appear_dielectric_eval(&de, wo, wt).v[0], ref, 1e-30);
            }
        }
        for (t = 0; t < 2; ++t) {
            H_CHECK(ec[t].max_rel < 1e-3, "%s: max rel err %.3g at ref %.6g", ec[t].name, ec[t].max_rel, ec[t].at_ref);
            h_err_report(&ec[t]);
        }
        H_CHECK(ed.max_rel < 1e-3, "%s: max rel err %.3g at ref %.6g", ed.name, ed.max_rel, ed.at_ref);
        h_err_report(&ed);
    }

    h_case("bounded VNDF [ET23] wastes fewer samples below the horizon than spherical caps (grazing, rough)");
    {
        static const float al[] = { 0.3f, 0.6f, 1.0f };
        static const float cs[] = { 0.05f, 0.2f, 0.5f };
        for (a = 0; a < 3; ++a)
            for (c = 0; c < 3; ++c) {
                appear_conductor v = gold(appear_microfacet_make(APPEAR_GGX, al[a], al[a], APPEAR_SAMPLE_VISIBLE));
                appear_conductor b = gold(appear_microfacet_make(APPEAR_GGX, al[a], al[a], APPEAR_SAMPLE_BOUNDED));
                appear_vec3 wo = dir_cos(cs[c], 0.3);
                long nv = 0, nb = 0, nn = h_n(100000);
                h_rng q = h_rng_make(8);
                for (i = 0; i < nn; ++i) {
                    appear_bsdf_record s;
                    float u1 = h_randf(&q), u2 = h_randf(&q);
                    nv += appear_conductor_sample(&v, wo, 0.5f, u1, u2, &s);
                    nb += appear_conductor_sample(&b, wo, 0.5f, u1, u2, &s);
                }
                H_CHECK(nb >= nv, "alpha %g cos %g: bounded success %ld < caps %ld", al[a], cs[c], nb, nv);
                if (a == 1 && c == 0)
                    h_measure("bounded VNDF", "alpha 0.6 cos 0.05: success fraction %.4f (caps %.4f)", (double)nb / nn, (double)nv / nn);
            }
    }

    h_case("conductor smooth limit: alpha < 1e-4 is a mirror delta with weight F, eval = pdf = 0");
    {
        appear_conductor cg = gold(appear_microfacet_make(APPEAR_GGX, 0.0f, 5e-5f, APPEAR_SAMPLE_VISIBLE));
        appear_bsdf_record s;
        appear_vec3 wo = dir_cos(0.3f, 1.0);
        int ok = appear_conductor_sample(&cg, wo, 0.3f, 0.2f, 0.9f, &s);
        float F = appear_fresnel_conductor(0.3f, 0.143f, 3.983f);
        H_CHECK(ok && (s.flags & APPEAR_LOBE_SPECULAR) && s.pdf == 1.0f && fabsf(s.weight.v[0] - F) < 1e-6f &&
                    s.wi.x == -wo.x && s.wi.y == -wo.y && s.wi.z == wo.z,
                "smooth sample: ok %d flags %u weight %g (F %g)", ok, s.flags, s.weight.v[0], F);
        H_CHECK(appear_conductor_eval(&cg, wo, s.wi).v[0] == 0.0f && appear_conductor_pdf(&cg, wo, s.wi) == 0.0f, "delta eval/pdf must be 0");
    }

    h_case("thin dielectric: R = 2F/(1+F) by frequency, T straight through, weight 1");
    {
        appear_thin_dielectric th = appear_thin_dielectric_make(1.5f);
        appear_vec3 wo = dir_cos(0.3f, 0.2);
        long nr = 0, nn = h_n(200000);
        double F = h_fresnel_dielectric(0.3, 1.5), R = 2 * F / (1 + F), fr;
        for (i = 0; i < nn; ++i) {
            appear_bsdf_record s;
            int ok = appear_thin_dielectric_sample(&th, wo, h_randf(&r), 0.5f, 0.5f, &s);
            H_CHECK(ok && s.weight.v[0] == 1.0f && (s.flags & APPEAR_LOBE_SPECULAR), "thin sample");
            if (s.flags & APPEAR_LOBE_REFLECTION) { ++nr; H_CHECK(s.wi.z == wo.z && s.wi.x == -wo.x, "mirror"); }
            else H_CHECK(s.wi.x == -wo.x && s.wi.y == -wo.y && s.wi.z == -wo.z && fabs(s.pdf - (1 - R)) < 1e-6, "straight through");
        }
        fr = (double)nr / nn;
        H_CHECK(fabs(fr - R) < 5 * sqrt(R * (1 - R) / nn), "R frequency %.5f vs %.5f", fr, R);
        H_CHECK(!appear_thin_dielectric_make(0.0f).valid && appear_thin_dielectric_eval(&th, wo, wo).v[0] == 0.0f, "invalid / eval");
    }

    h_case("dielectric smooth and pass-through limits; TIR from inside");
    {
        appear_bsdf_record s;
        appear_vec3 wo = dir_cos(0.6f, 0.4), wi_in = dir_cos(-0.2f, 0.4);
        appear_dielectric sm = appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f, APPEAR_SAMPLE_VISIBLE), 1.5f);
        appear_dielectric pass = appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, 0.5f, 0.5f, APPEAR_SAMPLE_VISIBLE), 1.0f);
        appear_dielectric rough = appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE), 1.5f);
        float F = appear_fresnel_dielectric(0.6f, 1.5f);
        int ok = appear_dielectric_sample(&sm, wo, 0.5f * F, 0.3f, 0.3f, &s);
        H_CHECK(ok && s.flags == (APPEAR_LOBE_REFLECTION | APPEAR_LOBE_SPECULAR) && fabsf(s.pdf - F) < 1e-6f && s.weight.v[0] == 1.0f,
                "smooth R: flags %u pdf %g weight %g", s.flags, s.pdf, s.weight.v[0]);
        ok = appear_dielectric_sample(&sm, wo, 0.99f, 0.3f, 0.3f, &s);
        {   /* Snell: sin_t = sin_i / eta, and radiance weight 1/eta^2 */
            double st = sqrt(s.wi.x * s.wi.x + s.wi.y * s.wi.y), si = sqrt(wo.x * wo.x + wo.y * wo.y);
            H_CHECK(ok && (s.flags & APPEAR_LOBE_TRANSMISSION) && fabs(st - si / 1.5) < 1e-6 && s.wi.z < 0 &&
                        fabsf(s.weight.v[0] - 1.0f / 2.25f) < 1e-6f && fabsf(s.eta - 1.5f) < 1e-7f && fabsf(s.pdf - (1 - F)) < 1e-6f,
                    "smooth T: sin %g vs %g, weight %g, eta %g", st, si / 1.5, s.weight.v[0], s.eta);
        }
        ok = appear_dielectric_sample(&pass, wo, 0.0f, 0.3f, 0.3f, &s);
        H_CHECK(ok && s.wi.x == -wo.x && s.wi.y == -wo.y && s.wi.z == -wo.z && s.weight.v[0] == 1.0f && (s.flags & APPEAR_LOBE_SPECULAR),
                "eta = 1 must pass straight through");
        ok = appear_dielectric_sample(&sm, wi_in, 0.999f, 0.3f, 0.3f, &s); /* sin_i = 0.98 > 1/1.5: TIR */
        H_CHECK(ok && (s.flags & APPEAR_LOBE_REFLECTION) && s.weight.v[0] == 1.0f && s.wi.z < 0, "smooth TIR from inside");
        for (i = 0; i < 2000; ++i) { /* rough: from inside at grazing most microfacets reflect totally */
            float q47 = h_randf(&r), q48 = h_randf(&r); /* in this order */
            ok = appear_dielectric_sample(&rough, dir_cos(-0.05f, 0.4), 1.0f, q47, q48, &s);
            if (ok && (s.flags & APPEAR_LOBE_TRANSMISSION)) {
                float cm = fabsf(appear_dot(appear_normalize(appear_add(dir_cos(-0.05f, 0.4), appear_scale(s.wi, 1.0f / 1.5f))), dir_cos(-0.05f, 0.4)));
                H_CHECK(cm > 0, "transmission through a totally reflecting facet");
            }
        }
    }

    h_case("smooth and rough refraction of a wo at the unit tolerance: wi is unit (the next bounce accepts it)");
    {
        /* |wo|^2 - 1 = +-0.999e-3 is accepted; before the fix, a smooth
           refraction at e = 1/2.4 returned |wi|^2 - 1 up to 5.8e-3 */
        static const float etas[] = { 1.5f, 2.4f, 1.0f / 2.4f, 1.0f + 1e-4f, 1.0f - 1e-4f };
        static const float alphas[] = { 0.0f, 0.3f };
        double worst = 0;
        int ei, ai, j, fails = 0;
        for (ei = 0; ei < 5; ++ei)
            for (ai = 0; ai < 2; ++ai) {
                appear_dielectric m = appear_dielectric_make(
                    appear_microfacet_make(APPEAR_GGX, alphas[ai], alphas[ai], APPEAR_SAMPLE_VISIBLE), etas[ei]);
                for (j = 0; j < 4000; ++j) {
                    appear_bsdf_record s;
                    float sc = sqrtf(1.0f + ((j & 2) ? 0.999e-3f : -0.999e-3f));
                    float uz = h_randf(&r), uphi = h_randf(&r); /* in this order */
                    appear_vec3 wo = appear_scale(dir_cos((j & 1 ? -1.0f : 1.0f) * (0.02f + 0.98f * uz), 6.28 * uphi), sc);
                    if (!appear_is_unit(wo)) continue;
                    float u1 = h_randf(&r), u2 = h_randf(&r);
                    if (!appear_dielectric_sample(&m, wo, 0.999999f, u1, u2, &s)) continue;
                    if (!(s.flags & APPEAR_LOBE_TRANSMISSION)) continue;
                    worst = fmax(worst, fabs(appear_dot(s.wi, s.wi) - 1.0));
                    fails += !appear_is_unit(s.wi);
                }
            }
        h_measure("refraction unit length", "max |wi|^2 - 1 = %.2g over smooth and rough, 5 etas", worst);
        H_CHECK(fails == 0 && worst < 1e-5, "%d refracted wi fail appear_is_unit, worst |wi|^2 - 1 = %.3g", fails, worst);
    }
}

/* ------------------------------------------------------------------------ */
/* Suite 4: stability                                                        */
/* ------------------------------------------------------------------------ */

static int vec_ok(appear_vec3 v) { return h_finite(v.x) && h_finite(v.y) && h_finite(v.z); }
static int spec_ok(appear_spectrum s)
{
    int i, ok = 1;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) ok &= H_OK_VALUE(s.v[i]);
    return ok;
}
static int sample_ok(int ret, const appear_bsdf_record *s)
{
    if (!ret) return s->flags == 0 && s->pdf == 0 && s->weight.v[0] == 0;
    return vec_ok(s->wi) && appear_is_unit(s->wi) && H_OK_VALUE(s->pdf) && s->pdf > 0 && spec_ok(s->f) && spec_ok(s->weight) && h_finite(s->eta) &&
           s->eta > 0;
}

void suite_microfacet_stability(void)
{
    h_rng r = h_rng_make(2024);
    long i, n = h_n(1000000), bad[24];
    int k, a, c, e, t;
    memset(bad, 0, sizeof bad);

    h_case("stability: >= 1e6 adversarial inputs per function (NaN, Inf, denormals, +-0, unnormalised, u = 0/1)");
    for (i = 0; i < n; ++i) {
        float ax = h_adv_float(&r), ay = (i & 3) ? ax : h_adv_float(&r), u1 = h_adv_u(&r), u2 = h_adv_u(&r), uc = h_adv_u(&r);
        float cs = h_adv_float(&r), eta = h_adv_float(&r), kk = h_adv_float(&r);
        appear_vec3 wo = h_adv_dir(&r), wi = h_adv_dir(&r), m = h_adv_dir(&r), v;
        appear_microfacet d = appear_microfacet_make((int)(i % 3), ax, ay, (int)((i / 3) % 4));
        appear_conductor cd = (i & 1) ? appear_conductor_make(d, appear_spectrum_splat(eta), appear_spectrum_splat(kk))
                                      : appear_conductor_make_f82(d, appear_spectrum_splat(u1), appear_spectrum_splat(u2));
        appear_dielectric de = appear_dielectric_make(d, eta);
        appear_bsdf_record s;
        int ret;
        bad[0] += !H_OK_VALUE(appear_ggx_D(ax, ay, m)) + !H_OK_VALUE(appear_beckmann_D(ax, ay, m));
        bad[1] += !H_OK_VALUE(appear_ggx_lambda(ax, ay, wo)) + !H_OK_VALUE(appear_beckmann_lambda(ax, ay, wo)) +
                  !H_OK_VALUE(appear_beckmann_lambda_fast(ax, ay, wo));
        bad[2] += !H_OK_VALUE(appear_ggx_G1(ax, ay, wo, m)) + !H_OK_VALUE(appear_beckmann_G1(ax, ay, wo, m));
        bad[3] += !H_OK_VALUE(appear_ggx_G2(ax, ay, wo, wi, m)) + !H_OK_VALUE(appear_beckmann_G2(ax, ay, wo, wi, m));
        bad[4] += !H_OK_VALUE(appear_ggx_pdf_visible(ax, ay, wo, m)) + !H_OK_VALUE(appear_beckmann_pdf_visible(ax, ay, wo, m)) +
                  !H_OK_VALUE(appear_ggx_pdf_bounded_reflect(ax, ay, wo, wi)) + !H_OK_VALUE(appear_ggx_pdf_D(ax, ay, m)) +
                  !H_OK_VALUE(appear_beckmann_pdf_D(ax, ay, m));
        v = appear_ggx_sample_visible(ax, ay, wo, u1, u2);
        bad[5] += !(vec_ok(v) && (appear_is_unit(v) || (v.x == 0 && v.y == 0 && v.z == 0)));
        v = appear_beckmann_sample_visible(ax, ay, wo, u1, u2);
        bad[6] += !(vec_ok(v) && (appear_is_unit(v) || (v.x == 0 && v.y == 0 && v.z == 0)));
        v = appear_ggx_sample_bounded_normal(ax, ay, wo, u1, u2);
        bad[7] += !(vec_ok(v) && (appear_is_unit(v) || (v.x == 0 && v.y == 0 && v.z == 0)));
        v = (i & 1) ? appear_ggx_sample_D(ax, ay, u1, u2) : appear_beckmann_sample_D(ax, ay, u1, u2);
        bad[8] += !(vec_ok(v) && (appear_is_unit(v) || (v.x == 0 && v.y == 0 && v.z == 0)));
        {
            float f1 = appear_fresnel_dielectric(cs, eta), f2 = appear_fresnel_conductor(cs, eta, kk), f3 = appear_fresnel_schlick(cs, u1),
                  f4 = appear_fresnel_f82(cs, u1, appear_fresnel_f82_coef(u1, u2));
            bad[9] += !(H_OK_VALUE(f1) && f1 <= 1) + !(H_OK_VALUE(f2) && f2 <= 1) + !(H_OK_VALUE(f3) && f3 <= 1) + !(H_OK_VALUE(f4) && f4 <= 1);
        }
        bad[10] += !spec_ok(appear_conductor_eval(&cd, wo, wi)) + !H_OK_VALUE(appear_conductor_pdf(&cd, wo, wi));
        ret = appear_conductor_sample(&cd, wo, uc, u1, u2, &s);
        bad[11] += !sample_ok(ret, &s);
        bad[12] += !spec_ok(appear_dielectric_eval(&de, wo, wi)) + !H_OK_VALUE(appear_dielectric_pdf(&de, wo, wi));
        ret = appear_dielectric_sample(&de, wo, uc, u1, u2, &s);
        bad[13] += !sample_ok(ret, &s);
        {
            appear_thin_dielectric th = appear_thin_dielectric_make(eta);
            ret = appear_thin_dielectric_sample(&th, wo, uc, u1, u2, &s);
            bad[14] += !sample_ok(ret, &s);
        }
    }
    for (k = 0; k < 15; ++k) H_CHECK(bad[k] == 0, "group %d: %ld bad outputs", k, bad[k]);

    h_case("stability grid: alpha x cos x eta x u in {0, 1-ulp, 1} for both models, GGX and Beckmann");
    memset(bad, 0, sizeof bad);
    for (t = 0; t < 2; ++t)
        for (a = 0; a < NA + 1; ++a)
            for (c = 0; c < NC; ++c)
                for (e = 0; e < NE; ++e)
                    for (k = 0; k < 27; ++k) {
                        static const float us[3] = { 0.0f, 0.99999994f, 1.0f };
                        float al = a < NA ? g_alphas[a] : 0.0f;
                        appear_microfacet d = appear_microfacet_make(t, al, al, (k + e) % 3 == 1 && t == 0 ? APPEAR_SAMPLE_BOUNDED : (k + e) % 3 == 2 ? APPEAR_SAMPLE_FULL_D : APPEAR_SAMPLE_VISIBLE);
                        appear_conductor cd = gold(d);
                        appear_dielectric de = appear_dielectric_make(d, g_etas[e]);
                        appear_vec3 wo = dir_cos(c & 1 ? -g_cos[c] : g_cos[c], 0.5), wi = dir_cos(-g_cos[(c + k) % NC], 2.0);
                        appear_bsdf_record s;
                        int ret;
                        ret = appear_conductor_sample(&cd, wo, us[k % 3], us[(k / 3) % 3], us[k / 9], &s);
                        bad[0] += !sample_ok(ret, &s);
                        ret = appear_dielectric_sample(&de, wo, us[k % 3], us[(k / 3) % 3], us[k / 9], &s);
                        bad[1] += !sample_ok(ret, &s);
                        bad[2] += !spec_ok(appear_dielectric_eval(&de, wo, wi)) + !H_OK_VALUE(appear_dielectric_pdf(&de, wo, wi)) +
                                  !spec_ok(appear_conductor_eval(&cd, wo, appear_neg(wi))) + !H_OK_VALUE(appear_conductor_pdf(&cd, wo, appear_neg(wi)));
                        if (g_cos[c] == 0.0f) bad[3] += ret != 0 || appear_dielectric_eval(&de, wo, wi).v[0] != 0.0f;
                    }
    for (k = 0; k < 4; ++k) H_CHECK(bad[k] == 0, "grid group %d: %ld bad", k, bad[k]);

    h_case("invalid parameters: make() returns valid = 0 and every call yields 0 / failure");
    {
        appear_microfacet d1 = appear_microfacet_make(APPEAR_GGX, -0.1f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        appear_microfacet d2 = appear_microfacet_make(APPEAR_BECKMANN, 0.3f, 0.3f, APPEAR_SAMPLE_BOUNDED);
        appear_microfacet d3 = appear_microfacet_make(APPEAR_GGX, NAN, 0.3f, APPEAR_SAMPLE_VISIBLE);
        appear_microfacet ok = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        appear_dielectric bd = appear_dielectric_make(ok, -1.5f);
        appear_conductor bc = appear_conductor_make(ok, appear_spectrum_splat(NAN), appear_spectrum_splat(1.0f));
        appear_bsdf_record s;
        appear_vec3 wo = dir_cos(0.5f, 0), wi = dir_cos(0.7f, 3);
        H_CHECK(!d1.valid && !d2.valid && !d3.valid && ok.valid && !bd.valid && !bc.valid, "validity");
        H_CHECK(appear_dielectric_sample(&bd, wo, 0.5f, 0.5f, 0.5f, &s) == 0 && appear_dielectric_pdf(&bd, wo, wi) == 0 &&
                    appear_conductor_sample(&bc, wo, 0.5f, 0.5f, 0.5f, &s) == 0 && appear_conductor_eval(&bc, wo, wi).v[0] == 0,
                "invalid models must yield 0");
    }
}

#endif /* APPEAR_NO_MICROFACET */

/* ------------------------------------------------------------------------ */
/* Suite 5: float sampled directions against the same constructions in double */
/* ------------------------------------------------------------------------ */
#ifndef APPEAR_NO_MICROFACET
/* GGX spherical caps [DB23] in double, plainly: v = stretched wo, p on the
   cap z in [-v.z, 1] at azimuth phi_v + pi - 2 pi u1 (the parametrisation of
   appear__ggx_caps_core), h = p + v, unstretch, normalise. Returns 0 where
   the construction degenerates (h.z = 0). */
static int caps_double(double ax, double ay, appear_vec3 wo, double u1, double u2, double m[3])
{
    double vx = ax * wo.x, vy = ay * wo.y, vz = fabs((double)wo.z), l = sqrt(vx * vx + vy * vy + vz * vz);
    double c, phi, z, st, hx, hy, hz;
    if (wo.z < 0) { vx = -vx; vy = -vy; }
    vx /= l; vy /= l; vz /= l; c = vz;
    phi = (vx != 0.0 || vy != 0.0 ? atan2(vy, vx) : 0.0) + PI_D - 2.0 * PI_D * u1;
    z = (1.0 - u2) * (1.0 + c) - c;
    st = sqrt(fmax(0.0, 1.0 - z * z));
    hx = ax * (st * cos(phi) + vx); hy = ay * (st * sin(phi) + vy); hz = z + c;
    if (!(hz > 0)) return 0;
    l = sqrt(hx * hx + hy * hy + hz * hz);
    m[0] = hx / l; m[1] = hy / l; m[2] = hz / l;
    return 1;
}
/* Beckmann visible normals [HdE14, Sec. 4] in double, plainly: v = stretched wo, c = cot theta_v;
   the x slope solves F(x) = u1 F(c) with F(x) = c sqrt(pi)/2 erfc(-x) + exp(-x^2)/2, the integral
   of (c - t) exp(-t^2) over t < x (erfc keeps the lower tail's relative accuracy), by bisection
   to the last bit; y solves erf(y) = b by bisection, b being the float code's own argument
   (float)(2 u2 - 1) clamped to +-(1 - 2^-24): the quantisation of that input is not the x
   sampler's error. Rotate by the azimuth of v, unstretch, normalise. */
static double beck_F_d(double c, double x) { return c * 0.5 * sqrt(PI_D) * erfc(-x) + 0.5 * exp(-x * x); }
static void beck_vis_double(double ax, double ay, appear_vec3 wo, double u1, float u2, double m[3])
{
    double vx = ax * wo.x, vy = ay * wo.y, vz = fabs((double)wo.z), l = sqrt(vx * vx + vy * vy + vz * vz);
    double r, cp, sp, c, N, lo = -40.0, hi, x, y, b, sx, sy;
    float bf = 2.0f * u2 - 1.0f;
    int k;
    if (wo.z < 0) { vx = -vx; vy = -vy; }
    vx /= l; vy /= l; vz /= l;
    r = sqrt(vx * vx + vy * vy);
    cp = r > 0 ? vx / r : 1.0; sp = r > 0 ? vy / r : 0.0;
    c = r > 0 ? fmin(vz / r, 1e8) : 1e8;
    N = beck_F_d(c, c);
    hi = fmin(c, 40.0);
    for (k = 0; k < 200 && hi - lo > 0; ++k) {
        double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        if (beck_F_d(c, mid) < u1 * N) lo = mid; else hi = mid;
    }
    x = 0.5 * (lo + hi);
    b = bf < -0.99999994f ? -0.99999994f : bf > 0.99999994f ? 0.99999994f : bf;
    for (lo = -6.0, hi = 6.0, k = 0; k < 200; ++k) {
        double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        if (erf(mid) < b) lo = mid; else hi = mid;
    }
    y = 0.5 * (lo + hi);
    sx = ax * (cp * x - sp * y); sy = ay * (sp * x + cp * y);
    l = sqrt(sx * sx + sy * sy + 1.0);
    m[0] = -sx / l; m[1] = -sy / l; m[2] = 1.0 / l;
}
/* u in [0,1): uniform, or within 2^-k (k up to 40) of 0 or of 1, or exactly 0 / 1-ulp */
static float u_edgy(h_rng *r)
{
    double t = h_rand(r), m = h_rand(r), x = h_rand(r), e = ldexp(m, -(int)(x * 40.0));
    float u;
    if (t < 0.4) return h_randf(r);
    if (t < 0.45) return t < 0.425 ? 0.0f : 0.99999994f;
    u = t < 0.7 ? (float)e : (float)(1.0 - e);
    return u < 1.0f ? u : 0.99999994f;
}
void suite_microfacet_sampling_accuracy(void)
{
    h_rng r = h_rng_make(77);
    long i, n = h_n(1400000), fails = 0, rim = 0;
    double worst = 0.0, worst_u1 = 0, worst_u2 = 0, worst_c = 0, worst_a = 0, worst_ay = 0;
    static const float cz[] = { 1.0f, 0.99999994f, 0.999f, 1e-2f, 1e-4f, 1e-6f, 1e-7f };

    h_case("GGX visible normals (spherical caps): float direction vs double <= 1e-5 (u near 0 and 1, grazing/normal wo, alpha 1e-4..2, anisotropic)");
    for (i = 0; i < n; ++i) {
        float ax = (float)(1e-4 * pow(2e4, h_rand(&r))), ay = ax;
        if (i & 1) ay = (float)fmin(2.0, fmax(1e-4, ax * pow(2.0, 8.0 * h_rand(&r) - 4.0))); /* ay/ax in [1/16, 16] */
        float u1 = u_edgy(&r), u2 = u_edgy(&r);
        appear_vec3 wo = h_rand_dir(&r), m;
        double md[3], e;
        int okd;
        if ((i & 3) == 2) wo = dir_cos(cz[(i >> 2) % 7], 2.0 * PI_D * h_rand(&r));
        if ((i & 7) == 3) wo = dir_cos(-cz[(i >> 3) % 7], 2.0 * PI_D * h_rand(&r));
        if (wo.z == 0.0f) continue;
        m = appear_ggx_sample_visible(ax, ay, wo, u1, u2);
        okd = caps_double(ax, ay, wo, u1, u2, md);
        if (okd && !(m.z > 0)) {
            /* documented: a normal within 2^-21 of the rim (wo.m <= 2^-21) fails */
            double s = wo.z < 0 ? -1.0 : 1.0, vis = s * (wo.x * md[0] + wo.y * md[1] + wo.z * md[2]);
            if (vis <= 9.6e-7) { ++rim; continue; } /* 2^-20: margin for the float dot's rounding */
        }
        if (!okd || !(m.z > 0)) { fails += okd != (m.z > 0); continue; }
        e = sqrt((m.x - md[0]) * (m.x - md[0]) + (m.y - md[1]) * (m.y - md[1]) + (m.z - md[2]) * (m.z - md[2]));
        if (!(e <= worst)) { worst = e; worst_u1 = u1; worst_u2 = u2; worst_c = wo.z; worst_a = ax; worst_ay = ay; }
    }
    H_CHECK(fails == 0, "%ld samples fail in float but not in double (or the reverse)", fails);
    h_measure("ggx caps rim", "%ld of %ld samples fail at the rim (exact wo.m <= 2^-20; u2 within 2^-20 of 1 is common here), as documented", rim, n);
    H_CHECK(worst <= 1e-5, "max |m - m_double| = %.3g (u1 %.9g u2 %.9g cos %.9g alpha %.9g %.9g)", worst, worst_u1, worst_u2, worst_c, worst_a, worst_ay);
    h_measure("ggx caps float vs double", "max |m - m_double| = %.3g over %ld samples", worst, n);

    h_case("Beckmann visible normals: float direction vs double <= 1e-3, <= 3e-4 for u1 in [2^-20, 1 - 2^-20], no failure there (grazing/normal wo, alpha 1e-4..2, anisotropic)");
    {
        long nb = h_n(300000);
        double wmid = 0.0, wall = 0.0, wm[5] = { 0 }, wa[5] = { 0 };
        long rim = 0;
        fails = 0;
        for (i = 0; i < nb; ++i) {
            float ax = (float)(1e-4 * pow(2e4, h_rand(&r))), ay = ax;
            float u1, u2;
            appear_vec3 wo = h_rand_dir(&r), m;
            double md[3], e;
            if (i & 1) ay = (float)fmin(2.0, fmax(1e-4, ax * pow(2.0, 8.0 * h_rand(&r) - 4.0)));
            u1 = u_edgy(&r); u2 = u_edgy(&r);
            if ((i & 3) == 2) wo = dir_cos(cz[(i >> 2) % 7], 2.0 * PI_D * h_rand(&r));
            if ((i & 7) == 3) wo = dir_cos(-cz[(i >> 3) % 7], 2.0 * PI_D * h_rand(&r));
            if (wo.z == 0.0f || u1 == 0.0f) continue;  /* u1 = 0: x = -inf in exact arithmetic */
            m = appear_beckmann_sample_visible(ax, ay, wo, u1, u2);
            beck_vis_double(ax, ay, wo, u1, u2, md);
            if (!(m.z > 0)) { /* the rim u1 > 1 - 2^-20 may fail, as documented (wo.m at rounding) */
                if (u1 > 1.0f - 9.5367431640625e-7f) ++rim; else ++fails;
                continue;
            }
            e = sqrt((m.x - md[0]) * (m.x - md[0]) + (m.y - md[1]) * (m.y - md[1]) + (m.z - md[2]) * (m.z - md[2]));
            if (!(e <= wall)) { wall = e; wa[0] = u1; wa[1] = u2; wa[2] = wo.z; wa[3] = ax; wa[4] = ay; }
            if (u1 >= 9.5367431640625e-7f && u1 <= 1.0f - 9.5367431640625e-7f && !(e <= wmid)) {
                wmid = e; wm[0] = u1; wm[1] = u2; wm[2] = wo.z; wm[3] = ax; wm[4] = ay;
            }
        }
        H_CHECK(fails == 0, "%ld Beckmann samples fail with u1 <= 1 - 2^-20", fails);
        H_CHECK(rim <= nb / 1000, "%ld of %ld Beckmann samples fail at the rim u1 > 1 - 2^-20", rim, nb);
        H_CHECK(wall <= 1e-3, "max |m - m_double| = %.3g (u1 %.9g u2 %.9g cos %.9g alpha %.9g %.9g)", wall, wa[0], wa[1], wa[2], wa[3], wa[4]);
        H_CHECK(wmid <= 3e-4, "u1 in [2^-20, 1 - 2^-20]: max |m - m_double| = %.3g (u1 %.9g u2 %.9g cos %.9g alpha %.9g %.9g)", wmid, wm[0], wm[1], wm[2], wm[3], wm[4]);
        h_measure("beckmann visible float vs double", "max |m - m_double| = %.3g, %.3g for u1 in [2^-20, 1 - 2^-20], over %ld samples (%ld fail at the rim u1 > 1 - 2^-20, as documented)", wall, wmid, nb, rim);
    }
}

/* ------------------------------------------------------------------------ */
/* Constant-reflectance conductor (appear_conductor_make_reflectance)        */
/* ------------------------------------------------------------------------ */

static int rel_close(float a, float b) /* equal to a few float roundings */
{
    float d = fabsf(a - b), m = fmaxf(fabsf(a), fabsf(b));
    return d <= 4.0f * 1.1920929e-7f * m || d <= 1e-30f;
}

void suite_microfacet_reflectance(void)
{
    static const float F0s[3] = {0.95f, 0.64f, 0.54f};
    h_rng r = h_rng_make(1616);
    appear_spectrum F0 = appear_spectrum_rgb(F0s[0], F0s[1], F0s[2]);
    long bad_eval = 0, bad_pdf = 0, bad_sample = 0, bad_batch = 0, n = h_n(20000), i;
    int t, sm, k;
    h_case("reflectance conductor: eval = F0 eval(eta = k = 0), pdf equal, sample weight = F0 "
           "weight(F = 1)");
    for (t = 0; t < 2; ++t)
        for (sm = 0; sm < 3; ++sm) {
            float al[4] = {0.01f, 0.2f, 0.7f, 1.5f};
            int a;
            for (a = 0; a < 4; ++a) {
                appear_microfacet d =
                    appear_microfacet_make(t, al[a], al[a] * (a & 1 ? 0.5f : 1.0f), sm);
                appear_conductor cr = appear_conductor_make_reflectance(d, F0);
                appear_conductor c1 = appear_conductor_make(d, appear_spectrum_splat(0.0f),
                                                            appear_spectrum_splat(0.0f));
                if (!d.valid) continue; /* Beckmann has no bounded strategy */
                H_CHECK(cr.valid && c1.valid, "valid %d %d (type %d sampling %d)", cr.valid,
                        c1.valid, t, sm);
                for (i = 0; i < n / 24; ++i) {
                    appear_vec3 wo = h_rand_dir(&r), wi = h_rand_dir(&r);
                    float uc = h_randf(&r), u1 = h_randf(&r), u2 = h_randf(&r);
                    appear_spectrum er = appear_conductor_eval(&cr, wo, wi),
                                    e1 = appear_conductor_eval(&c1, wo, wi);
                    appear_bsdf_record sr, s1;
                    int okr, ok1;
                    for (k = 0; k < 3; ++k) bad_eval += !rel_close(er.v[k], F0s[k] * e1.v[k]);
                    bad_pdf +=
                        appear_conductor_pdf(&cr, wo, wi) != appear_conductor_pdf(&c1, wo, wi);
                    okr = appear_conductor_sample(&cr, wo, uc, u1, u2, &sr);
                    ok1 = appear_conductor_sample(&c1, wo, uc, u1, u2, &s1);
                    bad_sample += okr != ok1;
                    if (okr && ok1) {
                        bad_sample += sr.wi.x != s1.wi.x || sr.wi.y != s1.wi.y ||
                                      sr.wi.z != s1.wi.z || sr.pdf != s1.pdf ||
                                      sr.flags != s1.flags;
                        for (k = 0; k < 3; ++k)
                            bad_sample += !rel_close(sr.weight.v[k], F0s[k] * s1.weight.v[k]) ||
                                          !rel_close(sr.f.v[k], F0s[k] * s1.f.v[k]);
                    }
                }
            }
        }
    H_CHECK(bad_eval == 0, "%ld eval channels differ from F0 * eval(F = 1)", bad_eval);
    H_CHECK(bad_pdf == 0, "%ld pdfs differ from the F = 1 conductor's", bad_pdf);
    H_CHECK(bad_sample == 0, "%ld samples differ from F0 * sample(F = 1)", bad_sample);

    h_case("reflectance conductor: smooth limit weight = F0, F0 = 1 albedo <= 1");
    {
        appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f, APPEAR_SAMPLE_VISIBLE);
        appear_conductor cr = appear_conductor_make_reflectance(d, F0);
        appear_bsdf_record s;
        int ok =
            appear_conductor_sample(&cr, appear_vec3_make(0.6f, 0.0f, 0.8f), 0.5f, 0.5f, 0.5f, &s);
        H_CHECK(ok && s.weight.v[0] == F0s[0] && s.weight.v[1] == F0s[1] &&
                    s.weight.v[2] == F0s[2] && (s.flags & APPEAR_LOBE_SPECULAR),
                "smooth: ok %d weight %g %g %g", ok, s.weight.v[0], s.weight.v[1], s.weight.v[2]);
    }

    h_case("reflectance conductor: F0 NaN, Inf, < 0, > 1 gives valid = 0 and zero results");
    {
        float badv[7] = {NAN, INFINITY, -INFINITY, -1e-3f, 1.0001f, 2.0f, -1e-40f};
        appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
        appear_vec3 wo = appear_vec3_make(0.0f, 0.6f, 0.8f),
                    wi = appear_vec3_make(0.0f, -0.6f, 0.8f);
        int b;
        for (b = 0; b < 7; ++b)
            for (k = 0; k < 3; ++k) {
                appear_spectrum f = F0;
                appear_conductor c;
                appear_bsdf_record s;
                appear_spectrum e;
                int ok;
                f.v[k] = badv[b];
                c = appear_conductor_make_reflectance(d, f);
                e = appear_conductor_eval(&c, wo, wi);
                ok = appear_conductor_sample(&c, wo, 0.5f, 0.3f, 0.7f, &s);
                H_CHECK(!c.valid && e.v[0] == 0 && e.v[1] == 0 && e.v[2] == 0 &&
                            appear_conductor_pdf(&c, wo, wi) == 0 && !ok && s.pdf == 0,
                        "F0[%d] = %g: valid %d eval %g ok %d", k, badv[b], c.valid, e.v[0], ok);
            }
        H_CHECK(appear_conductor_make_reflectance(d, appear_spectrum_splat(0.0f)).valid &&
                    appear_conductor_make_reflectance(d, appear_spectrum_splat(1.0f)).valid,
                "F0 = 0, 1 rejected");
        H_CHECK(!appear_conductor_make_reflectance(
                     appear_microfacet_make(APPEAR_GGX, -1.0f, 0.3f, 0), F0)
                     .valid,
                "invalid distribution accepted");
    }

    h_case("reflectance conductor: eval_batch / pdf_batch = scalar bit for bit (1..80 elements)");
    {
        enum { N = 80 };
        float ox[N], oy[N], oz[N], ix[N], iy[N], iz[N], f[3 * N], p[N];
        for (t = 0; t < 2; ++t) {
            appear_microfacet d = appear_microfacet_make(t, 0.4f, 0.15f, APPEAR_SAMPLE_VISIBLE);
            appear_conductor c = appear_conductor_make_reflectance(d, F0);
            int nn;
            for (nn = 1; nn <= N; nn += 13) {
                for (i = 0; i < nn; ++i) {
                    appear_vec3 wo = h_rand_dir(&r), wi = h_rand_dir(&r);
                    if (i & 1) wi.z = fabsf(wi.z) * (wo.z < 0 ? -1.0f : 1.0f);
                    ox[i] = wo.x;
                    oy[i] = wo.y;
                    oz[i] = wo.z;
                    ix[i] = wi.x;
                    iy[i] = wi.y;
                    iz[i] = wi.z;
                }
                appear_conductor_eval_batch(&c, ox, oy, oz, ix, iy, iz, f, nn);
                appear_conductor_pdf_batch(&c, ox, oy, oz, ix, iy, iz, p, nn);
                for (i = 0; i < nn; ++i) {
                    appear_vec3 wo = appear_vec3_make(ox[i], oy[i], oz[i]),
                                wi = appear_vec3_make(ix[i], iy[i], iz[i]);
                    appear_spectrum e = appear_conductor_eval(&c, wo, wi);
                    for (k = 0; k < 3; ++k)
                        bad_batch += memcmp(&e.v[k], &f[k * nn + i], sizeof(float)) != 0;
                    {
                        float ps = appear_conductor_pdf(&c, wo, wi);
                        bad_batch += memcmp(&ps, &p[i], sizeof(float)) != 0;
                    }
                }
            }
        }
        H_CHECK(bad_batch == 0, "%ld batch values differ from scalar", bad_batch);
    }
}

/* ------------------------------------------------------------------------ */
/* Suite: the fuzzy metal of Ray Tracing in One Weekend (appear_alpha_from_fuzz) */
/* ------------------------------------------------------------------------ */

/* The book's Metal (v4), transcribed in double: scattered = unit(reflect(r_in, n)) +
   fuzz * random_unit_vector(), absorbed when dot(scattered, n) <= 0. At normal incidence
   the mirror direction is n. The mean (and its standard error) of the angle between the
   scattered direction and n over the rays that survive (all of them for fuzz <= 1). */
static void book_metal_normal(double fuzz, long n, h_rng *r, double *mean, double *se)
{
    double s = 0, s2 = 0, k = 0;
    long i;
    for (i = 0; i < n; ++i) {
        double z = 1.0 - 2.0 * h_rand(r), phi = 2.0 * PI_D * h_rand(r);
        double st = sqrt(fmax(0.0, 1.0 - z * z)), x = fuzz * st * cos(phi),
               y = fuzz * st * sin(phi);
        double dz = 1.0 + fuzz * z, a;
        if (!(dz > 0)) continue; /* absorbed */
        a = atan2(sqrt(x * x + y * y), dz);
        s += a;
        s2 += a * a;
        k += 1;
    }
    *mean = s / k;
    *se = sqrt(fmax(0.0, s2 / k - *mean * *mean) / k);
}
/* appear.h's GGX conductor (visible normals, F0 = 1) at wo = n as a renderer sees it: the
   mean angle of wi to the mirror direction n weighted by s.weight (a failed sample weighs
   0); standard error of the ratio: sqrt(sum w^2 (a - mean)^2) / sum w. */
static void ggx_metal_normal(float alpha, long n, h_rng *r, double *mean, double *se)
{
    appear_conductor c = appear_conductor_make_reflectance(
        appear_microfacet_make(APPEAR_GGX, alpha, alpha, APPEAR_SAMPLE_VISIBLE),
        appear_spectrum_splat(1.0f));
    appear_vec3 wo = appear_vec3_make(0.0f, 0.0f, 1.0f);
    double sw = 0, swa = 0, sw2 = 0, sw2a = 0, sw2a2 = 0, m;
    long i;
    for (i = 0; i < n; ++i) {
        appear_bsdf_record s;
        float u1 = h_randf(r), u2 = h_randf(r);
        if (appear_conductor_sample(&c, wo, 0.5f, u1, u2, &s)) {
            double w = s.weight.v[0];
            double a =
                atan2(sqrt((double)s.wi.x * s.wi.x + (double)s.wi.y * s.wi.y), (double)s.wi.z);
            sw += w;
            swa += w * a;
            sw2 += w * w;
            sw2a += w * w * a;
            sw2a2 += w * w * a * a;
        }
    }
    m = sw > 0 ? swa / sw : 0.0;
    *mean = m;
    *se = sw > 0 ? sqrt(fmax(0.0, sw2a2 - 2.0 * m * sw2a + m * m * sw2)) / sw : 1e30;
}
static unsigned fz_bits(float x)
{
    unsigned u;
    memcpy(&u, &x, sizeof u);
    return u;
}
static float fz_float(unsigned u)
{
    float x;
    memcpy(&x, &u, sizeof x);
    return x;
}

void suite_microfacet_fuzz(void)
{
    /* fuzz values of the check, and the relative error of the fit's mean angle at normal
       incidence, measured by tests/gen/fit_fuzz.c: 1.29e-3 (0.058 deg at fuzz 1) */
    static const double fz[6] = {0.05, 0.1, 0.3, 0.5, 0.8, 1.0};
    const double fit_rel = 1.3e-3;
    long n = h_n(480000); /* quick mode: 30000 */
    int i;

    /* GGX at alpha(fuzz) and the book agree in the mean angle to the mirror direction at
       normal incidence within the fit's error plus the float sampler's (0.2% together) and
       4 standard errors of the two Monte Carlo means: 0.6-1.0% of the mean in full mode,
       1.8-3.7% in quick mode. The same check must reject the porting row this replaced,
       alpha = fuzz (GGX 8.3 vs 2.25 deg at fuzz 0.05, 33.2 vs 13.5 at 0.3, 48.0 vs 45 at 1),
       for every fuzz: it runs below. So this test can fail: a mapping off by more than the
       tolerance (alpha = fuzz, a wrong coefficient) does. */
    h_case("fuzz: GGX at appear_alpha_from_fuzz(f) has the book Metal(f)'s mean angle to the "
           "mirror direction at normal incidence (f = 0.05 .. 1), and alpha = f does not");
    for (i = 0; i < 6; ++i) {
        h_rng rb = h_rng_make(4200 + (uint64_t)i), rg = h_rng_make(4300 + (uint64_t)i);
        double mb, sb, mg, sg, mo, so, tol, tol_o;
        float a = appear_alpha_from_fuzz((float)fz[i]);
        book_metal_normal(fz[i], n, &rb, &mb, &sb);
        ggx_metal_normal(a, n, &rg, &mg, &sg);
        ggx_metal_normal((float)fz[i], n, &rg, &mo, &so);
        tol = (fit_rel + 7e-4) * mb + 4.0 * sqrt(sb * sb + sg * sg);
        tol_o = (fit_rel + 7e-4) * mb + 4.0 * sqrt(sb * sb + so * so);
        H_CHECK(fabs(mg - mb) <= tol,
                "fuzz %g alpha %.6g: GGX mean %.4f deg, book %.4f deg, |diff| %.4f > tol %.4f",
                fz[i], (double)a, mg * 180 / PI_D, mb * 180 / PI_D, fabs(mg - mb) * 180 / PI_D,
                tol * 180 / PI_D);
        H_CHECK(fabs(mo - mb) > tol_o,
                "fuzz %g: the check does not reject alpha = fuzz (GGX mean %.4f deg, book %.4f)",
                fz[i], mo * 180 / PI_D, mb * 180 / PI_D);
        h_measure("fuzz mean angle",
                  "fuzz %.2f: book %.3f deg (45 fuzz), GGX alpha %.5f: %.3f deg (+-%.3f), "
                  "|diff| %.3f <= tol %.3f; alpha = fuzz: %.3f deg (tol %.3f)",
                  fz[i], mb * 180 / PI_D, (double)a, mg * 180 / PI_D, sg * 180 / PI_D,
                  fabs(mg - mb) * 180 / PI_D, tol * 180 / PI_D, mo * 180 / PI_D, tol_o * 180 / PI_D);
    }

    h_case("fuzz: appear_alpha_from_fuzz is monotone, 0 at 0, within [f / 4, 0.671 f] on (0, 1]");
    {
        long k, down = 0, bound = 0;
        unsigned prev = 0, b;
        const long steps = 1L << 20;
        for (k = 0; k <= steps; ++k) { /* the grid k / 2^20 */
            float f = (float)k / (float)steps, a = appear_alpha_from_fuzz(f);
            b = fz_bits(a); /* non-negative floats order as their bits */
            down += b < prev;
            bound += !(a >= 0.25f * f && a <= 0.671f * f);
            prev = b;
        }
        /* every float near 0 (denormals included) and the last 2^14 below 1 */
        for (prev = 0, b = 0; b < 1u << 16; ++b) {
            unsigned x = fz_bits(appear_alpha_from_fuzz(fz_float(b)));
            down += x < prev;
            prev = x;
        }
        for (b = 0x3f800000u - (1u << 14), prev = 0; b <= 0x3f800000u; ++b) {
            unsigned x = fz_bits(appear_alpha_from_fuzz(fz_float(b)));
            down += x < prev;
            prev = x;
        }
        H_CHECK(down == 0, "%ld decreasing steps", down);
        H_CHECK(bound == 0, "%ld values outside [f / 4, 0.671 f]", bound);
        H_CHECK(fz_bits(appear_alpha_from_fuzz(0.0f)) == 0u, "alpha(0) = %a",
                (double)appear_alpha_from_fuzz(0.0f));
        /* alpha*(0.3) = 0.086441, alpha*(1) = 0.670792 (tests/gen/fit_fuzz.c); the fit is
           within 0.6% of them */
        H_CHECK(fabsf(appear_alpha_from_fuzz(0.3f) / 0.086441f - 1.0f) < 6e-3f &&
                    fabsf(appear_alpha_from_fuzz(1.0f) / 0.670792f - 1.0f) < 6e-3f,
                "alpha(0.3) = %.6g, alpha(1) = %.6g", (double)appear_alpha_from_fuzz(0.3f),
                (double)appear_alpha_from_fuzz(1.0f));
    }

    h_case("fuzz: bad inputs (NaN, -0, -Inf, negatives -> 0; +Inf, > 1 -> alpha(1)), on the "
           "bits; the smooth limit below fuzz 4e-4");
    {
        static const unsigned zero_in[] = {0x80000000u, 0x7fc00000u, 0xffc00000u, 0x7f800001u,
                                           0xff800001u, 0x7fffffffu, 0xffffffffu, 0xff800000u,
                                           0xbf800000u, 0xbe99999au, 0x80000001u, 0x807fffffu,
                                           0xff7fffffu, 0xb8d1b717u};
        static const unsigned one_in[] = {0x7f800000u, 0x3f800001u, 0x40000000u, 0x7f7fffffu,
                                          0x501502f9u};
        unsigned a1 = fz_bits(appear_alpha_from_fuzz(1.0f));
        int k;
        for (k = 0; k < (int)(sizeof zero_in / sizeof zero_in[0]); ++k) {
            float a = appear_alpha_from_fuzz(fz_float(zero_in[k]));
            H_CHECK(fz_bits(a) == 0u, "fuzz bits 0x%08x: alpha bits 0x%08x, expected +0",
                    zero_in[k], fz_bits(a));
            H_CHECK(appear_microfacet_make(APPEAR_GGX, a, a, APPEAR_SAMPLE_VISIBLE).smooth,
                    "fuzz bits 0x%08x: not the smooth conductor", zero_in[k]);
        }
        for (k = 0; k < (int)(sizeof one_in / sizeof one_in[0]); ++k) {
            unsigned a = fz_bits(appear_alpha_from_fuzz(fz_float(one_in[k])));
            H_CHECK(a == a1, "fuzz bits 0x%08x: alpha bits 0x%08x, expected alpha(1) 0x%08x",
                    one_in[k], a, a1);
        }
        { /* positive denormals: tiny, finite, >= 0 (0 under DAZ) */
            float a = appear_alpha_from_fuzz(fz_float(0x00000001u)),
                  b = appear_alpha_from_fuzz(fz_float(0x007fffffu));
            H_CHECK(fz_bits(a) < 0x00800000u && fz_bits(b) < 0x00800000u,
                    "denormal fuzz: alpha %a %a", (double)a, (double)b);
        }
        /* below fuzz 4e-4 alpha < APPEAR_MICROFACET_ALPHA_MIN: the smooth (delta) conductor,
           the book's lobe there being narrower than 0.018 deg; above, a rough one */
        H_CHECK(appear_microfacet_make(APPEAR_GGX, appear_alpha_from_fuzz(3.9e-4f),
                                       appear_alpha_from_fuzz(3.9e-4f), APPEAR_SAMPLE_VISIBLE)
                        .smooth &&
                    !appear_microfacet_make(APPEAR_GGX, appear_alpha_from_fuzz(4.1e-4f),
                                            appear_alpha_from_fuzz(4.1e-4f), APPEAR_SAMPLE_VISIBLE)
                         .smooth,
                "smooth threshold: alpha(3.9e-4) = %g, alpha(4.1e-4) = %g",
                (double)appear_alpha_from_fuzz(3.9e-4f), (double)appear_alpha_from_fuzz(4.1e-4f));
    }
}

#endif
