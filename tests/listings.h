/* tests/listings.h - plain baseline implementations, written from the papers
   the way pbrt-v4 and Mitsuba 3 write them: float, libm (sqrtf, expf, logf,
   sinf/cosf, erff, erfcf), early exits where they win, no validation beyond
   what those renderers do. They are the speed (and sanity) reference of
   bench/ (bench_latency.c times each against appear's public function; the
   timing comparison is only meaningful because bench_latency.c also checks
   that each pair computes the same values on random inputs).

   Conventions are appear's: wo, wi point away from the surface / scattering
   point; local frame z = normal; eta = n_inside / n_outside; phase function
   cos theta = -dot(wo, wi); eval returns f without the cosine; samplers fill
   appear's own records (appear_bsdf_record, appear_phase_record,
   appear_medium_sample). Where pbrt-v4's integrator, not its BxDF, computes
   weight = f |cos| / pdf, the baseline computes it too, so both sides of a
   comparison produce the same record.

   Header-only, every function static; C99 and C++. Include after appear.h
   (it includes ../appear.h itself). Names: lst_<what>. */
#ifndef APPEAR_TESTS_LISTINGS_H
#define APPEAR_TESTS_LISTINGS_H
#include "../appear.h"
#include <math.h>
#include <string.h>

#if defined(__GNUC__)
#define LST_UNUSED __attribute__((unused))
#else
#define LST_UNUSED
#endif
#define LST_FUNC static LST_UNUSED

#define LST_PI 3.14159265358979323846f
#define LST_PI_D 3.14159265358979323846 /* a double, as Mitsuba 0.6's M_PI */
#define LST_INV_PI 0.31830988618379067154f
#define LST_INV_4PI 0.07957747154594766788f
#define LST_INV_SQRT_PI 0.56418958354775628695f

/* ---- small vector helpers (pbrt-v4 geometry.h / vecmath.h style) ---- */
LST_FUNC appear_vec3 lst_v(float x, float y, float z) { appear_vec3 v; v.x = x; v.y = y; v.z = z; return v; }
LST_FUNC float lst_dot(appear_vec3 a, appear_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
LST_FUNC appear_vec3 lst_normalize(appear_vec3 a)
{ float il = 1.0f / sqrtf(lst_dot(a, a)); return lst_v(a.x * il, a.y * il, a.z * il); }
LST_FUNC appear_vec3 lst_reflect(appear_vec3 wo, appear_vec3 n) /* pbrt-v4 Reflect */
{ float d = 2.0f * lst_dot(wo, n); return lst_v(-wo.x + d * n.x, -wo.y + d * n.y, -wo.z + d * n.z); }
/* pbrt-v4 CoordinateSystem / Frame::FromZ (Duff et al. 2017) */
LST_FUNC void lst_coordinate_system(appear_vec3 v1, appear_vec3 *v2, appear_vec3 *v3)
{
    float sign = copysignf(1.0f, v1.z), a = -1.0f / (sign + v1.z), b = v1.x * v1.y * a;
    *v2 = lst_v(1.0f + sign * v1.x * v1.x * a, sign * b, -sign * v1.x);
    *v3 = lst_v(b, sign + v1.y * v1.y * a, -v1.y);
}
LST_FUNC appear_spectrum lst_splat(float x) { appear_spectrum s; int i; for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) s.v[i] = x; return s; }
LST_FUNC int lst_fail(appear_bsdf_record *s)
{
    s->wi = lst_v(0, 0, 0); s->f = s->weight = lst_splat(0.0f); s->pdf = 0; s->eta = 1; s->flags = 0;
    return 0;
}
/* the integrator's weight f |cos_i| / pdf, as pbrt-v4's PathIntegrator forms it */
LST_FUNC void lst_weight(appear_bsdf_record *s)
{ int i; float c = fabsf(s->wi.z) / s->pdf; for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) s->weight.v[i] = s->f.v[i] * c; }

/* ======================================================================== */
/* Lambert: f = R / pi; cosine-weighted hemisphere sampling (Malley's
   method, polar disk mapping with libm sinf/cosf). Mirrors pbrt-v4
   DiffuseBxDF (f, PDF, Sample_f; pbrt-v4 uses the concentric disk map for
   SampleCosineHemisphere, the polar one is used here because appear uses it:
   the same (u1, u2) then give the same wi). */
/* ======================================================================== */
/* pbrt-v4 DiffuseBxDF::f (src/pbrt/bxdfs.h): "if (!SameHemisphere(wo, wi)) return
   SampledSpectrum(0.f); return R * InvPi;" with pbrt-v4's SampledSpectrum of NSpectrumSamples = 4
   wavelengths (lst_sampled; the bench fills the fourth with 0, so the sum matches appear's RGB).
   The width matters to the code a compiler makes: with four lanes clang keeps pbrt's early
   return a branch; a three-float struct it if-converts into a select whose data dependency
   doubles the chain's latency (7.7 ns against pbrt's own 1.8 ns, issue 36). */
typedef struct lst_sampled { float v[4]; } lst_sampled;
LST_FUNC lst_sampled lst_lambert_eval(lst_sampled R, appear_vec3 wo, appear_vec3 wi)
{
    lst_sampled z = { { 0, 0, 0, 0 } };
    int i;
    if (!(wo.z * wi.z > 0)) return z;   /* SameHemisphere */
    for (i = 0; i < 4; ++i) R.v[i] *= LST_INV_PI; /* SampledSpectrum::operator*(Float) */
    return R;
}
LST_FUNC float lst_lambert_pdf(appear_vec3 wo, appear_vec3 wi)
{ return wo.z * wi.z > 0 ? fabsf(wi.z) * LST_INV_PI : 0.0f; }
LST_FUNC int lst_lambert_sample(appear_spectrum R, appear_vec3 wo, float u1, float u2, appear_bsdf_record *s)
{
    float r = sqrtf(u1), phi = 2.0f * LST_PI * u2, z = sqrtf(fmaxf(0.0f, 1.0f - u1));
    int i;
    if (wo.z < 0) z = -z;
    s->wi = lst_v(r * cosf(phi), r * sinf(phi), z);
    s->pdf = fabsf(z) * LST_INV_PI;
    if (s->pdf == 0) return lst_fail(s);
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) { s->f.v[i] = R.v[i] * LST_INV_PI; s->weight.v[i] = R.v[i]; }
    s->eta = 1; s->flags = APPEAR_LOBE_REFLECTION | APPEAR_LOBE_DIFFUSE;
    return 1;
}

/* ---- EON rough diffuse: the paper's GLSL listing [Portsmouth25] (f_EON with E_FON_exact,
   sample_EON / pdf_EON with CLTC), transcribed to C float and libm as a renderer would ship
   it: acosf, powf(r, 0.1) per call, the max(1e-7, .) guards; upper hemisphere only (the
   OpenPBR viewer returns 0 below DENOM_TOLERANCE). FON alone: its single-scattering term. */
#define LST_FON_C1 (0.5f - 2.0f / (3.0f * LST_PI))
#define LST_FON_C2 (2.0f / 3.0f - 28.0f / (15.0f * LST_PI))
typedef struct lst_eon { appear_spectrum rho; float r; } lst_eon;
LST_FUNC appear_spectrum lst_fon_eval(const lst_eon *m, appear_vec3 wo, appear_vec3 wi)
{
    float s = lst_dot(wi, wo) - wi.z * wo.z, stinv = s > 0.0f ? s / fmaxf(wi.z, wo.z) : s;
    float af = 1.0f / (1.0f + LST_FON_C1 * m->r), k = LST_INV_PI * af * (1.0f + m->r * stinv);
    appear_spectrum f; int i;
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return lst_splat(0.0f);
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) f.v[i] = m->rho.v[i] * k;
    return f;
}
LST_FUNC float lst_e_fon_exact(float mu, float r)
{
    float af = 1.0f / (1.0f + LST_FON_C1 * r), bf = r * af, si = sqrtf(1.0f - mu * mu);
    float g = si * (acosf(mu) - si * mu) + (2.0f / 3.0f) * ((si / mu) * (1.0f - si * si * si) - si);
    return af + (bf * LST_INV_PI) * g;
}
LST_FUNC appear_spectrum lst_eon_eval(const lst_eon *m, appear_vec3 wo, appear_vec3 wi)
{
    float s = lst_dot(wi, wo) - wi.z * wo.z, stinv = s > 0.0f ? s / fmaxf(wi.z, wo.z) : s;
    float af = 1.0f / (1.0f + LST_FON_C1 * m->r), efo, efi, avg;
    appear_spectrum f; int i;
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return lst_splat(0.0f);
    efo = lst_e_fon_exact(wo.z, m->r); efi = lst_e_fon_exact(wi.z, m->r);
    avg = af * (1.0f + LST_FON_C2 * m->r);
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) {
        float rho = m->rho.v[i], rho_ms = rho * rho * avg / (1.0f - rho * (1.0f - avg));
        f.v[i] = rho * LST_INV_PI * af * (1.0f + m->r * stinv) +
                 rho_ms * LST_INV_PI * fmaxf(1e-7f, 1.0f - efo) * fmaxf(1e-7f, 1.0f - efi) / fmaxf(1e-7f, 1.0f - avg);
    }
    return f;
}
LST_FUNC void lst_ltc_terms(float mu, float r, float *a, float *b, float *c, float *d)
{
    *a = 1.0f + r * (0.303392f + (-0.518982f + 0.111709f * mu) * mu + (-0.276266f + 0.335918f * mu) * r);
    *b = r * (-1.16407f + 1.15859f * mu + (0.150815f - 0.150105f * mu) * r) / (mu * mu * mu - 1.43545f);
    *c = 1.0f + (0.20013f + (-0.506373f + 0.261777f * mu) * mu) * r;
    *d = ((0.540852f + (-1.01625f + 0.475392f * mu) * mu) * r) / (-1.0743f + mu * (0.0725628f + mu));
}
LST_FUNC void lst_basis_ltc(appear_vec3 w, appear_vec3 *x, appear_vec3 *y)
{
    float l2 = w.x * w.x + w.y * w.y, il = l2 > 0.0f ? 1.0f / sqrtf(l2) : 0.0f;
    *x = l2 > 0.0f ? lst_v(w.x * il, w.y * il, 0.0f) : lst_v(1.0f, 0.0f, 0.0f);
    *y = lst_v(-x->y, x->x, 0.0f);
}
LST_FUNC float lst_cltc_pdf(appear_vec3 wo, appear_vec3 wi_l, float r)
{
    appear_vec3 x, y, w;
    float a, b, c, d, det, l2, vz, s, hx, hy, hz;
    lst_basis_ltc(wo, &x, &y);
    w = lst_v(lst_dot(x, wi_l), lst_dot(y, wi_l), wi_l.z);
    lst_ltc_terms(wo.z, r, &a, &b, &c, &d);
    det = c * (a - b * d);
    hx = c * (w.x - b * w.z); hy = (a - b * d) * w.y; hz = -c * (d * w.x - a * w.z);
    l2 = hx * hx + hy * hy + hz * hz;
    vz = 1.0f / sqrtf(d * d + 1.0f); s = 0.5f * (1.0f + vz);
    return (det / l2) * (det / l2) * fmaxf(hz, 0.0f) / (LST_PI * s);
}
LST_FUNC float lst_eon_pdf(const lst_eon *m, appear_vec3 wo, appear_vec3 wi)
{
    float mu = wo.z, pu = powf(m->r, 0.1f) * (0.162925f + mu * (-0.372058f + (0.538233f - 0.290822f * mu) * mu));
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
    return pu / (2.0f * LST_PI) + (1.0f - pu) * lst_cltc_pdf(wo, wi, m->r);
}
LST_FUNC int lst_eon_sample(const lst_eon *m, appear_vec3 wo, float u1, float u2, appear_bsdf_record *s)
{
    float mu = wo.z, pu = powf(m->r, 0.1f) * (0.162925f + mu * (-0.372058f + (0.538233f - 0.290822f * mu) * mu));
    float pc = 1.0f - pu, pdf_c, phi = 2.0f * LST_PI * u2;
    appear_vec3 wi;
    int i;
    if (!(wo.z > 0.0f)) return lst_fail(s);
    if (u1 <= pu) {                                             /* uniform_lobe_sample */
        float z = u1 / pu, r = sqrtf(1.0f - z * z);
        wi = lst_v(r * cosf(phi), r * sinf(phi), z);
        pdf_c = lst_cltc_pdf(wo, wi, m->r);
    } else {                                                    /* cltc_sample */
        float a, b, c, d, rr, x, y, vz, sc, len, det, pdf_wh;
        appear_vec3 wh, ex, ey, w;
        lst_ltc_terms(wo.z, m->r, &a, &b, &c, &d);
        u1 = (u1 - pu) / pc;
        rr = sqrtf(u1); x = rr * cosf(phi); y = rr * sinf(phi);
        vz = 1.0f / sqrtf(d * d + 1.0f); sc = 0.5f * (1.0f + vz);
        x = -((1.0f - sc) * sqrtf(1.0f - y * y) + sc * x);      /* -mix(sqrt(1 - y^2), x, s) */
        wh = lst_v(x, y, sqrtf(fmaxf(1.0f - (x * x + y * y), 0.0f)));
        pdf_wh = wh.z / (LST_PI * sc);
        w = lst_v(a * wh.x + b * wh.z, c * wh.y, d * wh.x + wh.z);
        len = sqrtf(lst_dot(w, w)); det = c * (a - b * d);
        pdf_c = pdf_wh * len * len * len / det;
        lst_basis_ltc(wo, &ex, &ey);
        wi = lst_normalize(lst_v(ex.x * w.x + ey.x * w.y, ex.y * w.x + ey.y * w.y, w.z));
    }
    s->wi = wi;
    s->pdf = pu / (2.0f * LST_PI) + pc * pdf_c;
    s->f = lst_eon_eval(m, wo, wi);
    if (!(s->pdf > 0.0f) || !(wi.z > 0.0f)) return lst_fail(s);
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) s->weight.v[i] = s->f.v[i] * wi.z / s->pdf;
    s->eta = 1; s->flags = APPEAR_LOBE_REFLECTION | APPEAR_LOBE_DIFFUSE;
    return 1;
}

/* ======================================================================== */
/* Phase functions                                                           */
/* ======================================================================== */
/* Isotropic: pbrt-v4 SampleUniformSphere (z = 1 - 2 u1, phi = 2 pi u2). */
LST_FUNC int lst_isotropic_sample(appear_vec3 wo, float u1, float u2, appear_phase_record *s)
{
    float z = 1.0f - 2.0f * u1, r = sqrtf(fmaxf(0.0f, 1.0f - z * z)), phi = 2.0f * LST_PI * u2;
    (void)wo;
    s->wi = lst_v(r * cosf(phi), r * sinf(phi), z);
    s->f = s->pdf = LST_INV_4PI; s->weight = 1; s->flags = APPEAR_LOBE_DIFFUSE;
    return 1;
}
/* Henyey-Greenstein [HG41], pbrt-v4 HenyeyGreenstein(Dot(wo, wi), g)
   (src/pbrt/util/scattering.h): g clamped to [-0.99, 0.99] ("isn't suitable
   for |g| ~ 1"); pbrt-v4 also has wo pointing away, so its denominator 1 +
   g^2 + 2 g dot(wo, wi) is appear's 1 + g^2 - 2 g mu with mu = -dot(wo, wi). */
LST_FUNC float lst_hg_eval(float g, appear_vec3 wo, appear_vec3 wi)
{
    float denom;
    g = fminf(fmaxf(g, -.99f), .99f);
    denom = 1 + g * g + 2 * g * lst_dot(wo, wi);
    return LST_INV_4PI * (1 - g * g) / (denom * sqrtf(fmaxf(denom, 0.0f)));
}
/* pbrt-v4 SampleHenyeyGreenstein (src/pbrt/util/sampling.cpp): the inverse
   CDF in cos theta measured from wo (so with the -1/(2g) sign), isotropic
   fallback for |g| < 1e-3, the frame Frame::FromZ(wo), pdf =
   HenyeyGreenstein(cosTheta, g), the pdf of the sampled cosine. _unclamped
   skips pbrt's clamp of g to 0.99: the bench's measure of that pdf's error
   near |g| = 1, not pbrt's function. */
LST_FUNC int lst_hg_sample_unclamped(float g, appear_vec3 wo, float u1, float u2, appear_phase_record *s)
{
    float cosTheta, sinTheta, phi, denom, sx, sy;
    appear_vec3 t1, t2;
    if (fabsf(g) < 1e-3f) cosTheta = 1 - 2 * u1;
    else {
        float q = (1 - g * g) / (1 + g - 2 * g * u1);
        cosTheta = -1 / (2 * g) * (1 + g * g - q * q);
    }
    sinTheta = sqrtf(fmaxf(0.0f, 1 - cosTheta * cosTheta));
    phi = 2 * LST_PI * u2;
    lst_coordinate_system(wo, &t1, &t2);
    sx = sinTheta * cosf(phi); sy = sinTheta * sinf(phi);
    s->wi = lst_v(sx * t1.x + sy * t2.x + cosTheta * wo.x, sx * t1.y + sy * t2.y + cosTheta * wo.y,
                  sx * t1.z + sy * t2.z + cosTheta * wo.z);
    denom = 1 + g * g + 2 * g * cosTheta;
    s->f = s->pdf = LST_INV_4PI * (1 - g * g) / (denom * sqrtf(fmaxf(denom, 0.0f))); /* SafeSqrt */
    s->weight = 1; s->flags = APPEAR_LOBE_GLOSSY;
    return 1;
}
LST_FUNC int lst_hg_sample(float g, appear_vec3 wo, float u1, float u2, appear_phase_record *s)
{ return lst_hg_sample_unclamped(fminf(fmaxf(g, -.99f), .99f), wo, u1, u2, s); }
/* The textbook HG inverse CDF (e.g. pbrt-v3), float, libm, with a frame about
   -wo (appear_frame_from_normal) and sinf/cosf; its pdf by the textbook
   formula. Moved here from bench/bench_core.c (its "textbook" rows). */
LST_FUNC appear_vec3 lst_hg_sample_textbook(float g, appear_vec3 wo, float u1, float u2, float *pdf)
{
    float mu, t, st, phi, d;
    appear_frame f;
    if (fabsf(g) < 1e-3f) mu = 2.0f * u1 - 1.0f; /* pbrt-v3's isotropic fallback near g = 0 */
    else { t = (1.0f - g * g) / (1.0f - g + 2.0f * g * u1); mu = (1.0f + g * g - t * t) / (2.0f * g); }
    st = sqrtf(fmaxf(0.0f, 1.0f - mu * mu));
    phi = 6.2831853f * u2;
    f = appear_frame_from_normal(appear_neg(wo));
    d = 1.0f + g * g - 2.0f * g * mu;
    *pdf = 0.0795774715f * (1.0f - g * g) / (d * sqrtf(d));
    return appear_frame_to_world(f, appear_vec3_make(st * cosf(phi), st * sinf(phi), mu));
}

/* ======================================================================== */
/* Fresnel                                                                   */
/* ======================================================================== */
/* Dielectric [BW99 Sec. 1.5], pbrt-v4 FrDielectric: cos_i < 0 flips to the
   inside (eta -> 1/eta); early exit under total internal reflection. */
LST_FUNC float lst_fresnel_dielectric(float cosTheta_i, float eta)
{
    float sin2Theta_i, sin2Theta_t, cosTheta_t, r_parl, r_perp;
    cosTheta_i = fminf(fmaxf(cosTheta_i, -1.0f), 1.0f);
    if (cosTheta_i < 0) { eta = 1 / eta; cosTheta_i = -cosTheta_i; }
    sin2Theta_i = 1 - cosTheta_i * cosTheta_i;
    sin2Theta_t = sin2Theta_i / (eta * eta);
    if (sin2Theta_t >= 1) return 1.f;
    cosTheta_t = sqrtf(fmaxf(0.0f, 1 - sin2Theta_t));
    r_parl = (eta * cosTheta_i - cosTheta_t) / (eta * cosTheta_i + cosTheta_t);
    r_perp = (cosTheta_i - eta * cosTheta_t) / (cosTheta_i + eta * cosTheta_t);
    return (r_parl * r_parl + r_perp * r_perp) / 2;
}
/* Conductor, complex IOR eta + i k [BW99 Ch. 14], pbrt-v4 FrComplex: Snell
   in complex arithmetic (pbrt's pstd::complex: sqrt by the half-angle
   formulas, division by |d|^2), F = (|r_parl|^2 + |r_perp|^2) / 2. */
typedef struct { float re, im; } lst_cx;
LST_FUNC lst_cx lst_cx_make(float re, float im) { lst_cx z; z.re = re; z.im = im; return z; }
LST_FUNC lst_cx lst_cx_mul(lst_cx a, lst_cx b) { return lst_cx_make(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re); }
LST_FUNC lst_cx lst_cx_div(lst_cx a, lst_cx b)
{
    float s = 1 / (b.re * b.re + b.im * b.im);
    return lst_cx_make(s * (a.re * b.re + a.im * b.im), s * (a.im * b.re - a.re * b.im));
}
LST_FUNC lst_cx lst_cx_sqrt(lst_cx z) /* pbrt-v4 pstd::sqrt(complex) */
{
    float n = sqrtf(z.re * z.re + z.im * z.im), t1, t2;
    if (n == 0) return lst_cx_make(0, 0);
    t1 = sqrtf(0.5f * (n + fabsf(z.re))); t2 = 0.5f * z.im / t1;
    if (z.re >= 0) return lst_cx_make(t1, t2);
    return lst_cx_make(fabsf(t2), copysignf(t1, z.im));
}
LST_FUNC float lst_fresnel_complex(float cosTheta_i, float eta_re, float eta_k)
{
    lst_cx eta = lst_cx_make(eta_re, eta_k), sin2t, cost, ec, rpa, rpe;
    float sin2Theta_i;
    cosTheta_i = fminf(fmaxf(cosTheta_i, 0.0f), 1.0f);
    sin2Theta_i = 1 - cosTheta_i * cosTheta_i;
    sin2t = lst_cx_div(lst_cx_make(sin2Theta_i, 0), lst_cx_mul(eta, eta));
    cost = lst_cx_sqrt(lst_cx_make(1 - sin2t.re, -sin2t.im));
    ec = lst_cx_make(eta.re * cosTheta_i, eta.im * cosTheta_i);
    rpa = lst_cx_div(lst_cx_make(ec.re - cost.re, ec.im - cost.im), lst_cx_make(ec.re + cost.re, ec.im + cost.im));
    {
        lst_cx ect = lst_cx_mul(eta, cost);
        rpe = lst_cx_div(lst_cx_make(cosTheta_i - ect.re, -ect.im), lst_cx_make(cosTheta_i + ect.re, ect.im));
    }
    return (rpa.re * rpa.re + rpa.im * rpa.im + rpe.re * rpe.re + rpe.im * rpe.im) / 2;
}
/* pbrt-v4 FrComplex(Float, SampledSpectrum eta, SampledSpectrum k): per channel */
LST_FUNC appear_spectrum lst_fresnel_complex_spectrum(float cosTheta_i, appear_spectrum eta, appear_spectrum k)
{
    appear_spectrum r; int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) r.v[i] = lst_fresnel_complex(cosTheta_i, eta.v[i], k.v[i]);
    return r;
}
/* Mitsuba 3 fresnel_conductor (include/mitsuba/render/fresnel.h), after Moeller's "Optics":
   real arithmetic, two square roots and two divisions; dr::safe_sqrt is sqrt(max(x, 0)); no
   clamp of cos_theta_i (its callers pass dot(wi, m) > 0). */
LST_FUNC float lst_safe_sqrt(float x) { return sqrtf(fmaxf(x, 0.0f)); }
LST_FUNC float lst_fresnel_conductor_mi3(float cos_theta_i, float eta_r, float eta_i)
{
    float cos_theta_i_2 = cos_theta_i * cos_theta_i, sin_theta_i_2 = 1.f - cos_theta_i_2,
          sin_theta_i_4 = sin_theta_i_2 * sin_theta_i_2;
    float temp_1 = eta_r * eta_r - eta_i * eta_i - sin_theta_i_2,
          a_2_pb_2 = lst_safe_sqrt(temp_1 * temp_1 + 4.f * eta_i * eta_i * eta_r * eta_r),
          a = lst_safe_sqrt(.5f * (a_2_pb_2 + temp_1));
    float term_1 = a_2_pb_2 + cos_theta_i_2, term_2 = 2.f * cos_theta_i * a;
    float r_s = (term_1 - term_2) / (term_1 + term_2);
    float term_3 = a_2_pb_2 * cos_theta_i_2 + sin_theta_i_4, term_4 = term_2 * sin_theta_i_2;
    float r_p = r_s * (term_3 - term_4) / (term_3 + term_4);
    return 0.5f * (r_s + r_p);
}
/* Schlick [Schlick94 Eq. 24]: F0 + (1 - F0)(1 - cos)^5, pbrt-v3 FrSchlick /
   Mitsuba 3 fresnel "schlick" form (cos >= 0 expected, no clamping). */
LST_FUNC float lst_fresnel_schlick(float c, float f0)
{ float m = 1 - c, m2 = m * m; return f0 + (1 - f0) * (m2 * m2 * m); }

/* ======================================================================== */
/* GGX (Trowbridge-Reitz), pbrt-v4 TrowbridgeReitzDistribution              */
/* ======================================================================== */
/* pbrt-v4 spherical helpers (vecmath.h) */
LST_FUNC float lst_cos2(appear_vec3 w) { return w.z * w.z; }
LST_FUNC float lst_sin2(appear_vec3 w) { return fmaxf(0.0f, 1 - lst_cos2(w)); }
LST_FUNC float lst_tan2(appear_vec3 w) { return lst_sin2(w) / lst_cos2(w); }
LST_FUNC float lst_cosphi(appear_vec3 w)
{ float st = sqrtf(lst_sin2(w)); return st == 0 ? 1 : fminf(fmaxf(w.x / st, -1.0f), 1.0f); }
LST_FUNC float lst_sinphi(appear_vec3 w)
{ float st = sqrtf(lst_sin2(w)); return st == 0 ? 0 : fminf(fmaxf(w.y / st, -1.0f), 1.0f); }
/* D(wm) [Walter07 Eq. 33; anisotropic, Heitz14 Eq. 85], pbrt-v4 D() */
LST_FUNC float lst_ggx_D(float ax, float ay, appear_vec3 wm)
{
    float tan2Theta = lst_tan2(wm), cos4Theta, cp, sp, e;
    if (isinf(tan2Theta)) return 0;
    cos4Theta = lst_cos2(wm) * lst_cos2(wm);
    if (cos4Theta < 1e-16f) return 0;
    cp = lst_cosphi(wm) / ax; sp = lst_sinphi(wm) / ay;
    e = tan2Theta * (cp * cp + sp * sp);
    return 1 / (LST_PI * ax * ay * cos4Theta * (1 + e) * (1 + e));
}
/* Smith Lambda [Heitz14 Eq. 86], pbrt-v4 Lambda() (0 at grazing, as pbrt) */
LST_FUNC float lst_ggx_lambda(float ax, float ay, appear_vec3 w)
{
    float tan2Theta = lst_tan2(w), cp, sp, alpha2;
    if (isinf(tan2Theta)) return 0;
    cp = lst_cosphi(w) * ax; sp = lst_sinphi(w) * ay;
    alpha2 = cp * cp + sp * sp;
    return (sqrtf(1 + alpha2 * tan2Theta) - 1) / 2;
}
LST_FUNC float lst_ggx_G1(float ax, float ay, appear_vec3 w) { return 1 / (1 + lst_ggx_lambda(ax, ay, w)); }
LST_FUNC float lst_ggx_G(float ax, float ay, appear_vec3 wo, appear_vec3 wi) /* height-correlated [Heitz14 Eq. 99] */
{ return 1 / (1 + lst_ggx_lambda(ax, ay, wo) + lst_ggx_lambda(ax, ay, wi)); }
/* visible-normal pdf D_w(wm) = G1(w) / |cos w| D(wm) |w.wm| [Heitz14 Eq. 16], pbrt-v4 PDF(w, wm) / D(w, wm) */
LST_FUNC float lst_ggx_pdf_visible(float ax, float ay, appear_vec3 w, appear_vec3 wm)
{ return lst_ggx_G1(ax, ay, w) / fabsf(w.z) * lst_ggx_D(ax, ay, wm) * fabsf(lst_dot(w, wm)); }
/* Visible-normal sample [Heitz18 listing 1], as pbrt-v4 Sample_wm writes it:
   stretch, basis from cross((0,0,1), wh), polar disk sample (libm
   sqrtf/cosf/sinf), warp to the visible half disk, lift, unstretch. wo on
   either side (wh flipped up). */
LST_FUNC appear_vec3 lst_ggx_sample_wm(float ax, float ay, appear_vec3 w, float u1, float u2)
{
    appear_vec3 wh = lst_normalize(lst_v(ax * w.x, ay * w.y, w.z)), T1, T2, nh;
    float r, th, px, py, h, s, pz;
    if (wh.z < 0) wh = lst_v(-wh.x, -wh.y, -wh.z);
    T1 = (wh.z < 0.99999f) ? lst_normalize(lst_v(-wh.y, wh.x, 0)) : lst_v(1, 0, 0);
    T2 = lst_v(wh.y * T1.z - wh.z * T1.y, wh.z * T1.x - wh.x * T1.z, wh.x * T1.y - wh.y * T1.x);
    r = sqrtf(u1); th = 2 * LST_PI * u2;                  /* SampleUniformDiskPolar */
    px = r * cosf(th); py = r * sinf(th);
    h = sqrtf(1 - px * px);
    s = (1 + wh.z) / 2;
    py = (1 - s) * h + s * py;                            /* Lerp((1 + wh.z) / 2, h, p.y) */
    pz = sqrtf(fmaxf(0.0f, 1 - px * px - py * py));
    nh = lst_v(px * T1.x + py * T2.x + pz * wh.x, px * T1.y + py * T2.y + pz * wh.y, px * T1.z + py * T2.z + pz * wh.z);
    return lst_normalize(lst_v(ax * nh.x, ay * nh.y, fmaxf(1e-6f, nh.z)));
}
/* [Heitz18] Listing 1, transcribed plainly (float, libm) in the listing's own
   steps; moved here from bench/bench_batch.c (bench_microfacet.c had a second
   transcription of the same listing; both files now use this one). */
LST_FUNC appear_vec3 lst_heitz18_vndf(appear_vec3 Ve, float alpha_x, float alpha_y, float U1, float U2)
{
    /* Section 3.2: transform the view direction to the hemisphere configuration */
    appear_vec3 Vh = appear_vec3_make(alpha_x * Ve.x, alpha_y * Ve.y, Ve.z), T1, T2, Nh, Ne;
    float l = sqrtf(Vh.x * Vh.x + Vh.y * Vh.y + Vh.z * Vh.z), lensq, r, phi, t1, t2, s;
    Vh = appear_vec3_make(Vh.x / l, Vh.y / l, Vh.z / l);
    /* Section 4.1: orthonormal basis (with special case if cross product is zero) */
    lensq = Vh.x * Vh.x + Vh.y * Vh.y;
    T1 = lensq > 0 ? appear_vec3_make(-Vh.y / sqrtf(lensq), Vh.x / sqrtf(lensq), 0) : appear_vec3_make(1, 0, 0);
    T2 = appear_cross(Vh, T1);
    /* Section 4.2: parameterization of the projected area */
    r = sqrtf(U1);
    phi = 2.0f * 3.14159265f * U2;
    t1 = r * cosf(phi);
    t2 = r * sinf(phi);
    s = 0.5f * (1.0f + Vh.z);
    t2 = (1.0f - s) * sqrtf(1.0f - t1 * t1) + s * t2;
    /* Section 4.3: reprojection onto hemisphere */
    {
        float w = 1.0f - t1 * t1 - t2 * t2;
        float h = sqrtf(w > 0 ? w : 0);
        Nh = appear_vec3_make(t1 * T1.x + t2 * T2.x + h * Vh.x, t1 * T1.y + t2 * T2.y + h * Vh.y,
                              t1 * T1.z + t2 * T2.z + h * Vh.z);
    }
    /* Section 3.4: transform the normal back to the ellipsoid configuration */
    Ne = appear_vec3_make(alpha_x * Nh.x, alpha_y * Nh.y, Nh.z > 0 ? Nh.z : 0);
    l = sqrtf(Ne.x * Ne.x + Ne.y * Ne.y + Ne.z * Ne.z);
    return appear_vec3_make(Ne.x / l, Ne.y / l, Ne.z / l);
}

/* ======================================================================== */
/* Beckmann, as Mitsuba 3 MicrofacetDistribution (type Beckmann)            */
/* ======================================================================== */
/* D(m) [Walter07 Eq. 25, anisotropic], Mitsuba 3 eval(): exp of the slope
   term over cos^2, the 1e-20 cut of Mitsuba's select. */
LST_FUNC float lst_beckmann_D(float ax, float ay, appear_vec3 m)
{
    float ct = m.z, ct2 = ct * ct, x = m.x / ax, y = m.y / ay;
    float r = expf(-(x * x + y * y) / ct2) / (LST_PI * ax * ay * ct2 * ct2);
    return r * ct > 1e-20f ? r : 0.0f;
}
/* erfinv: M. Giles, "Approximating the erfinv function" (GPU Gems 4 /
   2010), the single-precision branch pair: what Dr.Jit's erfinv and
   pbrt-v3's ErfInv evaluate (libm has no erfinvf). */
LST_FUNC float lst_erfinv(float x)
{
    float w = -logf((1.0f - x) * (1.0f + x)), p;
    if (w < 5.0f) {
        w = w - 2.5f;
        p = 2.81022636e-08f;
        p = 3.43273939e-07f + p * w; p = -3.5233877e-06f + p * w; p = -4.39150654e-06f + p * w;
        p = 0.00021858087f + p * w; p = -0.00125372503f + p * w; p = -0.00417768164f + p * w;
        p = 0.246640727f + p * w; p = 1.50140941f + p * w;
    } else {
        w = sqrtf(w) - 3.0f;
        p = -0.000200214257f;
        p = 0.000100950558f + p * w; p = 0.00134934322f + p * w; p = -0.00367342844f + p * w;
        p = 0.00573950773f + p * w; p = -0.0076224613f + p * w; p = 0.00943887047f + p * w;
        p = 1.00167406f + p * w; p = 2.83297682f + p * w;
    }
    return p * x;
}
/* Visible normals [HdE14], Mitsuba 3 MicrofacetDistribution::sample():
   stretch wi, sincos_phi of the stretched direction, sample_visible_11
   (Beckmann: the CDF of the slope inverted in the erf domain: initial guess
   x = erf(cot) - (erf(cot) + 1) erf(sqrt(-log u1)), the exact solution at
   grazing; then three unguarded Newton steps on
   1 + x + tan exp(-erfinv(x)^2) / sqrt(pi) = u1 (1 + erf(cot) + tan exp(-cot^2)/sqrt(pi));
   slope = erfinv(x, 2 u2 - 1), samples clamped to [1e-6, 1 - 1e-6]),
   rotate, unstretch, m = normalize(-slope, 1). libm erff/expf/logf, Giles'
   erfinv. Mitsuba's sample() also returns the pdf; appear's sampler returns
   m only, so the pdf is left out here. wo with z > 0 (Mitsuba's
   convention: the caller mirrors). */
LST_FUNC appear_vec3 lst_beckmann_sample_visible(float ax, float ay, appear_vec3 wi, float u1, float u2)
{
    appear_vec3 wp = lst_normalize(lst_v(ax * wi.x, ay * wi.y, wi.z));
    float st2 = 1 - wp.z * wp.z, sin_phi, cos_phi, ct = wp.z, tan_t, cot_t, maxval, x, sx, sy;
    int i;
    {   /* Frame3f::sincos_phi */
        float inv = 1 / sqrtf(st2);
        if (fabsf(st2) <= 4.0f * 5.96046448e-8f) { cos_phi = 1; sin_phi = 0; }
        else { cos_phi = fminf(fmaxf(wp.x * inv, -1.0f), 1.0f); sin_phi = fminf(fmaxf(wp.y * inv, -1.0f), 1.0f); }
    }
    tan_t = sqrtf(fmaxf(0.0f, 1 - ct * ct)) / ct;
    cot_t = 1 / tan_t;
    maxval = erff(cot_t);
    u1 = fmaxf(fminf(u1, 1.0f - 1e-6f), 1e-6f); u2 = fmaxf(fminf(u2, 1.0f - 1e-6f), 1e-6f);
    x = maxval - (maxval + 1.0f) * erff(sqrtf(-logf(u1)));
    u1 *= 1.0f + maxval + LST_INV_SQRT_PI * tan_t * expf(-cot_t * cot_t);
    for (i = 0; i < 3; ++i) {
        float slope = lst_erfinv(x);
        float value = 1.0f + x + LST_INV_SQRT_PI * tan_t * expf(-slope * slope) - u1;
        float derivative = 1.0f - slope * tan_t;
        x -= value / derivative;
    }
    sx = lst_erfinv(x); sy = lst_erfinv(2.0f * u2 - 1.0f);
    {
        float px = (cos_phi * sx - sin_phi * sy) * ax, py = (sin_phi * sx + cos_phi * sy) * ay;
        return lst_normalize(lst_v(-px, -py, 1.0f));
    }
}
/* Exact Smith Lambda of Beckmann [Heitz14 Eq. 72, Walter07 Eq. 27 before the
   fit] with libm erfcf/expf (pbrt-v3 BeckmannDistribution uses Walter's
   rational fit instead; appear's conductor uses the exact one, so does this). */
LST_FUNC float lst_beckmann_lambda(float ax, float ay, appear_vec3 w)
{
    float tan2 = lst_tan2(w), cp, sp, a;
    if (isinf(tan2)) return 0;
    cp = lst_cosphi(w) * ax; sp = lst_sinphi(w) * ay;
    a = 1 / sqrtf((cp * cp + sp * sp) * tan2);
    return (expf(-a * a) / (a * 1.77245385f) - erfcf(a)) / 2;
}

/* ======================================================================== */
/* Rough conductor, pbrt-v4 ConductorBxDF (f, PDF, Sample_f), RGB           */
/* f = D F(|wo.h|) G2 / (4 |cos_o| |cos_i|) [Walter07 Eq. 20, Heitz14 Eq. 99] */
/* ======================================================================== */
typedef struct lst_conductor {
    int beckmann;             /* 0: TrowbridgeReitz (pbrt-v4); 1: Beckmann (D, sampler: Mitsuba 3; exact Lambda) */
    float ax, ay;
    appear_spectrum eta, k;
} lst_conductor;
LST_FUNC float lst_mf_D(const lst_conductor *c, appear_vec3 m)
{ return c->beckmann ? lst_beckmann_D(c->ax, c->ay, m) : lst_ggx_D(c->ax, c->ay, m); }
LST_FUNC float lst_mf_lambda(const lst_conductor *c, appear_vec3 w)
{ return c->beckmann ? lst_beckmann_lambda(c->ax, c->ay, w) : lst_ggx_lambda(c->ax, c->ay, w); }
LST_FUNC float lst_mf_pdf(const lst_conductor *c, appear_vec3 w, appear_vec3 wm) /* pbrt-v4 PDF(w, wm) */
{ return 1 / (1 + lst_mf_lambda(c, w)) / fabsf(w.z) * lst_mf_D(c, wm) * fabsf(lst_dot(w, wm)); }
LST_FUNC appear_spectrum lst_conductor_eval(const lst_conductor *c, appear_vec3 wo, appear_vec3 wi)
{
    float cto = fabsf(wo.z), cti = fabsf(wi.z), l2, x;
    appear_vec3 wm;
    appear_spectrum F;
    int i;
    if (!(wo.z * wi.z > 0)) return lst_splat(0.0f);
    if (cti == 0 || cto == 0) return lst_splat(0.0f);
    wm = lst_v(wi.x + wo.x, wi.y + wo.y, wi.z + wo.z);
    l2 = lst_dot(wm, wm);
    if (l2 == 0) return lst_splat(0.0f);
    wm = lst_normalize(wm);
    F = lst_fresnel_complex_spectrum(fabsf(lst_dot(wo, wm)), c->eta, c->k);
    x = lst_mf_D(c, wm) / (1 + lst_mf_lambda(c, wo) + lst_mf_lambda(c, wi)) / (4 * cti * cto);
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) F.v[i] *= x;
    return F;
}
LST_FUNC float lst_conductor_pdf(const lst_conductor *c, appear_vec3 wo, appear_vec3 wi)
{
    appear_vec3 wm;
    if (!(wo.z * wi.z > 0)) return 0;
    wm = lst_v(wo.x + wi.x, wo.y + wi.y, wo.z + wi.z);
    if (lst_dot(wm, wm) == 0) return 0;
    wm = lst_normalize(wm);
    if (wm.z < 0) wm = lst_v(-wm.x, -wm.y, -wm.z);          /* FaceForward */
    return lst_mf_pdf(c, wo, wm) / (4 * fabsf(lst_dot(wo, wm)));
}
LST_FUNC int lst_conductor_sample(const lst_conductor *c, appear_vec3 wo, float u1, float u2, appear_bsdf_record *s)
{
    appear_vec3 wm, wi, wop = wo;
    float cto, cti, x;
    int i;
    if (wo.z == 0) return lst_fail(s);
    if (c->beckmann) { /* Mitsuba's sampler wants wo.z > 0 (its BSDF mirrors) */
        if (wop.z < 0) wop = lst_v(-wo.x, -wo.y, -wo.z);
        wm = lst_beckmann_sample_visible(c->ax, c->ay, wop, u1, u2);
    } else wm = lst_ggx_sample_wm(c->ax, c->ay, wo, u1, u2);
    wi = lst_reflect(wo, wm);
    if (!(wo.z * wi.z > 0)) return lst_fail(s);
    s->pdf = lst_mf_pdf(c, wo, wm) / (4 * fabsf(lst_dot(wo, wm)));
    cto = fabsf(wo.z); cti = fabsf(wi.z);
    if (cti == 0 || cto == 0) return lst_fail(s);
    s->f = lst_fresnel_complex_spectrum(fabsf(lst_dot(wo, wm)), c->eta, c->k);
    x = lst_mf_D(c, wm) / (1 + lst_mf_lambda(c, wo) + lst_mf_lambda(c, wi)) / (4 * cti * cto);
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) s->f.v[i] *= x;
    s->wi = wi; s->eta = 1; s->flags = APPEAR_LOBE_REFLECTION | APPEAR_LOBE_GLOSSY;
    lst_weight(s);
    return 1;
}
/* [Walter07] textbook GGX conductor, isotropic: D from tan^2 (Eq. 33),
   separable G = G1 G1 (Eq. 23, 34), appear's exact conductor Fresnel for
   channel 0. Moved here from bench/bench_microfacet.c (its "Walter07
   textbook" row); not the same G as appear (separable, not height-correlated). */
LST_FUNC float lst_walter_D(float alpha, float ct)
{
    float t2 = (1.0f - ct * ct) / (ct * ct), a2 = alpha * alpha;
    return ct > 0 ? a2 / (3.14159265f * powf(ct, 4.0f) * powf(a2 + t2, 2.0f)) : 0.0f;
}
LST_FUNC float lst_walter_G1(float alpha, float ct)
{
    float t2 = (1.0f - ct * ct) / (ct * ct);
    return 2.0f / (1.0f + sqrtf(1.0f + alpha * alpha * t2));
}
LST_FUNC float lst_walter_eval(float alpha, appear_vec3 wo, appear_vec3 wi)
{
    float hx = wo.x + wi.x, hy = wo.y + wi.y, hz = wo.z + wi.z, l = sqrtf(hx * hx + hy * hy + hz * hz), ch, oh;
    if (wo.z <= 0 || wi.z <= 0) return 0;
    hx /= l; hy /= l; hz /= l; ch = hz;
    oh = wo.x * hx + wo.y * hy + wo.z * hz;
    return appear_fresnel_conductor(oh, 0.143f, 3.983f) * lst_walter_D(alpha, ch) * lst_walter_G1(alpha, wo.z) *
           lst_walter_G1(alpha, wi.z) / (4.0f * wo.z * wi.z);
}

/* ======================================================================== */
/* Rough dielectric, pbrt-v4 DielectricBxDF (rough branch), GGX             */
/* [Walter07 Eqs. 16-17, 20-21]; R and T chosen by uc < R / (R + T).         */
/* Radiance convention: pbrt-v4 divides the transmitted f by etap^2 in
   TransportMode::Radiance; appear's dielectric_eval/sample are documented as
   the radiance convention (the smooth limit's weight is 1/e^2), and
   f_appear = (1-F) D G2 |wi.h||wo.h| / (zo |zi| |wo + e wi|^2) equals
   pbrt's radiance-mode ft (pbrt's denominator (wi.h + wo.h/etap)^2 is
   |wo + etap wi|^2 / etap^2). So this mirrors pbrt-v4 in Radiance mode.     */
/* ======================================================================== */
typedef struct lst_dielectric { float ax, ay, eta; } lst_dielectric;
LST_FUNC float lst_diel_D(const lst_dielectric *m, appear_vec3 wm) { return lst_ggx_D(m->ax, m->ay, wm); }
LST_FUNC float lst_diel_G(const lst_dielectric *m, appear_vec3 wo, appear_vec3 wi) { return lst_ggx_G(m->ax, m->ay, wo, wi); }
LST_FUNC float lst_diel_pdfm(const lst_dielectric *m, appear_vec3 w, appear_vec3 wm) { return lst_ggx_pdf_visible(m->ax, m->ay, w, wm); }
/* the generalized half vector of pbrt-v4 f() / PDF(): 0 when invalid */
LST_FUNC int lst_diel_half(const lst_dielectric *m, appear_vec3 wo, appear_vec3 wi, appear_vec3 *wm, float *etap, int *reflect)
{
    float co = wo.z, ci = wi.z;
    appear_vec3 h;
    *reflect = ci * co > 0;
    *etap = 1;
    if (!*reflect) *etap = co > 0 ? m->eta : 1 / m->eta;
    h = lst_v(wi.x * *etap + wo.x, wi.y * *etap + wo.y, wi.z * *etap + wo.z);
    if (ci == 0 || co == 0 || lst_dot(h, h) == 0) return 0;
    h = lst_normalize(h);
    if (h.z < 0) h = lst_v(-h.x, -h.y, -h.z);
    if (lst_dot(h, wi) * ci < 0 || lst_dot(h, wo) * co < 0) return 0;
    *wm = h;
    return 1;
}
LST_FUNC float lst_dielectric_eval(const lst_dielectric *m, appear_vec3 wo, appear_vec3 wi)
{
    appear_vec3 wm;
    float etap, F;
    int reflect;
    if (!lst_diel_half(m, wo, wi, &wm, &etap, &reflect)) return 0;
    F = lst_fresnel_dielectric(lst_dot(wo, wm), m->eta);
    if (reflect) return lst_diel_D(m, wm) * lst_diel_G(m, wo, wi) * F / fabsf(4 * wi.z * wo.z);
    {
        float d = lst_dot(wi, wm) + lst_dot(wo, wm) / etap, denom = d * d * wi.z * wo.z;
        float ft = lst_diel_D(m, wm) * (1 - F) * lst_diel_G(m, wo, wi) * fabsf(lst_dot(wi, wm) * lst_dot(wo, wm) / denom);
        return ft / (etap * etap);                         /* TransportMode::Radiance */
    }
}
LST_FUNC float lst_dielectric_pdf(const lst_dielectric *m, appear_vec3 wo, appear_vec3 wi)
{
    appear_vec3 wm;
    float etap, R, T;
    int reflect;
    if (!lst_diel_half(m, wo, wi, &wm, &etap, &reflect)) return 0;
    R = lst_fresnel_dielectric(lst_dot(wo, wm), m->eta); T = 1 - R;
    if (reflect) return lst_diel_pdfm(m, wo, wm) / (4 * fabsf(lst_dot(wo, wm))) * R / (R + T);
    {
        float d = lst_dot(wi, wm) + lst_dot(wo, wm) / etap;
        return lst_diel_pdfm(m, wo, wm) * (fabsf(lst_dot(wi, wm)) / (d * d)) * T / (R + T);
    }
}
/* pbrt-v4 Refract(wi, n, eta, &etap, &wt) */
LST_FUNC int lst_refract(appear_vec3 wi, appear_vec3 n, float eta, float *etap, appear_vec3 *wt)
{
    float ci = lst_dot(n, wi), s2i, s2t, ct;
    if (ci < 0) { eta = 1 / eta; ci = -ci; n = lst_v(-n.x, -n.y, -n.z); }
    s2i = fmaxf(0.0f, 1 - ci * ci);
    s2t = s2i / (eta * eta);
    if (s2t >= 1) return 0;
    ct = sqrtf(fmaxf(0.0f, 1 - s2t));
    *wt = lst_v(-wi.x / eta + (ci / eta - ct) * n.x, -wi.y / eta + (ci / eta - ct) * n.y, -wi.z / eta + (ci / eta - ct) * n.z);
    *etap = eta;
    return 1;
}
LST_FUNC int lst_dielectric_sample(const lst_dielectric *m, appear_vec3 wo, float uc, float u1, float u2, appear_bsdf_record *s)
{
    appear_vec3 wm = lst_ggx_sample_wm(m->ax, m->ay, wo, u1, u2), wi;
    float R = lst_fresnel_dielectric(lst_dot(wo, wm), m->eta), T = 1 - R, f;
    if (uc < R / (R + T)) {
        wi = lst_reflect(wo, wm);
        if (!(wo.z * wi.z > 0)) return lst_fail(s);
        s->pdf = lst_diel_pdfm(m, wo, wm) / (4 * fabsf(lst_dot(wo, wm))) * R / (R + T);
        f = lst_diel_D(m, wm) * lst_diel_G(m, wo, wi) * R / fabsf(4 * wi.z * wo.z);
        s->eta = 1; s->flags = APPEAR_LOBE_REFLECTION | APPEAR_LOBE_GLOSSY;
    } else {
        float etap, d, denom;
        if (!lst_refract(wo, wm, m->eta, &etap, &wi) || wo.z * wi.z > 0 || wi.z == 0) return lst_fail(s);
        d = lst_dot(wi, wm) + lst_dot(wo, wm) / etap;
        denom = d * d;
        s->pdf = lst_diel_pdfm(m, wo, wm) * (fabsf(lst_dot(wi, wm)) / denom) * T / (R + T);
        f = T * lst_diel_D(m, wm) * lst_diel_G(m, wo, wi) * fabsf(lst_dot(wi, wm) * lst_dot(wo, wm) / (wi.z * wo.z * denom));
        f /= etap * etap;                                    /* TransportMode::Radiance */
        s->eta = etap; s->flags = APPEAR_LOBE_TRANSMISSION | APPEAR_LOBE_GLOSSY;
    }
    s->wi = wi; s->f = lst_splat(f);
    lst_weight(s);
    return 1;
}

/* ======================================================================== */
/* Ward as Mitsuba 0.6 writes it (src/bsdfs/ward.cpp, Ward::eval / pdf / sample; both
   components, m_specularSamplingWeight = sAvg / (dAvg + sAvg)), on Linux x86-64 where
   math::fastexp / fastlog are the double exp / log (include/mitsuba/core/math.h: "about 5x
   faster" than glibc's float ones then). M_PI (LST_PI_D) is a double, so Mitsuba's normalisations are
   computed in double, as here. Its eval returns f cos(wi) (Mitsuba's bRec.wo is our wi); one
   2D sample, its x reused for the component choice; the diffuse direction by the concentric
   map (src/libcore/warp.cpp squareToUniformDiskConcentric, Cline's form). */
/* ======================================================================== */
enum { LST_WARD06_WARD = 0, LST_WARD06_DUER = 1, LST_WARD06_BALANCED = 2 };
typedef struct lst_ward06 { appear_spectrum rho_d, rho_s; float au, av, spec_w; int variant; } lst_ward06;
LST_FUNC lst_ward06 lst_ward06_make(appear_spectrum rho_d, appear_spectrum rho_s, float au, float av, int variant)
{
    lst_ward06 w; float sd = 0, ss = 0; int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) { sd += rho_d.v[i]; ss += rho_s.v[i]; }
    w.rho_d = rho_d; w.rho_s = rho_s; w.au = au; w.av = av; w.spec_w = ss / (sd + ss); w.variant = variant;
    return w;
}
LST_FUNC appear_spectrum lst_ward06_eval(const lst_ward06 *w, appear_vec3 wo, appear_vec3 wi)
{
    appear_spectrum r = lst_splat(0.0f);
    float hx, hy, hz, factor1 = 0, factor2, factor3, exponent, spec_ref;
    int i;
    if (wo.z <= 0 || wi.z <= 0) return r;
    hx = wi.x + wo.x; hy = wi.y + wo.y; hz = wi.z + wo.z;
    switch (w->variant) {
    case LST_WARD06_WARD: factor1 = (float)(1.0f / (4.0f * LST_PI_D * w->au * w->av * sqrtf(wo.z * wi.z))); break;
    case LST_WARD06_DUER: factor1 = (float)(1.0f / (4.0f * LST_PI_D * w->au * w->av * wo.z * wi.z)); break;
    default: factor1 = (float)((hx * hx + hy * hy + hz * hz) / (LST_PI_D * w->au * w->av * powf(hz, 4))); break;
    }
    factor2 = hx / w->au; factor3 = hy / w->av;
    exponent = -(factor2 * factor2 + factor3 * factor3) / (hz * hz);
    spec_ref = factor1 * (float)exp((double)exponent);
    if (spec_ref > 1e-10f)
        for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) r.v[i] += w->rho_s.v[i] * spec_ref;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) r.v[i] = (r.v[i] + w->rho_d.v[i] * LST_INV_PI) * wi.z;
    return r;
}
LST_FUNC float lst_ward06_pdf(const lst_ward06 *w, appear_vec3 wo, appear_vec3 wi)
{
    float hx, hy, hz, hl, factor1, factor2, factor3, exponent, spec_prob, diffuse_prob;
    if (wo.z <= 0 || wi.z <= 0) return 0.0f;
    hx = wi.x + wo.x; hy = wi.y + wo.y; hz = wi.z + wo.z;
    hl = 1.0f / sqrtf(hx * hx + hy * hy + hz * hz); hx *= hl; hy *= hl; hz *= hl; /* normalize */
    factor1 = (float)(1.0f / (4.0f * LST_PI_D * w->au * w->av * (hx * wo.x + hy * wo.y + hz * wo.z) * powf(hz, 3)));
    factor2 = hx / w->au; factor3 = hy / w->av;
    exponent = -(factor2 * factor2 + factor3 * factor3) / (hz * hz);
    spec_prob = factor1 * (float)exp((double)exponent);
    diffuse_prob = LST_INV_PI * wi.z; /* squareToCosineHemispherePdf */
    return w->spec_w * spec_prob + (1 - w->spec_w) * diffuse_prob;
}
LST_FUNC int lst_ward06_sample(const lst_ward06 *w, appear_vec3 wo, float u1, float u2, appear_bsdf_record *s)
{
    appear_vec3 wi;
    appear_spectrum e;
    float pdf;
    int spec = 1, i;
    if (u1 <= w->spec_w) u1 /= w->spec_w;
    else { u1 = (u1 - w->spec_w) / (1 - w->spec_w); spec = 0; }
    if (spec) {
        float phi_h = (float)atan(w->av / w->au * tan(2.0f * LST_PI_D * u2)), cos_phi_h, sin_phi_h, theta_h, st, ct, d;
        if (u2 > 0.5f) phi_h += (float)LST_PI_D;
        cos_phi_h = cosf(phi_h);
        sin_phi_h = lst_safe_sqrt(1.0f - cos_phi_h * cos_phi_h);
        theta_h = atanf(lst_safe_sqrt(-(float)log((double)u1) /
                                      ((cos_phi_h * cos_phi_h) / (w->au * w->au) + (sin_phi_h * sin_phi_h) / (w->av * w->av))));
        st = sinf(theta_h); ct = cosf(theta_h); /* sphericalDirection(thetaH, phiH) */
        d = 2.0f * (wo.x * st * cos_phi_h + wo.y * st * sin_phi_h + wo.z * ct);
        wi = lst_v(st * cos_phi_h * d - wo.x, st * sin_phi_h * d - wo.y, ct * d - wo.z);
        if (wi.z <= 0.0f) return lst_fail(s);
    } else {
        float r1 = 2.0f * u1 - 1.0f, r2 = 2.0f * u2 - 1.0f, phi, r, z;
        if (r1 == 0 && r2 == 0) r = phi = 0;
        else if (r1 * r1 > r2 * r2) { r = r1; phi = (float)(LST_PI_D / 4.0f) * (r2 / r1); }
        else { r = r2; phi = (float)(LST_PI_D / 2.0f) - (r1 / r2) * (float)(LST_PI_D / 4.0f); }
        z = lst_safe_sqrt(1.0f - r * r);
        if (z == 0) z = 1e-10f;
        wi = lst_v(r * cosf(phi), r * sinf(phi), z);
    }
    pdf = lst_ward06_pdf(w, wo, wi);
    if (pdf == 0) return lst_fail(s);
    e = lst_ward06_eval(w, wo, wi);
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) s->weight.v[i] = e.v[i] / pdf;
    s->wi = wi; s->pdf = pdf; s->eta = 1;
    s->flags = APPEAR_LOBE_REFLECTION | (spec ? APPEAR_LOBE_GLOSSY : APPEAR_LOBE_DIFFUSE);
    return 1;
}

/* ======================================================================== */
/* SGGX [Heitz15], Mitsuba 3 sggx_projected_area / sggx_pdf
   (include/mitsuba/render/microflake.h): S given by its six entries [Sxx,
   Syy, Szz, Sxy, Sxz, Syz] (Mitsuba's order).                              */
/* ======================================================================== */
/* sigma(w) = sqrt(w^T S w) [Heitz15 Eq. 11] */
LST_FUNC float lst_sggx_sigma(const float *s, appear_vec3 w)
{
    float q = w.x * w.x * s[0] + w.y * w.y * s[1] + w.z * w.z * s[2] +
              2.0f * (w.x * w.y * s[3] + w.x * w.z * s[4] + w.y * w.z * s[5]);
    return sqrtf(fmaxf(q, 0.0f));
}
/* D(m) = 1 / (pi sqrt|S| (m^T S^-1 m)^2) [Heitz15 Eq. 9] = |S|^(3/2) / (pi (m^T adj(S) m)^2) */
LST_FUNC float lst_sggx_D(const float *s, appear_vec3 m)
{
    float det = s[0] * s[1] * s[2] - s[0] * s[5] * s[5] - s[1] * s[4] * s[4] - s[2] * s[3] * s[3] + 2.0f * s[3] * s[4] * s[5];
    float den = m.x * m.x * (s[1] * s[2] - s[5] * s[5]) + m.y * m.y * (s[0] * s[2] - s[4] * s[4]) +
                m.z * m.z * (s[0] * s[1] - s[3] * s[3]) +
                2.0f * (m.x * m.y * (s[4] * s[5] - s[2] * s[3]) + m.x * m.z * (s[3] * s[5] - s[1] * s[4]) +
                        m.y * m.z * (s[3] * s[4] - s[0] * s[5]));
    det = fabsf(det);
    return fmaxf(det, 0.0f) * sqrtf(fmaxf(det, 0.0f)) / (LST_PI * den * den); /* max, safe_sqrt */
}

/* ======================================================================== */
/* Homogeneous free flight, chromatic, with spectral MIS (the one-sample
   model of pbrt-v4's VolPathIntegrator / Mitsuba 3's volpath with hero
   channel chosen by uc): c = floor(3 uc), t = SampleExponential(u, sigma_c)
   = -log(1-u) / sigma_c (pbrt-v4 src/pbrt/util/sampling.h); a collision
   when t < d. The transmittance per channel is pbrt-v4's T_maj, FastExp(-t
   sigma) (src/pbrt/media.h SampleT_maj; FastExp: src/pbrt/util/math.h, a
   cubic for 2^f, relative error ~1e-4); pdf = average over channels of
   sigma_i T_i (collision) or T_i (pass), the one-sample MIS pbrt's r_u
   ratios carry; weight_i = T_i / pdf.                                       */
/* ======================================================================== */
/* pbrt-v4 FastExp (CPU branch): e^x = 2^(x log2 e), 2^f by a cubic, the exponent in the bits */
LST_FUNC float lst_fast_exp(float x)
{
    float xp = x * 1.442695041f, fxp = floorf(xp), f = xp - fxp, two_to_f;
    int i = (int)fxp, exponent;
    unsigned bits;
    two_to_f = 1.f + f * (0.695556856f + f * (0.226173572f + f * 0.0781455737f)); /* EvaluatePolynomial */
    memcpy(&bits, &two_to_f, sizeof bits);
    exponent = (int)((bits >> 23) & 0xffu) - 127 + i; /* Exponent(twoToF) + i */
    if (exponent < -126) return 0;
    if (exponent > 127) return INFINITY;
    bits &= 0x807fffffu; /* 0b10000000011111111111111111111111u */
    bits |= (unsigned)(exponent + 127) << 23;
    memcpy(&two_to_f, &bits, sizeof bits);
    return two_to_f;
}
LST_FUNC int lst_homogeneous_sample(appear_spectrum sigma, float d, float uc, float u, appear_medium_sample *s)
{
    int c = (int)(uc * APPEAR_SPECTRUM_SAMPLES), i;
    float t, pdf = 0;
    if (c > APPEAR_SPECTRUM_SAMPLES - 1) c = APPEAR_SPECTRUM_SAMPLES - 1;
    t = -logf(1 - u) / sigma.v[c];
    s->scattered = t < d;
    if (!s->scattered) t = d;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) {
        s->tr.v[i] = lst_fast_exp(-t * sigma.v[i]);
        pdf += s->scattered ? sigma.v[i] * s->tr.v[i] : s->tr.v[i];
    }
    pdf *= 1.0f / APPEAR_SPECTRUM_SAMPLES;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) s->weight.v[i] = s->tr.v[i] / pdf;
    s->t = t; s->pdf = pdf; s->channel = c;
    return 1;
}
/* the same for a grey medium (one sigma), as pbrt-v4's SampleT_maj takes a
   homogeneous segment: t = SampleExponential(u, sigma); a collision: T_maj
   = FastExp(-t sigma), pdf = sigma T_maj (the integrator's T_maj[0]
   sigma_maj[0]); past d: T_maj = FastExp(-d sigma), pdf = T_maj. weight =
   T / pdf = 1/sigma or 1, written to every channel of the record */
LST_FUNC int lst_homogeneous_sample1(float sigma, float d, float u, appear_medium_sample *s)
{
    float t = -logf(1 - u) / sigma, tr;
    int i;
    s->scattered = t < d;
    if (!s->scattered) t = d;
    tr = lst_fast_exp(-t * sigma);
    s->t = t; s->channel = 0;
    s->pdf = s->scattered ? sigma * tr : tr;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) { s->tr.v[i] = tr; s->weight.v[i] = tr / s->pdf; }
    return 1;
}
LST_FUNC float lst_homogeneous_pdf(appear_spectrum sigma, float d, float t, int scattered)
{
    float p = 0; int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) p += scattered ? sigma.v[i] * expf(-sigma.v[i] * t) : expf(-sigma.v[i] * d);
    return p * (1.0f / APPEAR_SPECTRUM_SAMPLES);
}

#endif /* APPEAR_TESTS_LISTINGS_H */
