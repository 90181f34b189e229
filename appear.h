/* appear.h - v0.1 - public domain / MIT - material and medium models for renderers
                                     no warranty implied; use at your own risk

   Evaluate, sample and pdf functions for BSDFs, phase functions and
   participating-media estimators, in one C99 header that also compiles as
   C++ and as CUDA. Drop it into a CPU or GPU path tracer.

   ===========================================================================
   DO THIS
   ===========================================================================

       #include "appear.h"

   in every file that uses it. All model code is `static inline`, so nothing
   else is required. In exactly ONE C or C++ file you may also write

       #define APPEAR_IMPLEMENTATION
       #include "appear.h"

   which adds the host-only code (today: nothing a model needs; future host
   helpers such as table generators live there). The library depends on libm
   only: it allocates nothing, keeps no global mutable state, does no I/O and
   draws no random numbers of its own.

   A first material:

       appear_frame fr = appear_frame_from_normal(n);       // shading frame
       appear_vec3  wo = appear_frame_to_local(fr, view);   // view points AWAY
       appear_lambert m = appear_lambert_make(appear_spectrum_splat(0.8f));
       appear_bsdf_sample s;
       if (appear_lambert_sample(&m, wo, uc, u1, u2, &s)) {
           throughput = throughput * s.weight;              // f |cos| / pdf
           next_dir   = appear_frame_to_world(fr, s.wi);
       }

   ===========================================================================
   CONVENTIONS (every model obeys them)
   ===========================================================================

   Frame   Local shading frame: z is the shading normal, x the tangent (the
           anisotropy axis), y = z cross x. appear_frame_from_normal() builds
           one from a normal (Duff et al. 2017), appear_frame_from_normal_
           tangent() from a normal and a tangent (Gram-Schmidt).
   Dirs    wo and wi are unit vectors pointing AWAY from the surface or the
           scattering point, for BSDFs and for phase functions alike. So for a
           phase function the scattering angle theta has cos(theta) =
           -dot(wo, wi): forward scattering (g > 0) sends light to wi ~ -wo.
   Values  *_eval returns f (the BSDF or phase value) WITHOUT the cosine.
           *_pdf is per unit solid angle of wi.
           *_sample fills an appear_bsdf_sample / appear_phase_sample with wi,
           f, pdf, weight = f |cos theta_i| / pdf (phase: f / pdf), the lobe
           flags and, for transmission, eta. It returns 1 on success, 0 when
           no direction was produced (the record then holds flags = 0,
           pdf = 0, weight = 0). A delta (specular) lobe reports pdf as the
           discrete probability of choosing it, sets APPEAR_LOBE_SPECULAR and
           stores in f the delta coefficient such that weight = f|cos|/pdf.
           *_eval and *_pdf of a pure delta lobe return 0.
   Sides   wo below the surface (wo.z < 0) means "inside". Directions exactly
           in the tangent plane (cos theta = 0) belong to neither side: value
           0, pdf 0, the sample fails. Reflection-only models are two-sided:
           they reflect into the hemisphere of wo.
   eta     Ratio of indices of refraction, inside over outside (transmitted
           side over incident side when code has to choose).
   Random  Random numbers come in as arguments: uc (lobe choice), u1, u2 in
           [0,1). Exactly 0 and exactly 1 are allowed and break nothing.
   Colour  Achromatic physics (D, G, pdfs, sampling) is scalar float.
           Chromatic quantities use appear_spectrum, APPEAR_SPECTRUM_SAMPLES
           floats (3 = RGB by default; a hero-wavelength renderer defines 4).
   Units   Extinction and scattering coefficients per unit length; distances
           in the same unit.
   Float   Every model computes in float. The tests compare against double.

   ===========================================================================
   ROBUSTNESS CONTRACT
   ===========================================================================

   For every public function and every input, finite or not: results are
   finite, a pdf is >= 0, a value is >= 0. Invalid input gives a defined
   result, never NaN and never a crash:
     - a direction that is NaN, infinite, zero or not unit length (|len^2-1|
       > APPEAR_UNIT_TOLERANCE) gives value 0, pdf 0, a failed sample;
     - a parameter outside its domain is rejected by appear_<model>_make,
       which then returns a model whose every call yields 0 / failure and
       whose `valid` member is 0;
     - physical limits are handled as the physics says, never by a silent
       clamp: |g| = 1 in Henyey-Greenstein is a delta lobe, cos theta = 0
       gives 0, eta = 1 passes straight through.
   APPEAR_ASSERT (default: assert) may catch programmer errors in debug
   builds; release builds obey the contract regardless.

   ===========================================================================
   CONFIGURATION (define before including; defaults shown)
   ===========================================================================

   APPEAR_SPECTRUM_SAMPLES  3        floats in appear_spectrum
   APPEAR_FUNC              static inline (+ __host__ __device__ under nvcc)
   APPEAR_CONST             static const  (constant tables)
   APPEAR_ASSERT(x)         assert(x)
   APPEAR_UNIT_TOLERANCE    1e-3f    accepted |dot(v,v) - 1| for directions
   APPEAR_USE_LIBM          undefined: use appear's own polynomial special
                            functions in hot paths; define it to call libm
   APPEAR_SQRTF APPEAR_EXPF APPEAR_LOGF APPEAR_SINF APPEAR_COSF APPEAR_ATAN2F
   APPEAR_POWF APPEAR_ERFF APPEAR_FABSF
                            libm hooks (default: the C library's)
   APPEAR_NO_LAMBERT APPEAR_NO_PHASE APPEAR_NO_WARD APPEAR_NO_MICROFACET
   APPEAR_NO_MEDIA APPEAR_NO_FLAKES
                            compile a part out

   Renderers build with -fno-math-errno (or -ffast-math); so should you:
   without it sqrtf() keeps an errno branch and loops over the samplers do
   not vectorise.

   ===========================================================================
   WHAT IT DOES NOT DO
   ===========================================================================

   No scene, no ray tracing, no textures, no random number generator, no
   memory allocation, no spectral upsampling. Directions are in the local
   frame: moving them in and out is yours (appear_frame_* helps).

   ===========================================================================
   REFERENCES (cited again at each function)
   ===========================================================================

   [Duff17]   Duff et al., Building an Orthonormal Basis, Revisited, JCGT 2017.
   [HG41]     Henyey & Greenstein, Diffuse radiation in the galaxy, ApJ 1941.
   [Walter07] Walter et al., Microfacet Models for Refraction through Rough
              Surfaces, EGSR 2007.
   [Heitz14]  Heitz, Understanding the Masking-Shadowing Function in
              Microfacet-Based BRDFs, JCGT 2014.
   [Heitz18]  Heitz, Sampling the GGX Distribution of Visible Normals, JCGT 2018.
   [Pharr23]  Pharr, Jakob, Humphreys, Physically Based Rendering, 4th ed.

   Version history at the end of the file.
*/

#ifndef APPEAR_H
#define APPEAR_H

#define APPEAR_VERSION_MAJOR 0
#define APPEAR_VERSION_MINOR 1
#define APPEAR_VERSION_PATCH 0
#define APPEAR_VERSION 100 /* major*10000 + minor*100 + patch */

/* ======================================================================== */
/* Configuration                                                            */
/* ======================================================================== */

#ifndef APPEAR_SPECTRUM_SAMPLES
#define APPEAR_SPECTRUM_SAMPLES 3
#endif

#ifndef APPEAR_FUNC
#if defined(__CUDACC__)
#define APPEAR_FUNC static inline __host__ __device__
#else
#define APPEAR_FUNC static inline
#endif
#endif

#ifndef APPEAR_CONST
#define APPEAR_CONST static const
#endif

#ifndef APPEAR_ASSERT
#include <assert.h>
#define APPEAR_ASSERT(x) assert(x)
#endif

#ifndef APPEAR_UNIT_TOLERANCE
#define APPEAR_UNIT_TOLERANCE 1e-3f
#endif

#include <math.h>
#ifndef APPEAR_SQRTF
#define APPEAR_SQRTF sqrtf
#endif
#ifndef APPEAR_EXPF
#define APPEAR_EXPF expf
#endif
#ifndef APPEAR_LOGF
#define APPEAR_LOGF logf
#endif
#ifndef APPEAR_SINF
#define APPEAR_SINF sinf
#endif
#ifndef APPEAR_COSF
#define APPEAR_COSF cosf
#endif
#ifndef APPEAR_ATAN2F
#define APPEAR_ATAN2F atan2f
#endif
#ifndef APPEAR_POWF
#define APPEAR_POWF powf
#endif
#ifndef APPEAR_ERFF
#define APPEAR_ERFF erff
#endif
#ifndef APPEAR_FABSF
#define APPEAR_FABSF fabsf
#endif

#define APPEAR_PI 3.14159265358979323846f
#define APPEAR_INV_PI 0.31830988618379067154f
#define APPEAR_INV_4PI 0.07957747154594766788f
#define APPEAR_FLT_MAX 3.402823466e+38f

#ifdef __cplusplus
extern "C" {
#endif

/* ======================================================================== */
/* Types                                                                    */
/* ======================================================================== */

typedef struct appear_vec3 { float x, y, z; } appear_vec3;

/* Chromatic quantity: RGB by default, or the hero wavelengths of a spectral
   renderer (define APPEAR_SPECTRUM_SAMPLES). */
typedef struct appear_spectrum { float v[APPEAR_SPECTRUM_SAMPLES]; } appear_spectrum;

/* Orthonormal frame: x = tangent, y = bitangent, z = normal. */
typedef struct appear_frame { appear_vec3 x, y, z; } appear_frame;

/* Lobe flags of a sample (and of a model's lobes). */
enum {
    APPEAR_LOBE_REFLECTION   = 1u << 0,
    APPEAR_LOBE_TRANSMISSION = 1u << 1,
    APPEAR_LOBE_DIFFUSE      = 1u << 2,
    APPEAR_LOBE_GLOSSY       = 1u << 3,
    APPEAR_LOBE_SPECULAR     = 1u << 4  /* delta lobe: pdf is a probability */
};

/* What a BSDF sampler returns. weight = f |wi.z| / pdf. */
typedef struct appear_bsdf_sample {
    appear_vec3     wi;     /* sampled direction, local frame, unit */
    appear_spectrum f;      /* BSDF value (delta coefficient for delta lobes) */
    appear_spectrum weight; /* f |cos theta_i| / pdf */
    float           pdf;    /* solid-angle pdf, or discrete prob. of a delta lobe */
    float           eta;    /* relative IOR crossed by a transmission, else 1 */
    unsigned        flags;  /* APPEAR_LOBE_*; 0 when the sample failed */
} appear_bsdf_sample;

/* What a phase-function sampler returns. weight = f / pdf. */
typedef struct appear_phase_sample {
    appear_vec3 wi;
    float       f;      /* phase value (delta coefficient for a delta lobe) */
    float       pdf;    /* solid-angle pdf, or 1 for a delta lobe */
    float       weight; /* f / pdf */
    unsigned    flags;  /* APPEAR_LOBE_*; 0 when the sample failed */
} appear_phase_sample;

/* ======================================================================== */
/* Vectors, spectra and frames                                              */
/* ======================================================================== */

APPEAR_FUNC appear_vec3 appear_vec3_make(float x, float y, float z)
{ appear_vec3 v; v.x = x; v.y = y; v.z = z; return v; }
APPEAR_FUNC float appear_dot(appear_vec3 a, appear_vec3 b)
{ return a.x * b.x + a.y * b.y + a.z * b.z; }
APPEAR_FUNC appear_vec3 appear_cross(appear_vec3 a, appear_vec3 b)
{ return appear_vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
APPEAR_FUNC appear_vec3 appear_add(appear_vec3 a, appear_vec3 b)
{ return appear_vec3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
APPEAR_FUNC appear_vec3 appear_sub(appear_vec3 a, appear_vec3 b)
{ return appear_vec3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
APPEAR_FUNC appear_vec3 appear_scale(appear_vec3 a, float s)
{ return appear_vec3_make(a.x * s, a.y * s, a.z * s); }
APPEAR_FUNC appear_vec3 appear_neg(appear_vec3 a)
{ return appear_vec3_make(-a.x, -a.y, -a.z); }
/* Unit vector along v; the zero vector for a zero, NaN or infinite v. */
APPEAR_FUNC appear_vec3 appear_normalize(appear_vec3 v)
{
    float l2 = appear_dot(v, v);
    float s = (l2 > 0.0f && l2 <= APPEAR_FLT_MAX) ? 1.0f / APPEAR_SQRTF(l2) : 0.0f;
    return appear_scale(v, s);
}

/* 1 when v is a usable direction: finite and |dot(v,v) - 1| <= tolerance.
   NaN fails every comparison, so it is rejected too. */
APPEAR_FUNC int appear_is_unit(appear_vec3 v)
{
    float d = appear_dot(v, v) - 1.0f;
    return d <= APPEAR_UNIT_TOLERANCE && d >= -APPEAR_UNIT_TOLERANCE;
}

APPEAR_FUNC appear_spectrum appear_spectrum_splat(float s)
{ appear_spectrum r; int i; for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) r.v[i] = s; return r; }
APPEAR_FUNC appear_spectrum appear_spectrum_rgb(float r, float g, float b)
{
    appear_spectrum s; int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) s.v[i] = i == 0 ? r : i == 1 ? g : b;
    return s;
}
APPEAR_FUNC appear_spectrum appear_spectrum_scale(appear_spectrum a, float s)
{ int i; for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) a.v[i] *= s; return a; }
APPEAR_FUNC appear_spectrum appear_spectrum_mul(appear_spectrum a, appear_spectrum b)
{ int i; for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) a.v[i] *= b.v[i]; return a; }
APPEAR_FUNC appear_spectrum appear_spectrum_add(appear_spectrum a, appear_spectrum b)
{ int i; for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) a.v[i] += b.v[i]; return a; }
APPEAR_FUNC float appear_spectrum_max(appear_spectrum a)
{ int i; float m = a.v[0]; for (i = 1; i < APPEAR_SPECTRUM_SAMPLES; ++i) m = a.v[i] > m ? a.v[i] : m; return m; }
APPEAR_FUNC float appear_spectrum_avg(appear_spectrum a)
{ int i; float s = 0.0f; for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) s += a.v[i]; return s * (1.0f / APPEAR_SPECTRUM_SAMPLES); }

/* Frame from a unit normal, branchless, continuous except across z = 0
   [Duff17, Listing 3]. */
APPEAR_FUNC appear_frame appear_frame_from_normal(appear_vec3 n)
{
    appear_frame f;
    float sign = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    f.x = appear_vec3_make(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.y = appear_vec3_make(b, sign + n.y * n.y * a, -n.y);
    f.z = n;
    return f;
}

/* Frame from a unit normal and a tangent that need not be orthogonal to it
   (Gram-Schmidt). A tangent parallel to n (or zero) falls back to
   appear_frame_from_normal(n). */
APPEAR_FUNC appear_frame appear_frame_from_normal_tangent(appear_vec3 n, appear_vec3 t)
{
    appear_vec3 tp = appear_sub(t, appear_scale(n, appear_dot(n, t)));
    float l2 = appear_dot(tp, tp);
    appear_frame f;
    if (!(l2 > 1e-12f * (appear_dot(t, t) + 1e-30f)) || !(l2 <= APPEAR_FLT_MAX))
        return appear_frame_from_normal(n);
    f.x = appear_scale(tp, 1.0f / APPEAR_SQRTF(l2));
    f.z = n;
    f.y = appear_cross(n, f.x);
    return f;
}

APPEAR_FUNC appear_vec3 appear_frame_to_local(appear_frame f, appear_vec3 v)
{ return appear_vec3_make(appear_dot(v, f.x), appear_dot(v, f.y), appear_dot(v, f.z)); }
APPEAR_FUNC appear_vec3 appear_frame_to_world(appear_frame f, appear_vec3 v)
{
    return appear_vec3_make(f.x.x * v.x + f.y.x * v.y + f.z.x * v.z,
                            f.x.y * v.x + f.y.y * v.y + f.z.y * v.z,
                            f.x.z * v.x + f.y.z * v.y + f.z.z * v.z);
}

/* ======================================================================== */
/* Special functions                                                        */
/* Hot paths call these, never libm directly. Each states its error bound;  */
/* APPEAR_USE_LIBM routes them to the C library.                            */
/* ======================================================================== */

APPEAR_FUNC float appear__min(float a, float b) { return a < b ? a : b; }
APPEAR_FUNC float appear__max(float a, float b) { return a > b ? a : b; }
APPEAR_FUNC float appear__clamp(float x, float lo, float hi) { return x < lo ? lo : (x > hi ? hi : x); }
/* sqrt of a quantity that is >= 0 in exact arithmetic but may round below. */
APPEAR_FUNC float appear__safe_sqrt(float x) { return APPEAR_SQRTF(x > 0.0f ? x : 0.0f); }
APPEAR_FUNC int appear__isfinite(float x) { return x - x == 0.0f; }
/* x if finite, else 0: the last line of defence of the contract. */
APPEAR_FUNC float appear__finite_or_zero(float x) { return x - x == 0.0f ? x : 0.0f; }

/* sin and cos of 2*pi*u for |u| <= 2^22 (the integer part is dropped;
   NaN, Inf and larger |u| give sin 0, cos 1).
   Quadrant reduction to |angle| <= pi/4, then Taylor polynomials to x^9 and
   x^10: truncation error < 2e-9, result error below 1 ulp + 2e-8 absolute
   over u in [0,1] (tests/test_core.c measures it). Branch-free; vectorises. */
APPEAR_FUNC void appear_sincos_2pi(float u, float *s, float *c)
{
#ifdef APPEAR_USE_LIBM
    *s = APPEAR_SINF(6.28318530717958647692f * u);
    *c = APPEAR_COSF(6.28318530717958647692f * u);
#else
    float q = (u >= -4194304.0f && u <= 4194304.0f ? u : 0.0f) * 4.0f; /* NaN, huge -> 0 */
    float k = (float)(int)(q + (q >= 0.0f ? 0.5f : -0.5f)); /* nearest quadrant */
    float r = (q - k) * 1.57079632679489661923f;              /* |r| <= pi/4 */
    float r2 = r * r;
    float sp = r * (1.0f + r2 * (-1.0f / 6.0f + r2 * (1.0f / 120.0f + r2 * (-1.0f / 5040.0f + r2 * (1.0f / 362880.0f)))));
    float cp = 1.0f + r2 * (-0.5f + r2 * (1.0f / 24.0f + r2 * (-1.0f / 720.0f + r2 * (1.0f / 40320.0f + r2 * (-1.0f / 3628800.0f)))));
    int quadrant = ((int)k) & 3;
    float sv = (quadrant & 1) ? cp : sp;
    float cv = (quadrant & 1) ? sp : cp;
    *s = (quadrant & 2) ? -sv : sv;
    *c = ((quadrant + 1) & 2) ? -cv : cv;
#endif
}

/* Elementary functions used by model code. Today they forward to the libm
   hooks; appear's own polynomial versions replace the bodies (with their
   error bounds stated here) unless APPEAR_USE_LIBM is defined. Model code
   calls these names only. */
APPEAR_FUNC float appear__exp(float x) { return APPEAR_EXPF(x); }
APPEAR_FUNC float appear__log(float x) { return APPEAR_LOGF(x); }
APPEAR_FUNC float appear__erf(float x) { return APPEAR_ERFF(x); }
APPEAR_FUNC float appear__atan2(float y, float x) { return APPEAR_ATAN2F(y, x); }
APPEAR_FUNC float appear__pow(float x, float y) { return APPEAR_POWF(x, y); }
/* Inverse error function on (-1, 1) (Giles, Approximating the erfinv
   function, GPU Computing Gems 2011, single-precision branch pair);
   +-1 map to +-Inf, |x| > 1 and NaN to 0. */
APPEAR_FUNC float appear__erfinv(float x)
{
    float w, p;
    if (!(x > -1.0f && x < 1.0f)) return (x == 1.0f) ? HUGE_VALF : (x == -1.0f) ? -HUGE_VALF : 0.0f;
    w = -appear__log((1.0f - x) * (1.0f + x));
    if (w < 5.0f) {
        w = w - 2.5f;
        p = 2.81022636e-08f;
        p = 3.43273939e-07f + p * w;  p = -3.5233877e-06f + p * w;
        p = -4.39150654e-06f + p * w; p = 0.00021858087f + p * w;
        p = -0.00125372503f + p * w;  p = -0.00417768164f + p * w;
        p = 0.246640727f + p * w;     p = 1.50140941f + p * w;
    } else {
        w = APPEAR_SQRTF(w) - 3.0f;
        p = -0.000200214257f;
        p = 0.000100950558f + p * w;  p = 0.00134934322f + p * w;
        p = -0.00367342844f + p * w;  p = 0.00573950773f + p * w;
        p = -0.0076224613f + p * w;   p = 0.00943887047f + p * w;
        p = 1.00167406f + p * w;      p = 2.83297682f + p * w;
    }
    return p * x;
}

/* ======================================================================== */
/* Lambertian BRDF                                                          */
/* f = R / pi, two-sided. Cosine-weighted hemisphere sampling (Malley).     */
/* ======================================================================== */
#ifndef APPEAR_NO_LAMBERT

typedef struct appear_lambert {
    appear_spectrum albedo; /* R in [0,1] per channel */
    int valid;
} appear_lambert;

/* Reference: every channel of R must be finite and in [0, 1]; otherwise the
   model is returned with valid = 0 and all its calls yield zero / failure. */
APPEAR_FUNC appear_lambert appear_lambert_make(appear_spectrum albedo)
{
    appear_lambert m; int i;
    m.valid = 1;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i)
        m.valid &= (albedo.v[i] >= 0.0f && albedo.v[i] <= 1.0f);
    m.albedo = m.valid ? albedo : appear_spectrum_splat(0.0f);
    return m;
}

/* f(wo, wi) = R/pi when wo and wi lie strictly on the same side, else 0. */
APPEAR_FUNC appear_spectrum appear_lambert_eval(const appear_lambert *m, appear_vec3 wo, appear_vec3 wi)
{
    int ok = m->valid && appear_is_unit(wo) && appear_is_unit(wi) && wo.z * wi.z > 0.0f;
    return appear_spectrum_scale(m->albedo, ok ? APPEAR_INV_PI : 0.0f);
}

/* pdf(wi) = |cos theta_i| / pi on the side of wo. */
APPEAR_FUNC float appear_lambert_pdf(const appear_lambert *m, appear_vec3 wo, appear_vec3 wi)
{
    int ok = m->valid && appear_is_unit(wo) && appear_is_unit(wi) && wo.z * wi.z > 0.0f;
    return ok ? APPEAR_FABSF(wi.z) * APPEAR_INV_PI : 0.0f;
}

/* Cosine-weighted sampling: disk point (sqrt(u1), 2 pi u2) lifted to the
   hemisphere of wo. uc is unused. weight = R exactly. Fails when wo is
   invalid or in the tangent plane, and when the lift lands exactly on the
   tangent plane (u1 = 1). */
APPEAR_FUNC int appear_lambert_sample(const appear_lambert *m, appear_vec3 wo, float uc, float u1,
                                      float u2, appear_bsdf_sample *s)
{
    float sphi, cphi, r, z;
    int ok;
    (void)uc;
    u1 = appear__clamp(u1, 0.0f, 1.0f); /* NaN -> fails below via z */
    appear_sincos_2pi(u2, &sphi, &cphi);
    r = APPEAR_SQRTF(u1);
    z = appear__safe_sqrt(1.0f - u1);
    z = wo.z < 0.0f ? -z : z;
    ok = m->valid && appear_is_unit(wo) && wo.z != 0.0f && z != 0.0f && appear__isfinite(u2);
    s->wi = appear_vec3_make(ok ? r * cphi : 0.0f, ok ? r * sphi : 0.0f, ok ? z : 0.0f);
    s->pdf = ok ? APPEAR_FABSF(z) * APPEAR_INV_PI : 0.0f;
    s->f = appear_spectrum_scale(m->albedo, ok ? APPEAR_INV_PI : 0.0f);
    s->weight = ok ? m->albedo : appear_spectrum_splat(0.0f);
    s->eta = 1.0f;
    s->flags = ok ? (unsigned)(APPEAR_LOBE_REFLECTION | APPEAR_LOBE_DIFFUSE) : 0u;
    return ok;
}

#endif /* APPEAR_NO_LAMBERT */

/* ======================================================================== */
/* Phase functions: isotropic and Henyey-Greenstein                         */
/* cos(theta) = -dot(wo, wi): both directions point away from the point.    */
/* ======================================================================== */
#ifndef APPEAR_NO_PHASE

/* Sample a direction about the axis a (unit) with cos = mu measured from a,
   given 1-mu and 1+mu separately so sin(theta) keeps its digits. */
APPEAR_FUNC appear_vec3 appear__dir_about_axis(appear_vec3 a, float one_minus_mu, float one_plus_mu, float u2)
{
    /* a may be off unit length by APPEAR_UNIT_TOLERANCE: renormalise so the
       result is unit to float precision */
    appear_frame f = appear_frame_from_normal(appear_scale(a, 1.0f / APPEAR_SQRTF(appear_dot(a, a))));
    float sphi, cphi;
    float mu = one_minus_mu < one_plus_mu ? 1.0f - one_minus_mu : one_plus_mu - 1.0f;
    float st = appear__safe_sqrt(one_minus_mu * one_plus_mu);
    appear_sincos_2pi(u2, &sphi, &cphi);
    return appear_frame_to_world(f, appear_vec3_make(st * cphi, st * sphi, mu));
}

APPEAR_FUNC void appear__phase_fail(appear_phase_sample *s)
{
    s->wi = appear_vec3_make(0.0f, 0.0f, 0.0f);
    s->f = 0.0f; s->pdf = 0.0f; s->weight = 0.0f; s->flags = 0u;
}

/* Isotropic phase function p = 1 / (4 pi). */
APPEAR_FUNC float appear_isotropic_eval(appear_vec3 wo, appear_vec3 wi)
{ return appear_is_unit(wo) && appear_is_unit(wi) ? APPEAR_INV_4PI : 0.0f; }
APPEAR_FUNC float appear_isotropic_pdf(appear_vec3 wo, appear_vec3 wi)
{ return appear_isotropic_eval(wo, wi); }
/* Uniform sphere: z = 1 - 2 u1 written as (1-z, 1+z) = (2 u1, 2 - 2 u1). */
APPEAR_FUNC int appear_isotropic_sample(appear_vec3 wo, float u1, float u2, appear_phase_sample *s)
{
    int ok = appear_is_unit(wo) && u1 >= 0.0f && u1 <= 1.0f && appear__isfinite(u2);
    if (!ok) { appear__phase_fail(s); return 0; }
    s->wi = appear__dir_about_axis(appear_vec3_make(0.0f, 0.0f, 1.0f), 2.0f * u1, 2.0f - 2.0f * u1, u2);
    s->f = s->pdf = APPEAR_INV_4PI;
    s->weight = 1.0f;
    s->flags = APPEAR_LOBE_DIFFUSE;
    return 1;
}

/* Henyey-Greenstein [HG41], g in [-1, 1] the mean cosine:
       p(mu) = (1 - g^2) / (4 pi (1 + g^2 - 2 g mu)^(3/2)),  mu = -dot(wo, wi).
   g > 0 scatters forward (wi ~ -wo), g < 0 backward (wi ~ wo).
   The denominator is written as (1-|g|)^2 + 2|g| (1 - s mu), s = sign(g),
   with 1 - s mu = |wo + s wi|^2 / 2 computed from the vectors, so the value
   keeps its digits in the sharp peak of |g| -> 1.
   |g| = 1 is a delta lobe: eval and pdf return 0, sample returns it.
   |g| > 1 or NaN: 0 / failure. */
APPEAR_FUNC float appear_hg_eval(float g, appear_vec3 wo, appear_vec3 wi)
{
    float ag = APPEAR_FABSF(g);
    float sg = g < 0.0f ? -1.0f : 1.0f;
    appear_vec3 d = appear_add(wo, appear_scale(wi, sg));
    float one_minus_smu = 0.5f * appear_dot(d, d); /* 1 - s mu, in [0, 2] */
    float den = (1.0f - ag) * (1.0f - ag) + 2.0f * ag * one_minus_smu;
    float num = (1.0f - ag) * (1.0f + ag);
    int ok = ag < 1.0f && appear_is_unit(wo) && appear_is_unit(wi);
    /* den >= (1-|g|)^2 > 0 for |g| < 1, so den * sqrt(den) is finite and > 0 */
    return ok ? APPEAR_INV_4PI * num / (den * APPEAR_SQRTF(den)) : 0.0f;
}

APPEAR_FUNC float appear_hg_pdf(float g, appear_vec3 wo, appear_vec3 wi)
{ return appear_hg_eval(g, wo, wi); }

/* Exact inverse CDF of HG in a form without cancellation. With
   h = 1 - g + 2 g u1 (> 0), the textbook
       mu = (1 + g^2 - ((1 - g^2) / h)^2) / (2 g)
   (which loses every digit as g -> 0) equals, after dividing out 2g,
       1 - mu = 2 (1-g)^2 (1-u1) (1 + g u1) / h^2,
       1 + mu = 2 (1+g)^2 u1 (1 - g + g u1) / h^2,
   both products of non-negative factors: accurate to a few ulp for every
   g in (-1, 1), including g = 0 (uniform) and |g| = 1e-7. mu is taken from
   whichever of the two is smaller. u1 is the CDF in mu from mu = -1.
   |g| = 1: delta lobe (wi = -wo for g = 1, wi = wo for g = -1), pdf = 1,
   f = 1, weight = 1, flags SPECULAR. */
APPEAR_FUNC int appear_hg_sample(float g, appear_vec3 wo, float u1, float u2, appear_phase_sample *s)
{
    float ag = APPEAR_FABSF(g);
    float h, a, b, ih2, omm, opm;
    int ok = appear_is_unit(wo) && ag <= 1.0f && u1 >= 0.0f && u1 <= 1.0f && appear__isfinite(u2);
    if (!ok) { appear__phase_fail(s); return 0; }
    if (ag == 1.0f) {
        s->wi = g > 0.0f ? appear_neg(wo) : wo;
        s->f = 1.0f; s->pdf = 1.0f; s->weight = 1.0f;
        s->flags = APPEAR_LOBE_SPECULAR;
        return 1;
    }
    /* every factor as a sum of non-negative terms (1 - u1 is exact for
       u1 >= 1/2), so none cancels when |g| -> 1 */
    {
        float v1 = 1.0f - u1;
        int pos = g >= 0.0f;
        h   = pos ? (1.0f - g) + 2.0f * g * u1 : (1.0f + g) - 2.0f * g * v1;
        a   = pos ? 1.0f + g * u1 : (1.0f + g) - g * v1;          /* 1 + g u1 */
        b   = pos ? (1.0f - g) + g * u1 : 1.0f - g * v1;          /* 1 - g + g u1 */
        ih2 = 1.0f / (h * h);
        omm = 2.0f * (1.0f - g) * (1.0f - g) * v1 * a * ih2;
        opm = 2.0f * (1.0f + g) * (1.0f + g) * u1 * b * ih2;
    }
    s->wi = appear__dir_about_axis(appear_neg(wo), omm, opm, u2);
    /* pdf evaluated at the returned vector, not from the sampled mu: the two
       differ by the rounding of wi (up to 1e-4 relative in the peak of
       |g| -> 1), and renderers need sample().pdf == pdf(wo, sample().wi) */
    s->f = s->pdf = appear_hg_eval(g, wo, s->wi);
    s->weight = 1.0f;
    s->flags = APPEAR_LOBE_GLOSSY;
    /* the sampled wi is unit by construction, so pdf > 0 unless rounding
       lands in an underflowed tail: report that as a failure */
    if (!(s->pdf > 0.0f)) { appear__phase_fail(s); return 0; }
    return 1;
}

#endif /* APPEAR_NO_PHASE */

/* ======================================================================== */
/* SECTION ward (APPEAR_NO_WARD)                                            */
/* ======================================================================== */
/* END SECTION ward */

/* ======================================================================== */
/* SECTION microfacet (APPEAR_NO_MICROFACET)                                */
/* ======================================================================== */
/*
   Microfacet distributions, Smith masking, visible-normal sampling, Fresnel,
   rough conductor BRDF and rough dielectric BSDF.

   References (cited at each function):
   [Walter07]  Walter, Marschner, Li, Torrance, Microfacet Models for
               Refraction through Rough Surfaces, EGSR 2007.
   [Heitz14]   Heitz, Understanding the Masking-Shadowing Function in
               Microfacet-Based BRDFs, JCGT 3(2) 2014.
   [HdE14]     Heitz & d'Eon, Importance Sampling Microfacet-Based BSDFs
               using the Distribution of Visible Normals, EGSR 2014.
   [Heitz18]   Heitz, Sampling the GGX Distribution of Visible Normals,
               JCGT 7(4) 2018.
   [DB23]      Dupuy & Benyoub, Sampling Visible GGX Normals with Spherical
               Caps, HPG 2023.
   [ET23]      Eto & Tokuyoshi, Bounded VNDF Sampling for Smith-GGX
               Reflections, SIGGRAPH Asia 2023 Technical Communications.
   [BW99]      Born & Wolf, Principles of Optics, 7th ed., Sec. 1.5 and 14.2.
   [Schlick94] Schlick, An Inexpensive BRDF Model for Physically-based
               Rendering, CGF 1994.
   [Kutz21]    Kutz, Hasan, Edmondson, Novel aspects of the Adobe Standard
               Material, 2021 (the F82-tint conductor; after Hoffman 2019,
               Fresnel Equations Considered Harmful).
   [Veach97]   Veach, Robust Monte Carlo Methods for Light Transport
               Simulation, PhD thesis 1997, Sec. 5.2 (non-symmetric BSDFs).

   CONVENTIONS OF THIS PART
   - alpha (ax along the tangent x, ay along y) is the roughness of
     [Walter07] (GGX alpha, Beckmann rms slope * sqrt 2).  Isotropic is
     ax == ay; the formulas are the same, no separate code path is needed.
   - Microfacet normals m live in the upper hemisphere (m.z > 0).  A
     direction w "sees" m when (w.m) * w.z > 0, so the building blocks work
     for w on either side (the distributions are symmetric under m -> -m).
   - Building blocks (appear_ggx_*, appear_beckmann_*) clamp alpha into
     [APPEAR_MICROFACET_ALPHA_MIN, APPEAR_MICROFACET_ALPHA_MAX]; a NaN alpha
     or an invalid direction gives 0 (a zero vector for samplers).
   - Models (appear_conductor_*, appear_dielectric_*) take an
     appear_microfacet made by appear_microfacet_make().  When
     max(ax, ay) < APPEAR_MICROFACET_ALPHA_MIN the model is the smooth
     (delta) limit: eval and pdf return 0, sample returns the specular
     direction(s) flagged APPEAR_LOBE_SPECULAR.  When only one alpha is
     below the threshold it is raised to it (a ridge narrower than 1e-4
     rad is beyond what float directions resolve).
   - Smith G2 is the height-correlated form G2 = 1/(1 + L(wo) + L(wi))
     [Heitz14, Eq. 99], used for reflection and (like pbrt-v4) for
     transmission.  Everything is written with z*Lambda(w), which stays
     finite at grazing, so G1 -> 0 as cos -> 0 and nothing divides by 0.
   - Transmission, radiance convention: appear_dielectric_eval returns the
     BTDF for RADIANCE transport (camera paths), [Walter07, Eq. 21]:
        f_t(wo,wi) = (1-F) D G2 |wi.h||wo.h| / (|wi.z||wo.z| (wo.h + e wi.h)^2)
     with e = n(wi side)/n(wo side) (stored in appear_bsdf_sample.eta).  It
     obeys the eta^2 rule [Veach97, Eq. 5.14]:
        f_t(wo,wi) / e^2 = f_t(wi,wo)     i.e.  n_o^2 f(wi,wo) = n_i^2 f(wo,wi)
     so a light (importance) path multiplies transmitted f and weight by
     e^2.  A smooth transmission therefore has weight (1-F)/e^2 / (1-F) =
     1/e^2.  Energy conservation reads R + e^2 T <= 1.
*/
#ifndef APPEAR_NO_MICROFACET

#ifndef APPEAR_MICROFACET_ALPHA_MIN
#define APPEAR_MICROFACET_ALPHA_MIN 1e-4f /* below: smooth (delta) limit */
#endif
#ifndef APPEAR_MICROFACET_ALPHA_MAX
#define APPEAR_MICROFACET_ALPHA_MAX 100.0f
#endif
#define APPEAR__SQRT_PI 1.77245385090551602730f
#define APPEAR__INV_SQRT_PI 0.56418958354775628695f

/* Distribution types and sampling strategies of appear_microfacet. */
enum { APPEAR_GGX = 0, APPEAR_BECKMANN = 1 };
enum {
    APPEAR_SAMPLE_VISIBLE = 0, /* visible normals: spherical caps (GGX), erf-Newton (Beckmann) */
    APPEAR_SAMPLE_BOUNDED = 1, /* bounded VNDF [ET23]: GGX reflection only; dielectrics use VISIBLE */
    APPEAR_SAMPLE_FULL_D  = 2  /* m ~ D(m) cos(theta_m), the classic [Walter07] sampler */
};

typedef struct appear_microfacet {
    int   type;     /* APPEAR_GGX or APPEAR_BECKMANN */
    int   sampling; /* APPEAR_SAMPLE_* */
    float ax, ay;   /* roughness, clamped to >= ALPHA_MIN unless smooth */
    int   smooth;   /* 1: delta limit (max(ax, ay) < ALPHA_MIN) */
    int   valid;
} appear_microfacet;

/* ---- small private helpers -------------------------------------------- */

APPEAR_FUNC float appear__mf_alpha(float a)
{   /* NaN -> 0 (caller rejects), else clamp into the documented range */
    return a >= APPEAR_MICROFACET_ALPHA_MIN ? (a <= APPEAR_MICROFACET_ALPHA_MAX ? a : APPEAR_MICROFACET_ALPHA_MAX)
         : (a == a ? APPEAR_MICROFACET_ALPHA_MIN : 0.0f);
}
APPEAR_FUNC appear_vec3 appear__reflect(appear_vec3 wo, appear_vec3 m)
{ return appear_sub(appear_scale(m, 2.0f * appear_dot(wo, m)), wo); }
APPEAR_FUNC appear_vec3 appear__zero3(void) { return appear_vec3_make(0.0f, 0.0f, 0.0f); }
/* w with its z made non-negative (mirror through the tangent plane) */
APPEAR_FUNC appear_vec3 appear__upper(appear_vec3 w) { return appear_vec3_make(w.x, w.y, APPEAR_FABSF(w.z)); }

/* ======================================================================== */
/* GGX (Trowbridge-Reitz)                                                   */
/* ======================================================================== */

/* D(m) = 1 / (pi ax ay (mx^2/ax^2 + my^2/ay^2 + mz^2)^2), m unit, mz > 0
   [Walter07, Eq. 33, anisotropic form of Heitz14, Eq. 85]; written without
   tan(theta) so it is exact at grazing m. */
APPEAR_FUNC float appear__ggx_D(float ax, float ay, appear_vec3 m)
{
    float x = m.x / ax, y = m.y / ay;
    float s = x * x + y * y + m.z * m.z;
    return m.z > 0.0f ? 1.0f / (APPEAR_PI * ax * ay * s * s) : 0.0f;
}
/* |w.z| Lambda(w) = (sqrt(z^2 + ax^2 x^2 + ay^2 y^2) - |z|) / 2
   [Heitz14, Eq. 86 times |z|], as a2 / (2 (s + |z|)) without cancellation.
   Finite for every unit w; 0 at w = +-z. */
APPEAR_FUNC float appear__ggx_zlambda(float ax, float ay, appear_vec3 w)
{
    float a2 = ax * ax * w.x * w.x + ay * ay * w.y * w.y;
    float z = APPEAR_FABSF(w.z);
    float s = APPEAR_SQRTF(a2 + z * z);
    return a2 > 0.0f ? a2 / (2.0f * (s + z)) : 0.0f;
}

/* ======================================================================== */
/* Beckmann                                                                 */
/* ======================================================================== */

/* D(m) = exp(-(mx^2/ax^2 + my^2/ay^2) / mz^2) / (pi ax ay mz^4)
   [Walter07, Eq. 25; Heitz14, Eq. 84]. The exponent is tested before the
   division by mz^4, so grazing m gives 0, never 0/0. */
APPEAR_FUNC float appear__beckmann_D(float ax, float ay, appear_vec3 m)
{
    float x = m.x / ax, y = m.y / ay, z2 = m.z * m.z;
    float num = x * x + y * y;
    int ok = m.z > 0.0f && num < 88.0f * z2; /* exp(-88) ~ 6e-39: below, D underflows to 0 */
    float e = ok ? num / z2 : 0.0f;
    return ok ? appear__exp(-e) / (APPEAR_PI * ax * ay * z2 * z2) : 0.0f;
}
/* |w.z| Lambda(w) for Beckmann. With t = sqrt(ax^2 x^2 + ay^2 y^2) and
   a = |z| / t [Heitz14, Eq. 83]:
      Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2,
      |z| Lambda = (t exp(-a^2)/sqrt(pi) - |z| erfc(a)) / 2   (finite at a = 0).
   For a >= 2.5 the difference cancels, so it is rewritten with the Laplace
   continued fraction erfc(a) = exp(-a^2)/sqrt(pi) / (a + r),
   r = (1/2)/(a + 1/(a + (3/2)/(a + ...))):  Lambda = exp(-a^2) r /
   (2 sqrt(pi) a (a + r)), 12 levels: relative error < 2e-7 for a >= 2.5
   (checked against mpmath). Below 2.5, erfc = 1 - erf: absolute error of
   Lambda < 1e-7, which is what G1 = 1/(1 + Lambda) needs. */
APPEAR_FUNC float appear__beckmann_zlambda(float ax, float ay, appear_vec3 w)
{
    float t2 = ax * ax * w.x * w.x + ay * ay * w.y * w.y;
    float t = APPEAR_SQRTF(t2), z = APPEAR_FABSF(w.z);
    float a = t > 0.0f ? z / t : 1e30f;
    float ac = a < 10.0f ? a : 10.0f;
    float ex = appear__exp(-ac * ac);
    float direct = 0.5f * (t * ex * APPEAR__INV_SQRT_PI - z * (1.0f - appear__erf(ac)));
    float acf = ac > 2.5f ? ac : 2.5f; /* the fraction is only used there */
    float r = 0.0f, cf;
    int k;
    for (k = 13; k >= 2; --k) r = (0.5f * (float)k) / (acf + r);
    r = 0.5f / (acf + r);
    cf = t * ex * r * (0.5f * APPEAR__INV_SQRT_PI) / (acf + r);
    return a >= 10.0f ? 0.0f : (a < 2.5f ? appear__max(direct, 0.0f) : cf);
}
/* Walter's rational fit of Beckmann Lambda [Walter07, Eq. 27], as |z|
   Lambda = t (1 - 1.259a + 0.396a^2) / (3.535 + 2.181a) for a < 1.6, else 0.
   Documented fast option; tests/test_microfacet.c measures its error. */
APPEAR_FUNC float appear__beckmann_zlambda_fast(float ax, float ay, appear_vec3 w)
{
    float t = APPEAR_SQRTF(ax * ax * w.x * w.x + ay * ay * w.y * w.y);
    float z = APPEAR_FABSF(w.z);
    float a = t > 0.0f ? z / t : 1e30f;
    return a < 1.6f ? t * (1.0f - 1.259f * a + 0.396f * a * a) / (3.535f + 2.181f * a) : 0.0f;
}

/* ======================================================================== */
/* Generic Smith functions from z*Lambda                                   */
/* ======================================================================== */

/* Lambda = zL / |z|, +inf reported as APPEAR_FLT_MAX (grazing w). */
APPEAR_FUNC float appear__lambda_from_zl(float zl, float z)
{
    float az = APPEAR_FABSF(z);
    return zl < az * APPEAR_FLT_MAX ? zl / az : (zl > 0.0f ? APPEAR_FLT_MAX : 0.0f);
}
/* G1 = 1/(1+Lambda) = |z| / (|z| + zL): 0 at grazing, 1 at w = z. */
APPEAR_FUNC float appear__g1_from_zl(float zl, float z)
{
    float az = APPEAR_FABSF(z);
    return az + zl > 0.0f ? az / (az + zl) : 0.0f;
}
/* G2 = 1/(1 + Lo + Li) = zo zi / (zo zi + zi zLo + zo zLi) [Heitz14, Eq. 99]. */
APPEAR_FUNC float appear__g2_from_zl(float zlo, float zo, float zli, float zi)
{
    float p = APPEAR_FABSF(zo) * APPEAR_FABSF(zi);
    float den = p + APPEAR_FABSF(zi) * zlo + APPEAR_FABSF(zo) * zli;
    return den > 0.0f ? p / den : 0.0f;
}

/* ---- public GGX building blocks ---------------------------------------- */

/* GGX normal distribution D(m) (per unit solid angle of m; integrates
   D(m) m.z dm = 1). 0 for m.z <= 0 or invalid m. */
APPEAR_FUNC float appear_ggx_D(float ax, float ay, appear_vec3 m)
{
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    return (ax > 0.0f && ay > 0.0f && appear_is_unit(m)) ? appear__ggx_D(ax, ay, m) : 0.0f;
}
/* Smith Lambda(w) for GGX [Heitz14, Eq. 86]: (-1 + sqrt(1 + a^2 tan^2)) / 2,
   computed without tan. Grazing w (z = 0): APPEAR_FLT_MAX (= +inf). */
APPEAR_FUNC float appear_ggx_lambda(float ax, float ay, appear_vec3 w)
{
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    return (ax > 0.0f && ay > 0.0f && appear_is_unit(w)) ? appear__lambda_from_zl(appear__ggx_zlambda(ax, ay, w), w.z) : 0.0f;
}
/* Smith G1(w, m) = chi+((w.m) w.z) / (1 + Lambda(w)) [Heitz14, Eq. 43];
   for GGX 2|z| / (|z| + sqrt(z^2 + ax^2 x^2 + ay^2 y^2)). Pass m = (0,0,1)
   for the plain G1(w). 0 at grazing. */
APPEAR_FUNC float appear_ggx_G1(float ax, float ay, appear_vec3 w, appear_vec3 m)
{
    int ok;
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    ok = ax > 0.0f && ay > 0.0f && appear_is_unit(w) && appear_is_unit(m) && m.z > 0.0f && appear_dot(w, m) * w.z > 0.0f;
    return ok ? appear__g1_from_zl(appear__ggx_zlambda(ax, ay, w), w.z) : 0.0f;
}
/* Height-correlated G2(wo, wi, m) = chi+ chi+ / (1 + L(wo) + L(wi))
   [Heitz14, Eq. 99]; wo and wi may lie on either side (the side tests are
   (wo.m) wo.z > 0 and (wi.m) wi.z > 0). */
APPEAR_FUNC float appear_ggx_G2(float ax, float ay, appear_vec3 wo, appear_vec3 wi, appear_vec3 m)
{
    int ok;
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    ok = ax > 0.0f && ay > 0.0f && appear_is_unit(wo) && appear_is_unit(wi) && appear_is_unit(m) && m.z > 0.0f &&
         appear_dot(wo, m) * wo.z > 0.0f && appear_dot(wi, m) * wi.z > 0.0f;
    return ok ? appear__g2_from_zl(appear__ggx_zlambda(ax, ay, wo), wo.z, appear__ggx_zlambda(ax, ay, wi), wi.z) : 0.0f;
}

/* ---- public Beckmann building blocks ----------------------------------- */

APPEAR_FUNC float appear_beckmann_D(float ax, float ay, appear_vec3 m)
{
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    return (ax > 0.0f && ay > 0.0f && appear_is_unit(m)) ? appear__beckmann_D(ax, ay, m) : 0.0f;
}
/* Exact Smith Lambda(w) for Beckmann [Heitz14, Eq. 83], see
   appear__beckmann_zlambda for the stable evaluation. */
APPEAR_FUNC float appear_beckmann_lambda(float ax, float ay, appear_vec3 w)
{
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    return (ax > 0.0f && ay > 0.0f && appear_is_unit(w)) ? appear__lambda_from_zl(appear__beckmann_zlambda(ax, ay, w), w.z) : 0.0f;
}
/* Walter's rational approximation of the Beckmann Lambda [Walter07,
   Eq. 27]: cheaper (no exp, no erf); G1 error below 2e-3 (measured in
   tests). */
APPEAR_FUNC float appear_beckmann_lambda_fast(float ax, float ay, appear_vec3 w)
{
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    return (ax > 0.0f && ay > 0.0f && appear_is_unit(w)) ? appear__lambda_from_zl(appear__beckmann_zlambda_fast(ax, ay, w), w.z) : 0.0f;
}
APPEAR_FUNC float appear_beckmann_G1(float ax, float ay, appear_vec3 w, appear_vec3 m)
{
    int ok;
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    ok = ax > 0.0f && ay > 0.0f && appear_is_unit(w) && appear_is_unit(m) && m.z > 0.0f && appear_dot(w, m) * w.z > 0.0f;
    return ok ? appear__g1_from_zl(appear__beckmann_zlambda(ax, ay, w), w.z) : 0.0f;
}
APPEAR_FUNC float appear_beckmann_G2(float ax, float ay, appear_vec3 wo, appear_vec3 wi, appear_vec3 m)
{
    int ok;
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    ok = ax > 0.0f && ay > 0.0f && appear_is_unit(wo) && appear_is_unit(wi) && appear_is_unit(m) && m.z > 0.0f &&
         appear_dot(wo, m) * wo.z > 0.0f && appear_dot(wi, m) * wi.z > 0.0f;
    return ok ? appear__g2_from_zl(appear__beckmann_zlambda(ax, ay, wo), wo.z, appear__beckmann_zlambda(ax, ay, wi), wi.z) : 0.0f;
}

/* ======================================================================== */
/* Visible normals: sampling and pdf                                        */
/* ======================================================================== */

/* GGX visible normals by spherical caps [DB23, Listing 3]. wo with z >= 0
   (callers mirror). Stretch wo to the alpha = 1 configuration, sample the
   spherical cap z in [-wo_s.z, 1] uniformly (Sec. 3), add wo_s (the half
   vector of the hemisphere construction), unstretch and normalise. The
   cap's sin^2 is formed as u2 (1+c) ((1-u2)(1+c) + (1-c)) with c = wo_s.z,
   a product of non-negative factors, so z -> 1 keeps its digits.
   Returns the zero vector when the construction degenerates (measure 0). */
APPEAR_FUNC appear_vec3 appear__ggx_sample_caps(float ax, float ay, appear_vec3 wo, float u1, float u2)
{
    appear_vec3 v = appear_normalize(appear_vec3_make(ax * wo.x, ay * wo.y, wo.z));
    float c = v.z, sp, cp, z, st;
    appear_vec3 h;
    u2 = appear__clamp(u2, 0.0f, 1.0f);
    appear_sincos_2pi(u1, &sp, &cp);
    z = (1.0f - u2) * (1.0f + c) - c;
    st = appear__safe_sqrt(u2 * (1.0f + c) * ((1.0f - u2) * (1.0f + c) + (1.0f - c)));
    h = appear_vec3_make(st * cp + v.x, st * sp + v.y, z + c);
    h = appear_normalize(appear_vec3_make(ax * h.x, ay * h.y, h.z > 0.0f ? h.z : 0.0f));
    return h.z > 0.0f ? h : appear__zero3();
}

/* Bounded VNDF sampling of GGX [ET23, Listing 1, Eq. 5-6]: the caps
   construction with the cap shrunk to z in [-k c, 1], where
   k = (1 - a^2) s^2 / (s^2 + a^2 wo.z^2), a = min(1, min(ax, ay)),
   s = 1 + |wo.xy|. Only normals whose reflection may be above the horizon
   are generated; use with appear__ggx_pdf_reflect_bounded. */
APPEAR_FUNC appear_vec3 appear__ggx_sample_bounded(float ax, float ay, appear_vec3 wo, float u1, float u2)
{
    appear_vec3 v = appear_normalize(appear_vec3_make(ax * wo.x, ay * wo.y, wo.z));
    float a = appear__min(1.0f, appear__min(ax, ay));
    float s = 1.0f + APPEAR_SQRTF(wo.x * wo.x + wo.y * wo.y);
    float a2 = a * a, s2 = s * s;
    float k = (1.0f - a2) * s2 / (s2 + a2 * wo.z * wo.z);
    float c = k * v.z, sp, cp, z, st;
    appear_vec3 h;
    u2 = appear__clamp(u2, 0.0f, 1.0f);
    appear_sincos_2pi(u1, &sp, &cp);
    z = (1.0f - u2) * (1.0f + c) - c;
    st = appear__safe_sqrt(u2 * (1.0f + c) * ((1.0f - u2) * (1.0f + c) + (1.0f - c)));
    h = appear_vec3_make(st * cp + v.x, st * sp + v.y, z + v.z);
    h = appear_normalize(appear_vec3_make(ax * h.x, ay * h.y, h.z > 0.0f ? h.z : 0.0f));
    return h.z > 0.0f ? h : appear__zero3();
}
/* pdf of the REFLECTED direction wi under bounded VNDF sampling [ET23,
   Eq. 8 times the reflection Jacobian]: D(h) / (2 (k wo.z + t)),
   t = sqrt(ax^2 x^2 + ay^2 y^2 + z^2); wo, wi with z > 0. */
APPEAR_FUNC float appear__ggx_pdf_reflect_bounded(float ax, float ay, appear_vec3 wo, appear_vec3 h)
{
    float a = appear__min(1.0f, appear__min(ax, ay));
    float s = 1.0f + APPEAR_SQRTF(wo.x * wo.x + wo.y * wo.y);
    float a2 = a * a, s2 = s * s;
    float k = (1.0f - a2) * s2 / (s2 + a2 * wo.z * wo.z);
    float t = APPEAR_SQRTF(ax * ax * wo.x * wo.x + ay * ay * wo.y * wo.y + wo.z * wo.z);
    return appear__ggx_D(ax, ay, h) / (2.0f * (k * wo.z + t));
}

/* Beckmann visible normals [HdE14, Sec. 4 and App. B]: stretch wo to
   alpha = 1, sample the slope x~ along the projected direction from
   p(x~) ~ (cot - x~) exp(-x~^2) on x~ < cot, and y~ ~ exp(-y~^2)
   independently, rotate, unstretch. x~ is found in the erf domain
   b = erf(x~), where the CDF is (up to normalisation)
       C(b) = p (1 + b) + q exp(-x~^2)/sqrt(pi),  dC/db = p - q x~,
   with (p, q) = (1, tan) for cot >= 1 and (cot, 1) below, so neither
   normal incidence (cot = inf) nor grazing (cot = 0) produces inf * 0.
   Newton steps safeguarded by bisection on [-1, erf(cot)], at most 16:
   no NaN when cos(theta) rounds to 1 at low roughness. */
APPEAR_FUNC appear_vec3 appear__beckmann_sample_vis(float ax, float ay, appear_vec3 wo, float u1, float u2)
{
    appear_vec3 v = appear_normalize(appear_vec3_make(ax * wo.x, ay * wo.y, wo.z));
    float r = APPEAR_SQRTF(v.x * v.x + v.y * v.y);
    float cphi = r > 0.0f ? v.x / r : 1.0f, sphi = r > 0.0f ? v.y / r : 0.0f;
    int big = v.z >= r;                              /* cot >= 1 */
    float cot = big ? (r > 0.0f ? appear__min(v.z / r, 10.0f) : 10.0f) : v.z / r;
    float tn = big ? r / v.z : 1.0f;                 /* q */
    float p = big ? 1.0f : cot;
    float lo = -1.0f, hi = appear__erf(cot);
    float norm = p * (1.0f + hi) + tn * appear__exp(-cot * cot) * APPEAR__INV_SQRT_PI;
    float u = appear__clamp(u1, 0.0f, 1.0f);
    float target = u * norm;
    float b = lo + (hi - lo) * u, x = 0.0f, sx, sy, y;
    int it;
    if (!(v.z >= 0.0f) || !(norm > 0.0f)) return appear__zero3();
    for (it = 0; it < 16; ++it) {
        float val, der;
        if (!(b > lo && b < hi)) b = 0.5f * (lo + hi);
        x = appear__erfinv(b);
        val = p * (1.0f + b) + tn * appear__exp(-x * x) * APPEAR__INV_SQRT_PI - target;
        der = p - tn * x;
        if (val > 0.0f) hi = b; else lo = b;
        if (APPEAR_FABSF(val) <= 2e-7f * norm || hi - lo <= 1.2e-7f) break;
        b -= der > 0.0f ? val / der : 0.0f;
    }
    x = appear__erfinv(appear__clamp(b, -0.99999994f, 0.99999994f));
    y = appear__erfinv(appear__clamp(2.0f * u2 - 1.0f, -0.99999994f, 0.99999994f));
    sx = ax * (cphi * x - sphi * y);
    sy = ay * (sphi * x + cphi * y);
    v = appear_normalize(appear_vec3_make(-sx, -sy, 1.0f));
    return v.z > 0.0f ? v : appear__zero3();
}

/* Full-D sampling, m ~ D(m) m.z [Walter07, Eq. 28-29, 35-36], in slope
   space: a radial slope of the alpha = 1 distribution (GGX:
   r^2 = u1/(1-u1); Beckmann: r^2 = -log(1-u1)), stretched by (ax, ay).
   pdf(m) = D(m) m.z. */
APPEAR_FUNC appear_vec3 appear__mf_sample_D(int type, float ax, float ay, float u1, float u2)
{
    float sp, cp, r2;
    appear_vec3 m;
    u1 = appear__clamp(u1, 0.0f, 1.0f);
    r2 = type == APPEAR_GGX ? u1 / (1.0f - u1) : -appear__log(1.0f - u1);
    appear_sincos_2pi(u2, &sp, &cp);
    r2 = APPEAR_SQRTF(r2);
    m = appear_normalize(appear_vec3_make(-ax * r2 * cp, -ay * r2 * sp, 1.0f));
    return m.z > 0.0f ? m : appear__zero3();
}

/* VNDF D_wo(m) = G1(wo) max(0, wo.m) D(m) / wo.z [Heitz14, Eq. 38 / HdE14
   Eq. 2] = max(0, wo.m) D(m) / (wo.z + wo.z Lambda(wo)); wo.z > 0. */
APPEAR_FUNC float appear__vndf(float d, float zl, appear_vec3 wo, appear_vec3 m)
{
    float c = appear_dot(wo, m);
    float den = wo.z + zl;
    return c > 0.0f && den > 0.0f ? c * d / den : 0.0f;
}

/* Public samplers and pdfs of visible normals. wo on either side (mirrored
   to z >= 0); m is returned with m.z > 0 (the zero vector on failure).
   pdf_visible(wo, m) = G1(wo) |wo.m| D(m) / |wo.z| when (wo.m) wo.z > 0,
   else 0. */
APPEAR_FUNC appear_vec3 appear_ggx_sample_visible(float ax, float ay, appear_vec3 wo, float u1, float u2)
{
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    if (!(ax > 0.0f && ay > 0.0f && appear_is_unit(wo) && wo.z != 0.0f && appear__isfinite(u1))) return appear__zero3();
    return appear__ggx_sample_caps(ax, ay, wo.z < 0.0f ? appear_neg(wo) : wo, u1, u2);
}
APPEAR_FUNC float appear_ggx_pdf_visible(float ax, float ay, appear_vec3 wo, appear_vec3 m)
{
    int ok;
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    ok = ax > 0.0f && ay > 0.0f && appear_is_unit(wo) && appear_is_unit(m) && wo.z != 0.0f && m.z > 0.0f;
    wo = wo.z < 0.0f ? appear_neg(wo) : wo;
    return ok ? appear__vndf(appear__ggx_D(ax, ay, m), appear__ggx_zlambda(ax, ay, wo), wo, m) : 0.0f;
}
/* Bounded VNDF [ET23]: returns m; the pdf that matters is that of the
   reflected direction, appear_ggx_pdf_reflect_bounded(wo, wi) =
   D(h) / (2 (k |wo.z| + t)) for wi on the side of wo, else 0. */
APPEAR_FUNC appear_vec3 appear_ggx_sample_visible_bounded(float ax, float ay, appear_vec3 wo, float u1, float u2)
{
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    if (!(ax > 0.0f && ay > 0.0f && appear_is_unit(wo) && wo.z != 0.0f && appear__isfinite(u1))) return appear__zero3();
    return appear__ggx_sample_bounded(ax, ay, wo.z < 0.0f ? appear_neg(wo) : wo, u1, u2);
}
APPEAR_FUNC float appear_ggx_pdf_reflect_bounded(float ax, float ay, appear_vec3 wo, appear_vec3 wi)
{
    int ok;
    appear_vec3 h;
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    ok = ax > 0.0f && ay > 0.0f && appear_is_unit(wo) && appear_is_unit(wi) && wo.z * wi.z > 0.0f;
    if (wo.z < 0.0f) { wo = appear_neg(wo); wi = appear_neg(wi); }
    h = appear_normalize(appear_add(wo, wi));
    return ok ? appear__ggx_pdf_reflect_bounded(ax, ay, wo, h) : 0.0f;
}
APPEAR_FUNC appear_vec3 appear_beckmann_sample_visible(float ax, float ay, appear_vec3 wo, float u1, float u2)
{
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    if (!(ax > 0.0f && ay > 0.0f && appear_is_unit(wo) && wo.z != 0.0f && appear__isfinite(u1) && appear__isfinite(u2)))
        return appear__zero3();
    return appear__beckmann_sample_vis(ax, ay, wo.z < 0.0f ? appear_neg(wo) : wo, u1, u2);
}
APPEAR_FUNC float appear_beckmann_pdf_visible(float ax, float ay, appear_vec3 wo, appear_vec3 m)
{
    int ok;
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    ok = ax > 0.0f && ay > 0.0f && appear_is_unit(wo) && appear_is_unit(m) && wo.z != 0.0f && m.z > 0.0f;
    wo = wo.z < 0.0f ? appear_neg(wo) : wo;
    return ok ? appear__vndf(appear__beckmann_D(ax, ay, m), appear__beckmann_zlambda(ax, ay, wo), wo, m) : 0.0f;
}
/* Full-D samplers: m ~ D(m) m.z, pdf_D(m) = D(m) m.z. */
APPEAR_FUNC appear_vec3 appear_ggx_sample_D(float ax, float ay, float u1, float u2)
{
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    return ax > 0.0f && ay > 0.0f && appear__isfinite(u2) ? appear__mf_sample_D(APPEAR_GGX, ax, ay, u1, u2) : appear__zero3();
}
APPEAR_FUNC float appear_ggx_pdf_D(float ax, float ay, appear_vec3 m)
{ return appear_ggx_D(ax, ay, m) * (m.z > 0.0f ? m.z : 0.0f); }
APPEAR_FUNC appear_vec3 appear_beckmann_sample_D(float ax, float ay, float u1, float u2)
{
    ax = appear__mf_alpha(ax); ay = appear__mf_alpha(ay);
    return ax > 0.0f && ay > 0.0f && appear__isfinite(u2) ? appear__mf_sample_D(APPEAR_BECKMANN, ax, ay, u1, u2) : appear__zero3();
}
APPEAR_FUNC float appear_beckmann_pdf_D(float ax, float ay, appear_vec3 m)
{ return appear_beckmann_D(ax, ay, m) * (m.z > 0.0f ? m.z : 0.0f); }

/* ======================================================================== */
/* The distribution struct (what models dispatch on)                        */
/* ======================================================================== */

/* Reference: type must be APPEAR_GGX or APPEAR_BECKMANN, sampling one of
   APPEAR_SAMPLE_* (BOUNDED only with GGX), ax and ay finite in
   [0, APPEAR_MICROFACET_ALPHA_MAX]; otherwise valid = 0. alpha = 0 is
   allowed and means smooth. max(ax, ay) < APPEAR_MICROFACET_ALPHA_MIN sets
   smooth = 1; otherwise each alpha is raised to at least ALPHA_MIN. */
APPEAR_FUNC appear_microfacet appear_microfacet_make(int type, float ax, float ay, int sampling)
{
    appear_microfacet d;
    d.valid = (type == APPEAR_GGX || type == APPEAR_BECKMANN) &&
              (sampling == APPEAR_SAMPLE_VISIBLE || sampling == APPEAR_SAMPLE_FULL_D ||
               (sampling == APPEAR_SAMPLE_BOUNDED && type == APPEAR_GGX)) &&
              ax >= 0.0f && ax <= APPEAR_MICROFACET_ALPHA_MAX && ay >= 0.0f && ay <= APPEAR_MICROFACET_ALPHA_MAX;
    d.type = d.valid ? type : APPEAR_GGX;
    d.sampling = d.valid ? sampling : APPEAR_SAMPLE_VISIBLE;
    d.smooth = d.valid && appear__max(ax, ay) < APPEAR_MICROFACET_ALPHA_MIN;
    d.ax = d.valid ? appear__max(ax, APPEAR_MICROFACET_ALPHA_MIN) : 1.0f;
    d.ay = d.valid ? appear__max(ay, APPEAR_MICROFACET_ALPHA_MIN) : 1.0f;
    return d;
}
/* Dispatchers (no validation: model internals; m, w unit). */
APPEAR_FUNC float appear__mf_D(const appear_microfacet *d, appear_vec3 m)
{ return d->type == APPEAR_GGX ? appear__ggx_D(d->ax, d->ay, m) : appear__beckmann_D(d->ax, d->ay, m); }
APPEAR_FUNC float appear__mf_zl(const appear_microfacet *d, appear_vec3 w)
{ return d->type == APPEAR_GGX ? appear__ggx_zlambda(d->ax, d->ay, w) : appear__beckmann_zlambda(d->ax, d->ay, w); }
/* G2 / (4 |zo| |zi|) = 1 / (4 (zo zi + zi zLo + zo zLi)), finite when one
   of zo, zi is non-zero. */
APPEAR_FUNC float appear__mf_vis(float zlo, float zo, float zli, float zi)
{
    float den = 4.0f * (zo * zi + zi * zlo + zo * zli);
    return den > 0.0f ? 1.0f / den : 0.0f;
}
/* Sample m for wo with z > 0 (VISIBLE or FULL_D; BOUNDED = GGX bounded). */
APPEAR_FUNC appear_vec3 appear__mf_sample_m(const appear_microfacet *d, appear_vec3 wo, float u1, float u2, int allow_bounded)
{
    if (d->sampling == APPEAR_SAMPLE_FULL_D) return appear__mf_sample_D(d->type, d->ax, d->ay, u1, u2);
    if (d->type == APPEAR_BECKMANN) return appear__beckmann_sample_vis(d->ax, d->ay, wo, u1, u2);
    if (d->sampling == APPEAR_SAMPLE_BOUNDED && allow_bounded) return appear__ggx_sample_bounded(d->ax, d->ay, wo, u1, u2);
    return appear__ggx_sample_caps(d->ax, d->ay, wo, u1, u2);
}
/* pdf of m for the strategy (VISIBLE: D_wo(m); FULL_D: D(m) m.z); wo.z > 0. */
APPEAR_FUNC float appear__mf_pdf_m(const appear_microfacet *d, appear_vec3 wo, appear_vec3 m, float dm, float zlo)
{
    float full = dm * (m.z > 0.0f ? m.z : 0.0f);
    float c = appear_dot(wo, m);
    return d->sampling == APPEAR_SAMPLE_FULL_D ? (c > 0.0f ? full : 0.0f) : appear__vndf(dm, zlo, wo, m);
}

/* ======================================================================== */
/* Fresnel                                                                  */
/* ======================================================================== */

/* Exact unpolarised dielectric Fresnel reflectance [BW99, Sec. 1.5.2].
   cos_i is signed: cos_i >= 0 means the light arrives from the outside
   (relative IOR eta = n_inside / n_outside); cos_i < 0 means from the
   inside, then eta -> 1/eta and cos_i -> -cos_i. With
   g = sqrt(eta^2 - 1 + c^2) (= eta cos_t; [Walter07, Eq. 22]):
       r_s = (c - g)/(c + g) = (1 - eta^2) / (c + g)^2,
       r_p = (eta^2 c - g)/(eta^2 c + g) = (eta^2 - 1)((eta^2 + 1) c^2 - 1) / (eta^2 c + g)^2,
   F = (r_s^2 + r_p^2) / 2: the cancelling differences are formed as
   products, so F keeps its relative accuracy as eta -> 1 (F ~ (eta-1)^2/4).
   g^2 < 0: total internal reflection, F = 1. eta = 1: F = 0 everywhere.
   eta <= 0 or NaN, or NaN cos_i: 0. |cos_i| is clamped to 1.
   Optional out: cos_t (>= 0, 0 under TIR) and the relative eta used. */
APPEAR_FUNC float appear__fresnel_dielectric_full(float cos_i, float eta, float *cos_t)
{
    float c = APPEAR_FABSF(cos_i);
    float e = cos_i < 0.0f ? 1.0f / eta : eta;
    float e2, g2, g, rs, rp, ds, dp, f;
    int ok = eta > 0.0f && eta <= APPEAR_FLT_MAX && c == c;
    c = c < 1.0f ? c : 1.0f;
    e = ok ? appear__clamp(e, 1e-6f, 1e6f) : 1.0f; /* documented range of eta */
    e2 = e * e;
    g2 = (e - 1.0f) * (e + 1.0f) + c * c;
    g = appear__safe_sqrt(g2);
    ds = (c + g) * (c + g);
    dp = (e2 * c + g) * (e2 * c + g);
    rs = ds > 0.0f ? (1.0f - e) * (1.0f + e) / ds : 0.0f;
    rp = dp > 0.0f ? (e - 1.0f) * (e + 1.0f) * ((e2 + 1.0f) * c * c - 1.0f) / dp : 0.0f;
    f = 0.5f * (rs * rs + rp * rp);
    f = g2 < 0.0f ? 1.0f : appear__clamp(appear__finite_or_zero(f), 0.0f, 1.0f);
    f = ok ? f : 0.0f;
    if (cos_t) *cos_t = ok && g2 > 0.0f ? g / e : 0.0f;
    return f;
}
APPEAR_FUNC float appear_fresnel_dielectric(float cos_i, float eta)
{ return appear__fresnel_dielectric_full(cos_i, eta, 0); }
APPEAR_FUNC appear_spectrum appear_fresnel_dielectric_spectrum(float cos_i, appear_spectrum eta)
{
    appear_spectrum r; int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) r.v[i] = appear_fresnel_dielectric(cos_i, eta.v[i]);
    return r;
}

/* Exact conductor Fresnel reflectance for complex IOR eta + i k, one
   wavelength [BW99, Sec. 14.2; in the a, b form of e.g. Lazanyi &
   Szirmay-Kalos 2005]: with s^2 = 1 - c^2, t0 = eta^2 - k^2 - s^2,
   a^2 + b^2 = sqrt(t0^2 + 4 eta^2 k^2), a^2 = (a^2 + b^2 + t0) / 2:
     R_s = (a^2 + b^2 - 2 a c + c^2) / (a^2 + b^2 + 2 a c + c^2),
     R_p = R_s (c^2 (a^2+b^2) - 2 a c s^2 + s^4) / (c^2 (a^2+b^2) + 2 a c s^2 + s^4),
   F = (R_s + R_p) / 2. |cos_i| is used. eta and k are clamped into
   [0, 1e6] (NaN -> 0); k = 0 gives the dielectric result (incl. TIR for
   eta < 1). c = 0 gives 1. Result in [0, 1]. */
APPEAR_FUNC float appear_fresnel_conductor(float cos_i, float eta, float k)
{
    float c = appear__clamp(APPEAR_FABSF(cos_i), 0.0f, 1.0f);
    float c2, s2, e2, k2, t0, ab, a, t1, t2, t3, t4, rs, rp;
    eta = appear__clamp(eta, 0.0f, 1e6f); k = appear__clamp(k, 0.0f, 1e6f);
    eta = eta == eta ? eta : 0.0f; k = k == k ? k : 0.0f;
    c = c == c ? c : 1.0f;
    c2 = c * c; s2 = (1.0f - c) * (1.0f + c);
    e2 = eta * eta; k2 = k * k;
    t0 = e2 - k2 - s2;
    ab = APPEAR_SQRTF(t0 * t0 + 4.0f * e2 * k2);
    a = appear__safe_sqrt(0.5f * (ab + t0));
    t1 = ab + c2; t2 = 2.0f * a * c;
    rs = t1 + t2 > 0.0f ? (t1 - t2) / (t1 + t2) : 1.0f;
    t3 = c2 * ab + s2 * s2; t4 = t2 * s2;
    rp = t3 + t4 > 0.0f ? rs * (t3 - t4) / (t3 + t4) : rs;
    return appear__clamp(appear__finite_or_zero(0.5f * (rs + rp)), 0.0f, 1.0f);
}
APPEAR_FUNC appear_spectrum appear_fresnel_conductor_spectrum(float cos_i, appear_spectrum eta, appear_spectrum k)
{
    appear_spectrum r; int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) r.v[i] = appear_fresnel_conductor(cos_i, eta.v[i], k.v[i]);
    return r;
}

/* Schlick's approximation [Schlick94, Eq. 15]: F0 + (1 - F0)(1 - |c|)^5.
   F0 clamped to [0, 1] (NaN -> 0), |c| to [0, 1]. */
APPEAR_FUNC float appear_fresnel_schlick(float cos_i, float f0)
{
    float c = appear__clamp(APPEAR_FABSF(cos_i), 0.0f, 1.0f), m, m2;
    c = c == c ? c : 1.0f;
    f0 = f0 == f0 ? appear__clamp(f0, 0.0f, 1.0f) : 0.0f;
    m = 1.0f - c; m2 = m * m;
    return f0 + (1.0f - f0) * m2 * m2 * m;
}
APPEAR_FUNC appear_spectrum appear_fresnel_schlick_spectrum(float cos_i, appear_spectrum f0)
{
    appear_spectrum r; int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) r.v[i] = appear_fresnel_schlick(cos_i, f0.v[i]);
    return r;
}

/* F82-tint conductor [Kutz21, Sec. 2.1]: Schlick with a Lazanyi correction
   term,  F(c) = F_s(c) - b c (1 - c)^6,  where b is fixed so that at
   c82 = 1/7 (82 degrees) F equals tint * F_s(c82):
       b = F_s(c82) (1 - tint) / (c82 (1 - c82)^6).
   appear_f82_coef() precomputes b; appear_fresnel_f82() evaluates with it.
   f0, tint in [0, 1]; the result is clamped into [0, 1]. */
APPEAR_FUNC float appear_f82_coef(float f0, float tint)
{
    const float c82 = 1.0f / 7.0f;
    const float inv_den = 117649.0f / (46656.0f * c82); /* 1 / (c82 (6/7)^6) */
    tint = tint == tint ? appear__clamp(tint, 0.0f, 1.0f) : 1.0f;
    return appear_fresnel_schlick(c82, f0) * (1.0f - tint) * inv_den;
}
APPEAR_FUNC float appear_fresnel_f82(float cos_i, float f0, float b)
{
    float c = appear__clamp(APPEAR_FABSF(cos_i), 0.0f, 1.0f), m, m3;
    c = c == c ? c : 1.0f;
    m = 1.0f - c; m3 = m * m * m;
    b = b == b ? b : 0.0f;
    return appear__clamp(appear__finite_or_zero(appear_fresnel_schlick(c, f0) - b * c * m3 * m3), 0.0f, 1.0f);
}
APPEAR_FUNC appear_spectrum appear_fresnel_f82_spectrum(float cos_i, appear_spectrum f0, appear_spectrum tint)
{
    appear_spectrum r; int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) r.v[i] = appear_fresnel_f82(cos_i, f0.v[i], appear_f82_coef(f0.v[i], tint.v[i]));
    return r;
}

/* ======================================================================== */
/* Rough conductor BRDF                                                     */
/* f(wo, wi) = F(wo.h) D(h) G2(wo, wi) / (4 |wo.z| |wi.z|)  [Walter07, Eq.20]*/
/* ======================================================================== */

enum { APPEAR_FRESNEL_CONDUCTOR = 0, APPEAR_FRESNEL_F82 = 1 };

typedef struct appear_conductor {
    appear_microfacet d;
    appear_spectrum   p0, p1;  /* complex IOR (eta, k) or F82 (f0, b) */
    int               fresnel; /* APPEAR_FRESNEL_* */
    int               valid;
} appear_conductor;

APPEAR_FUNC appear_conductor appear__conductor_check(appear_conductor c, float lo1, float hi1)
{
    int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i)
        c.valid &= c.p0.v[i] >= 0.0f && c.p0.v[i] <= hi1 && c.p1.v[i] >= lo1 && c.p1.v[i] <= 1e6f;
    if (!c.valid) { c.p0 = appear_spectrum_splat(0.0f); c.p1 = appear_spectrum_splat(0.0f); }
    return c;
}
/* Reference: complex IOR eta + i k per channel (eta, k finite in [0, 1e6])
   and a valid distribution; otherwise valid = 0. E.g. gold at RGB
   ~ eta (0.143, 0.374, 1.442), k (3.983, 2.386, 1.603). */
APPEAR_FUNC appear_conductor appear_conductor_make(appear_microfacet d, appear_spectrum eta, appear_spectrum k)
{
    appear_conductor c;
    c.d = d; c.p0 = eta; c.p1 = k; c.fresnel = APPEAR_FRESNEL_CONDUCTOR; c.valid = d.valid;
    return appear__conductor_check(c, 0.0f, 1e6f);
}
/* Reference: F82-tint parameters f0 and tint in [0, 1] per channel. */
APPEAR_FUNC appear_conductor appear_conductor_make_f82(appear_microfacet d, appear_spectrum f0, appear_spectrum tint)
{
    appear_conductor c; int i;
    c.d = d; c.p0 = f0; c.fresnel = APPEAR_FRESNEL_F82; c.valid = d.valid;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) {
        c.valid &= tint.v[i] >= 0.0f && tint.v[i] <= 1.0f;
        c.p1.v[i] = appear_f82_coef(f0.v[i], tint.v[i]);
    }
    c = appear__conductor_check(c, -1e6f, 1.0f);
    return c;
}
APPEAR_FUNC appear_spectrum appear__conductor_F(const appear_conductor *c, float cos_i)
{
    appear_spectrum r; int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i)
        r.v[i] = c->fresnel == APPEAR_FRESNEL_F82 ? appear_fresnel_f82(cos_i, c->p0.v[i], c->p1.v[i])
                                                  : appear_fresnel_conductor(cos_i, c->p0.v[i], c->p1.v[i]);
    return r;
}
/* Scalar part of f and of the pdf for wo, wi mirrored to z > 0. */
APPEAR_FUNC float appear__conductor_core(const appear_conductor *c, appear_vec3 wo, appear_vec3 wi, float *pdf, float *cos_h)
{
    appear_vec3 h = appear_normalize(appear_add(wo, wi));
    float dm = appear__mf_D(&c->d, h);
    float zlo = appear__mf_zl(&c->d, wo), zli = appear__mf_zl(&c->d, wi);
    float oh = appear_dot(wo, h);
    float pm;
    /* reflection Jacobian dh/dwi = 1 / (4 wo.h) [Walter07, Eq. 14] */
    if (c->d.sampling == APPEAR_SAMPLE_BOUNDED && c->d.type == APPEAR_GGX)
        pm = appear__ggx_pdf_reflect_bounded(c->d.ax, c->d.ay, wo, h);
    else
        pm = oh > 0.0f ? appear__mf_pdf_m(&c->d, wo, h, dm, zlo) / (4.0f * oh) : 0.0f;
    *pdf = appear__finite_or_zero(pm);
    *cos_h = oh;
    return appear__finite_or_zero(dm * appear__mf_vis(zlo, wo.z, zli, wi.z));
}

/* f(wo, wi) for wo, wi on the same side (two-sided); 0 otherwise, for
   invalid directions, and for the smooth (delta) limit. */
APPEAR_FUNC appear_spectrum appear_conductor_eval(const appear_conductor *c, appear_vec3 wo, appear_vec3 wi)
{
    float pdf, ch, f;
    int ok = c->valid && !c->d.smooth && appear_is_unit(wo) && appear_is_unit(wi) && wo.z * wi.z > 0.0f;
    if (!ok) return appear_spectrum_splat(0.0f);
    if (wo.z < 0.0f) { wo.z = -wo.z; wi.z = -wi.z; }
    f = appear__conductor_core(c, wo, wi, &pdf, &ch);
    return appear_spectrum_scale(appear__conductor_F(c, ch), f);
}
/* pdf(wi) of appear_conductor_sample:
     VISIBLE: D_wo(h) / (4 wo.h) = D(h) / (4 (|wo.z| + |wo.z| Lambda(wo)))
              [Heitz18, Eq. 17]; GGX: D(h) / (2 (|wo.z| + t)).
     BOUNDED: D(h) / (2 (k |wo.z| + t))                        [ET23, Eq. 8]
     FULL_D:  D(h) h.z / (4 wo.h)                         [Walter07, Eq. 14]
   with h = normalize(wo + wi), for wi on the side of wo; else 0. */
APPEAR_FUNC float appear_conductor_pdf(const appear_conductor *c, appear_vec3 wo, appear_vec3 wi)
{
    float pdf, ch;
    int ok = c->valid && !c->d.smooth && appear_is_unit(wo) && appear_is_unit(wi) && wo.z * wi.z > 0.0f;
    if (!ok) return 0.0f;
    if (wo.z < 0.0f) { wo.z = -wo.z; wi.z = -wi.z; }
    (void)appear__conductor_core(c, wo, wi, &pdf, &ch);
    return pdf;
}
APPEAR_FUNC int appear__bsdf_fail(appear_bsdf_sample *s)
{
    s->wi = appear__zero3();
    s->f = s->weight = appear_spectrum_splat(0.0f);
    s->pdf = 0.0f; s->eta = 1.0f; s->flags = 0u;
    return 0;
}
/* Samples h with the distribution's strategy, reflects wo about it.
   uc is unused. Fails (returns 0) for invalid input, wo in the tangent
   plane, and when the reflected direction is below the horizon (the
   sampler's lost mass: the pdf integrates to the success probability).
   Smooth limit: wi = (-wo.x, -wo.y, wo.z), pdf = 1, f = F(|wo.z|)/|wo.z|,
   weight = F, flags REFLECTION | SPECULAR. */
APPEAR_FUNC int appear_conductor_sample(const appear_conductor *c, appear_vec3 wo, float uc, float u1, float u2,
                                        appear_bsdf_sample *s)
{
    float sg, pdf, ch, f, ci;
    appear_vec3 m, wi;
    int i;
    (void)uc;
    if (!(c->valid && appear_is_unit(wo) && wo.z != 0.0f && appear__isfinite(u1) && appear__isfinite(u2)))
        return appear__bsdf_fail(s);
    sg = wo.z < 0.0f ? -1.0f : 1.0f;
    wo.z = APPEAR_FABSF(wo.z);
    if (c->d.smooth) {
        s->wi = appear_vec3_make(-wo.x, -wo.y, sg * wo.z);
        s->weight = appear__conductor_F(c, wo.z);
        s->f = appear_spectrum_scale(s->weight, 1.0f / wo.z);
        s->pdf = 1.0f; s->eta = 1.0f;
        s->flags = (unsigned)(APPEAR_LOBE_REFLECTION | APPEAR_LOBE_SPECULAR);
        return 1;
    }
    m = appear__mf_sample_m(&c->d, wo, u1, u2, 1);
    wi = appear__reflect(wo, m);
    if (!(m.z > 0.0f && wi.z > 0.0f && appear_dot(wo, m) > 0.0f)) return appear__bsdf_fail(s);
    wi = appear_normalize(wi);
    f = appear__conductor_core(c, wo, wi, &pdf, &ch);
    if (!(pdf > 0.0f) || !(wi.z > 0.0f)) return appear__bsdf_fail(s);
    s->f = appear_spectrum_scale(appear__conductor_F(c, ch), f);
    ci = wi.z / pdf;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) s->weight.v[i] = appear__finite_or_zero(s->f.v[i] * ci);
    s->wi = appear_vec3_make(wi.x, wi.y, sg * wi.z);
    s->pdf = pdf; s->eta = 1.0f;
    s->flags = (unsigned)(APPEAR_LOBE_REFLECTION | APPEAR_LOBE_GLOSSY);
    return 1;
}

/* ======================================================================== */
/* Rough dielectric BSDF [Walter07]                                         */
/* ======================================================================== */

typedef struct appear_dielectric {
    appear_microfacet d;
    float eta;    /* n_inside / n_outside */
    int   smooth; /* delta lobes: d.smooth, or eta == 1 (pass-through) */
    int   valid;
} appear_dielectric;

/* Reference: eta finite, > 0 (eta < 1 is fine: a bubble); d valid (the
   BOUNDED strategy is treated as VISIBLE: bounded VNDF covers reflection
   only). eta == 1 exactly is an index-matched interface: light passes
   straight through (a delta transmission with weight 1) whatever alpha. */
APPEAR_FUNC appear_dielectric appear_dielectric_make(appear_microfacet d, float eta)
{
    appear_dielectric m;
    m.valid = d.valid && eta > 0.0f && eta <= 1e6f;
    m.d = d;
    m.d.sampling = d.sampling == APPEAR_SAMPLE_BOUNDED ? APPEAR_SAMPLE_VISIBLE : d.sampling;
    m.eta = m.valid ? eta : 1.0f;
    m.smooth = m.valid && (d.smooth || eta == 1.0f);
    return m;
}

/* Core for wo.z > 0 (wo and wi mirrored when wo is inside; e = n(other
   side) / n(wo side)). Returns f, writes the pdf.
   Reflection (wi.z > 0): h = normalize(wo + wi),
       f = F D G2 / (4 zo zi),  pdf = F D_wo(h) / (4 wo.h)   (VISIBLE)
   Transmission (wi.z < 0): h = +-normalize(wo + e wi) with h.z > 0, needs
   wo.h > 0 > wi.h [Walter07, Eq. 16 and Sec. 5.2],
       f = (1-F) D G2 |wi.h| |wo.h| / (zo |zi| L^2),   L = |wo + e wi|
       pdf = (1-F) D_wo(h) e^2 |wi.h| / L^2             [Walter07, Eq. 17]
   (FULL_D: D_wo(h) replaced by D(h) h.z). F = F(wo.h, e). */
APPEAR_FUNC float appear__dielectric_core(const appear_dielectric *m, appear_vec3 wo, appear_vec3 wi, float e, float *pdf)
{
    int refl = wi.z > 0.0f;
    appear_vec3 hv = refl ? appear_add(wo, wi) : appear_add(wo, appear_scale(wi, e));
    float l2 = appear_dot(hv, hv);
    appear_vec3 h = appear_normalize(hv);
    float oh, ih, dm, zlo, zli, fr, g4, pm, jac, f;
    h = h.z < 0.0f ? appear_neg(h) : h;
    oh = appear_dot(wo, h); ih = appear_dot(wi, h);
    dm = appear__mf_D(&m->d, h);
    zlo = appear__mf_zl(&m->d, wo); zli = appear__mf_zl(&m->d, wi);
    fr = appear__fresnel_dielectric_full(oh, e, 0);
    g4 = appear__mf_vis(zlo, wo.z, zli, APPEAR_FABSF(wi.z));  /* G2 / (4 zo |zi|) */
    pm = appear__mf_pdf_m(&m->d, wo, h, dm, zlo);
    if (refl) {
        int ok = oh > 0.0f && h.z > 0.0f;
        f = ok ? fr * dm * g4 : 0.0f;
        pm = ok ? fr * pm / (4.0f * oh) : 0.0f;
    } else {
        int ok = oh > 0.0f && ih < 0.0f && h.z > 0.0f && l2 > 0.0f;
        jac = ok ? -ih / l2 : 0.0f;
        f = ok ? (1.0f - fr) * dm * 4.0f * g4 * oh * jac : 0.0f;
        pm = ok ? (1.0f - fr) * pm * e * e * jac : 0.0f;
    }
    *pdf = appear__finite_or_zero(pm);
    return appear__finite_or_zero(f);
}

/* f(wo, wi), radiance convention (see the top of this section). Zero for
   the smooth limit, invalid or tangent-plane directions. */
APPEAR_FUNC appear_spectrum appear_dielectric_eval(const appear_dielectric *m, appear_vec3 wo, appear_vec3 wi)
{
    float pdf, e;
    int ok = m->valid && !m->smooth && appear_is_unit(wo) && appear_is_unit(wi) && wo.z != 0.0f && wi.z != 0.0f;
    if (!ok) return appear_spectrum_splat(0.0f);
    e = wo.z > 0.0f ? m->eta : 1.0f / m->eta;
    if (wo.z < 0.0f) { wo.z = -wo.z; wi.z = -wi.z; }
    return appear_spectrum_splat(appear__dielectric_core(m, wo, wi, e, &pdf));
}
/* pdf(wi) of appear_dielectric_sample (both lobes; see the core). */
APPEAR_FUNC float appear_dielectric_pdf(const appear_dielectric *m, appear_vec3 wo, appear_vec3 wi)
{
    float pdf, e;
    int ok = m->valid && !m->smooth && appear_is_unit(wo) && appear_is_unit(wi) && wo.z != 0.0f && wi.z != 0.0f;
    if (!ok) return 0.0f;
    e = wo.z > 0.0f ? m->eta : 1.0f / m->eta;
    if (wo.z < 0.0f) { wo.z = -wo.z; wi.z = -wi.z; }
    (void)appear__dielectric_core(m, wo, wi, e, &pdf);
    return pdf;
}
/* Samples a microfacet normal m (visible normals, or full D), then picks
   reflection when uc < F(wo.m, e) (always under total internal
   reflection), transmission otherwise [Walter07, Sec. 5.3]; the refracted
   direction wi = (-wo + (c - g) m) / e with c = wo.m, g = e cos_t, and
   c - g = (1 - e^2)/(c + g) (no cancellation as e -> 1). Fails when the
   scattered direction lands on the wrong side of the macro surface.
   s->eta = e (n(wi side) / n(wo side)) for a transmission, 1 for a
   reflection. Smooth limit (and eta == 1): delta reflection with
   probability F(|wo.z|) (weight 1) or delta transmission with probability
   1 - F (weight 1/e^2, radiance convention). */
APPEAR_FUNC int appear_dielectric_sample(const appear_dielectric *m, appear_vec3 wo, float uc, float u1, float u2,
                                         appear_bsdf_sample *s)
{
    float sg, e, fr, c, ct, pdf, f, cost;
    appear_vec3 h, wi;
    int refl;
    if (!(m->valid && appear_is_unit(wo) && wo.z != 0.0f && appear__isfinite(u1) && appear__isfinite(u2) && uc == uc))
        return appear__bsdf_fail(s);
    sg = wo.z < 0.0f ? -1.0f : 1.0f;
    e = wo.z > 0.0f ? m->eta : 1.0f / m->eta;
    wo.z = APPEAR_FABSF(wo.z);
    h = m->smooth ? appear_vec3_make(0.0f, 0.0f, 1.0f) : appear__mf_sample_m(&m->d, wo, u1, u2, 0);
    c = appear_dot(wo, h);
    if (!(h.z > 0.0f && c > 0.0f)) return appear__bsdf_fail(s);
    fr = appear__fresnel_dielectric_full(c, e, &cost);
    refl = uc < fr || fr >= 1.0f;
    if (refl) {
        wi = appear__reflect(wo, h);
    } else {
        float g = cost * e;
        wi = appear_scale(appear_add(appear_neg(wo), appear_scale(h, (1.0f - e) * (1.0f + e) / (c + g))), 1.0f / e);
    }
    if (m->smooth) {
        ct = APPEAR_FABSF(wi.z);
        if (!(ct > 0.0f)) return appear__bsdf_fail(s);
        s->pdf = refl ? fr : 1.0f - fr;
        s->weight = appear_spectrum_splat(refl ? 1.0f : 1.0f / (e * e));
        s->f = appear_spectrum_splat(refl ? fr / ct : (1.0f - fr) / (e * e * ct));
        s->flags = (unsigned)((refl ? APPEAR_LOBE_REFLECTION : APPEAR_LOBE_TRANSMISSION) | APPEAR_LOBE_SPECULAR);
    } else {
        if (!(refl ? wi.z > 0.0f : wi.z < 0.0f)) return appear__bsdf_fail(s);
        wi = appear_normalize(wi);
        f = appear__dielectric_core(m, wo, wi, e, &pdf);
        if (!(pdf > 0.0f)) return appear__bsdf_fail(s);
        s->pdf = pdf;
        s->f = appear_spectrum_splat(f);
        s->weight = appear_spectrum_splat(appear__finite_or_zero(f * APPEAR_FABSF(wi.z) / pdf));
        s->flags = (unsigned)((refl ? APPEAR_LOBE_REFLECTION : APPEAR_LOBE_TRANSMISSION) | APPEAR_LOBE_GLOSSY);
    }
    s->wi = appear_vec3_make(wi.x, wi.y, sg * wi.z);
    s->eta = refl ? 1.0f : e;
    return 1;
}

#endif /* APPEAR_NO_MICROFACET */
/* END SECTION microfacet */

/* ======================================================================== */
/* SECTION multiple scattering, energy compensation, thin film              */
/* ======================================================================== */
/*
   Multiple scattering, energy compensation and thin-film iridescence.

   References (cited at each function):
   [BB17]   Belcour & Barla, A Practical Extension to Microfacet Theory for
            the Modeling of Varying Iridescence, ACM TOG 36(4) 2017, and
            its supplemental material (Gaussian fit of the CIE 1931 XYZ
            matching functions in wavenumber).
   [Heitz16] Heitz, Hanika, d'Eon, Dachsbacher, Multiple-Scattering
            Microfacet BSDFs with the Smith Model, ACM TOG 35(4) 2016.
   [KC17]   Kulla & Conty, Revisiting Physically Based Shading at
            Imageworks, SIGGRAPH 2017 course (energy compensation).
   [Turquin19] Turquin, Practical multiple scattering compensation for
            microfacet models, Tech. report 2019 (albedo scaling).
   [BW99]   Born & Wolf, Principles of Optics, 7th ed., Sec. 1.5, 1.6
            (Airy summation), 14.2 (absorbing media).
*/

/* ======================================================================== */
/* Thin-film iridescence [BB17]                    (APPEAR_NO_THINFILM)      */
/* ======================================================================== */
/*
   A film of real index n2 and thickness d (nm) on a base of complex index
   n3 = eta + i k (k = 0: dielectric), lit from a medium of index 1.
   All indices are relative to the outside medium. cos_i is the cosine of
   the incident angle on the film (for a microfacet model: wo.h).

   appear_thinfilm_airy()      exact reflectance at one wavelength
                               (spectral and hero-wavelength renderers).
   appear_thinfilm_rgb()       [BB17, Sec. 4] Fourier-space evaluation of
                               the reflectance integrated against linear
                               sRGB (Rec. 709) sensitivities, white point
                               E (a constant spectral reflectance R maps
                               to RGB (R, R, R)). The base's eta, k are
                               taken per channel and constant over the
                               channel's band.
   appear_thinfilm_F()         either of the two, per appear_thinfilm.
   appear_thinfilm_conductor_* a rough conductor whose Fresnel term is the
                               film (eval, pdf, sample).
*/
#ifndef APPEAR_NO_THINFILM

#ifndef APPEAR_THINFILM_TERMS
#define APPEAR_THINFILM_TERMS 8 /* Airy orders summed exactly in _rgb; the rest in closed form */
#endif

typedef struct { float re, im; } appear__cpx;
APPEAR_FUNC appear__cpx appear__c(float re, float im) { appear__cpx z; z.re = re; z.im = im; return z; }
APPEAR_FUNC appear__cpx appear__cmul(appear__cpx a, appear__cpx b)
{ return appear__c(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re); }
APPEAR_FUNC appear__cpx appear__cadd(appear__cpx a, appear__cpx b) { return appear__c(a.re + b.re, a.im + b.im); }
APPEAR_FUNC appear__cpx appear__csub(appear__cpx a, appear__cpx b) { return appear__c(a.re - b.re, a.im - b.im); }
APPEAR_FUNC float appear__cabs2(appear__cpx a) { return a.re * a.re + a.im * a.im; }
/* a / b; 0 when b = 0 */
APPEAR_FUNC appear__cpx appear__cdiv(appear__cpx a, appear__cpx b)
{
    float d = appear__cabs2(b), s = d > 0.0f ? 1.0f / d : 0.0f;
    return appear__c((a.re * b.re + a.im * b.im) * s, (a.im * b.re - a.re * b.im) * s);
}
/* Principal square root (Re >= 0; Im >= 0 when Im(a) >= 0), without
   cancellation: the larger of |Re|, |Im| of the root from (|a| + |Re a|)/2. */
APPEAR_FUNC appear__cpx appear__csqrt(appear__cpx a)
{
    float m = APPEAR_SQRTF(appear__cabs2(a));
    float t = APPEAR_SQRTF(0.5f * (m + APPEAR_FABSF(a.re)));
    float o = t > 0.0f ? 0.5f * a.im / t : 0.0f;
    return a.re >= 0.0f ? appear__c(t, o) : appear__c(APPEAR_FABSF(o), a.im < 0.0f ? -t : t);
}

/* Amplitude reflection coefficients of the two interfaces, s and p
   polarisation [BW99, Sec. 1.5.2 Eq. 21; Sec. 14.2 for the complex base],
   sign convention r_p = (n_t cos_i - n_i cos_t) / (n_t cos_i + n_i cos_t)
   so that r21 = -r12 (Stokes). With Snell n2 sin2 = sin1 = s1 the base
   term is n3 cos3 = sqrt(n3^2 - s1^2) (principal root: Im >= 0, the
   evanescent / absorbed wave; also total internal reflection in the base
   for a real n3 < n2). Returns 0 and R = 1 under total internal
   reflection at the film (n2 < 1). c2 = cos theta in the film. */
APPEAR_FUNC int appear__thinfilm_interfaces(float c1, float n2, float n3, float k3, float *r12s, float *r12p,
                                            appear__cpx *r23s, appear__cpx *r23p, float *c2)
{
    float s1s = (1.0f - c1) * (1.0f + c1);
    float c2s = 1.0f - s1s / (n2 * n2);
    appear__cpx n3c = appear__c(n3, k3), n3sq = appear__cmul(n3c, n3c), q, a, b;
    float n2c2;
    *c2 = appear__safe_sqrt(c2s);
    n2c2 = n2 * *c2;
    *r12s = (c1 - n2c2) / (c1 + n2c2);
    *r12p = (n2 * c1 - *c2) / (n2 * c1 + *c2);
    q = appear__csqrt(appear__c(n3sq.re - s1s, n3sq.im));
    *r23s = appear__cdiv(appear__c(n2c2 - q.re, -q.im), appear__c(n2c2 + q.re, q.im));
    a = appear__c(n3sq.re * *c2 - n2 * q.re, n3sq.im * *c2 - n2 * q.im);
    b = appear__c(n3sq.re * *c2 + n2 * q.re, n3sq.im * *c2 + n2 * q.im);
    *r23p = appear__cdiv(a, b);
    return c2s > 0.0f && c1 > 0.0f;
}

/* Validated, clamped parameters shared by the film functions. */
APPEAR_FUNC int appear__thinfilm_args(float *c1, float *n2, float *d, float *n3, float *k3)
{
    int ok = *n2 > 0.0f && *n2 <= 1e3f && *d >= 0.0f && *d <= 1e5f && *n3 > 0.0f && *n3 <= 1e6f && *k3 >= 0.0f &&
             *k3 <= 1e6f && *c1 == *c1;
    *c1 = appear__clamp(APPEAR_FABSF(*c1), 0.0f, 1.0f);
    if (!ok) { *n2 = 1.0f; *d = 0.0f; *n3 = 1.0f; *k3 = 0.0f; }
    return ok;
}

/* Exact reflectance of the film at wavelength lambda_nm [BW99, Sec. 1.6.4,
   Eq. 57 (Airy summation)], per polarisation
       r = (r12 + r23 e^{i Delta}) / (1 + r12 r23 e^{i Delta}),
       Delta = 2 pi OPD / lambda,   OPD = 2 n2 d cos theta2,
   R = (|r_s|^2 + |r_p|^2) / 2 (unpolarised light). d = 0 gives exactly the
   Fresnel reflectance of the bare base (r = (r12 + r23)/(1 + r12 r23) =
   r13). Total internal reflection at the film: 1. cos_i = 0: 1.
   Invalid (film index or thickness, base index out of (0, 1e6], d out of
   [0, 1e5] nm, k < 0, NaN, lambda <= 0): 0. */
APPEAR_FUNC float appear_thinfilm_airy(float cos_i, float lambda_nm, float eta_film, float thickness_nm,
                                       float eta_base, float k_base)
{
    float r12s, r12p, c2, sp, cp, res = 1.0f;
    appear__cpx r23s, r23p, e, num, den;
    int ok = appear__thinfilm_args(&cos_i, &eta_film, &thickness_nm, &eta_base, &k_base) && lambda_nm > 0.0f &&
             lambda_nm <= 1e6f;
    int notir = appear__thinfilm_interfaces(cos_i, eta_film, eta_base, k_base, &r12s, &r12p, &r23s, &r23p, &c2);
    /* phase in turns: OPD / lambda */
    appear_sincos_2pi(ok ? 2.0f * eta_film * thickness_nm * c2 / lambda_nm : 0.0f, &sp, &cp);
    e = appear__c(cp, sp);
    {
        appear__cpx t = appear__cmul(r23s, e);
        num = appear__c(r12s + t.re, t.im);
        den = appear__c(1.0f + r12s * t.re, r12s * t.im);
        res = appear__cabs2(appear__cdiv(num, den));
        t = appear__cmul(r23p, e);
        num = appear__c(r12p + t.re, t.im);
        den = appear__c(1.0f + r12p * t.re, r12p * t.im);
        res = 0.5f * (res + appear__cabs2(appear__cdiv(num, den)));
    }
    res = notir ? appear__clamp(appear__finite_or_zero(res), 0.0f, 1.0f) : 1.0f;
    return ok ? res : 0.0f;
}

/* Channel weights of the four Gaussian lobes of the CIE 1931 XYZ matching
   functions in wavenumber nu (1/nm) [BB17, supplemental]:
       lobe_j(nu) = a_j exp(-(nu - mu_j)^2 / (4 v_j)),
   x = lobes 0 + 3, y = lobe 1, z = lobe 2, with
   a = (5.4856e-13, 4.4201e-13, 5.2481e-13, 9.7470e-14),
   mu = (1.6810e-3, 1.7953e-3, 2.2084e-3, 2.2399e-3) /nm,
   v = (4.3278e-9, 9.3046e-9, 6.6121e-9, 4.5282e-9) /nm^2.
   Linear sRGB sensitivity s_c = sum_k M_ck xyz_k (M = XYZ -> Rec. 709,
   IEC 61966-2-1) normalised to unit integral: W_cj = M_c,k(j) a_j
   sqrt(4 pi v_j) / sum_j' (same). tests/test_multiscatter.c recomputes
   these in double. */
APPEAR_CONST float appear__tf_w[3][4] = {
    { 2.275931014e+00f, -1.275526329e+00f, -4.140566885e-01f, 4.136520038e-01f },
    { -8.652895013e-01f, 1.978686592e+00f, 4.386986255e-02f, -1.572669531e-01f },
    { 5.176554571e-02f, -2.242516572e-01f, 1.163077688e+00f, 9.408423006e-03f } };
APPEAR_CONST float appear__tf_mu[4] = { 1.6810e-3f, 1.7953e-3f, 2.2084e-3f, 2.2399e-3f };
/* 4 pi^2 v_j */
APPEAR_CONST float appear__tf_v4[4] = { 1.708546957e-07f, 3.673308844e-07f, 2.610352450e-07f, 1.787661706e-07f };

/* Fourier-space RGB reflectance of the film [BB17, Sec. 4, Eq. 9-12],
   derived here for the stated sensitivities. With r21 = -r12 real,
   t12 t21 = 1 - R12 = T, z = r21 r23 = rho e^{i phi2}, the Airy intensity
   per polarisation is the Fourier series in Delta = 2 pi nu OPD
       R(nu) = C0 + 2 Re sum_{m>=1} Cm z^m e^{i m Delta},
       C0 = R12 + T^2 R23 / (1 - R12 R23),  Cm = -T (1 - R23) / (1 - R12 R23)
   (expand |r12 - (T/r12) x|^2, x = sum_k (z e^{i Delta})^k). Integrated
   against s_c (normalised):  R_c = C0 + 2 Re sum_m Cm z^m S_c(m OPD) with
       S_c(D) = sum_j W_cj exp(-4 pi^2 v_j D^2) e^{2 pi i mu_j D}
   (Fourier transform of a Gaussian). Orders 1..APPEAR_THINFILM_TERMS are
   summed exactly; the rest in closed form, per lobe, after bounding
   m^2 by its tangent at M+1 (a geometric series in m):
       sum_{m>M} z^m e^{-q m^2} e^{i m th} ~ e^{-q (M+1)^2} (z e^{i th})^(M+1)
                                            / (1 - z e^{i th} e^{-2 q (M+1)}),
   q = 4 pi^2 v_j D^2, th = 2 pi mu_j D: exact at D = 0, so the zero-
   thickness limit is exactly the bare base's Fresnel (to float rounding),
   and the neglected factor e^{-q (m-M-1)^2} matters only where the tail
   is already small.
   The only approximations are that tail and the base's (eta, k) being
   constant within a channel; tests measure it against the exact spectral
   integral. Result clamped to [0, 1] per channel. Same validation as
   appear_thinfilm_airy (invalid: 0). */
APPEAR_FUNC appear_spectrum appear_thinfilm_rgb(float cos_i, float eta_film, float thickness_nm, appear_spectrum eta_base,
                                                appear_spectrum k_base)
{
    appear_spectrum out;
    appear__cpx gj[4], gstep[4], sc[3][APPEAR_THINFILM_TERMS + 1];
    float opd, ej[4], estep[4], e2q[4], tstep[4];
    int i, j, m, okall = 1;
    {
        float n3 = eta_base.v[0], k3 = k_base.v[0], c = cos_i;
        okall = appear__thinfilm_args(&c, &eta_film, &thickness_nm, &n3, &k3);
        cos_i = c;
    }
    {
        float s1s = (1.0f - cos_i) * (1.0f + cos_i);
        float c2 = appear__safe_sqrt(1.0f - s1s / (eta_film * eta_film));
        opd = 2.0f * eta_film * thickness_nm * c2;
    }
    /* S_c(m OPD) for m = 1..M(+1), by recurrences on each lobe:
       e^{2 pi i mu m D} = (e^{2 pi i mu D})^m,
       exp(-q m^2) = exp(-q (m-1)^2) exp(-q (2m - 1)). */
    for (j = 0; j < 4; ++j) {
        float sp, cp, q = appear__tf_v4[j] * opd * opd;
        appear_sincos_2pi(appear__tf_mu[j] * opd, &sp, &cp);
        gstep[j] = appear__c(cp, sp);
        gj[j] = appear__c(1.0f, 0.0f);
        ej[j] = 1.0f;
        estep[j] = appear__exp(-q);              /* exp(-q (2m-1)) at m = 1 */
        e2q[j] = estep[j] * estep[j];            /* exp(-2q) */
    }
    for (m = 1; m <= APPEAR_THINFILM_TERMS + 1; ++m) {
        for (i = 0; i < 3; ++i) sc[i][m - 1] = appear__c(0.0f, 0.0f);
        for (j = 0; j < 4; ++j) {
            gj[j] = appear__cmul(gj[j], gstep[j]);
            ej[j] *= estep[j];                   /* exp(-q m^2) */
            estep[j] *= e2q[j];                  /* exp(-q (2m+1)) */
            for (i = 0; i < 3; ++i) {
                float w = appear__tf_w[i][j] * ej[j];
                sc[i][m - 1] = appear__c(sc[i][m - 1].re + w * gj[j].re, sc[i][m - 1].im + w * gj[j].im);
            }
        }
    }
    for (j = 0; j < 4; ++j) tstep[j] = appear__exp(-2.0f * (float)(APPEAR_THINFILM_TERMS + 1) * appear__tf_v4[j] * opd * opd);
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) {
        int ch = i % 3, pol;
        float n3 = eta_base.v[i], k3 = k_base.v[i], c = cos_i, n2 = eta_film, d = thickness_nm;
        float r12[2], c2, acc = 0.0f;
        appear__cpx r23[2];
        int ok = appear__thinfilm_args(&c, &n2, &d, &n3, &k3) && okall;
        int notir = appear__thinfilm_interfaces(c, n2, n3, k3, &r12[0], &r12[1], &r23[0], &r23[1], &c2);
        for (pol = 0; pol < 2; ++pol) {
            float R12 = r12[pol] * r12[pol], R23 = appear__cabs2(r23[pol]), T = 1.0f - R12;
            float den = 1.0f - R12 * R23;
            float C0 = den > 0.0f ? R12 + T * T * R23 / den : 1.0f;
            float Cm = den > 0.0f ? -T * (1.0f - R23) / den : 0.0f;
            appear__cpx z = appear__c(-r12[pol] * r23[pol].re, -r12[pol] * r23[pol].im), zm = z;
            float sum = 0.0f;
            for (m = 1; m <= APPEAR_THINFILM_TERMS; ++m) {
                appear__cpx t = appear__cmul(zm, sc[ch][m - 1]);
                sum += t.re;
                zm = appear__cmul(zm, z);
            }
            /* tail, per lobe j, with m^2 >= (M+1)^2 + 2 (M+1)(m-M-1) (tangent at M+1):
               sum_{m>M} z^m W_j e^{-q m^2} e^{i m th} ~ W_j e^{-q (M+1)^2} (z e^{i th})^(M+1)
               / (1 - z e^{i th} e^{-2 q (M+1)}); exact at D = 0 */
            for (j = 0; j < 4; ++j) {
                appear__cpx zt = appear__cmul(z, gstep[j]), num = zm, q;
                num = appear__cmul(zm, gj[j]);  /* z^(M+1) e^{i (M+1) th}: zm = z^(M+1), gj = e^{i (M+1) th} */
                q = appear__cdiv(num, appear__c(1.0f - zt.re * tstep[j], -zt.im * tstep[j]));
                sum += appear__tf_w[ch][j] * ej[j] * q.re;
            }
            acc += C0 + 2.0f * Cm * sum;
        }
        acc = notir ? appear__clamp(appear__finite_or_zero(0.5f * acc), 0.0f, 1.0f) : 1.0f;
        out.v[i] = ok ? acc : 0.0f;
    }
    return out;
}

/* A film description usable as a Fresnel term. */
typedef struct appear_thinfilm {
    float           eta_film, thickness_nm;
    appear_spectrum eta_base, k_base;
    appear_spectrum lambda_nm; /* spectral mode: wavelength of each sample */
    int             spectral;  /* 1: exact per wavelength, 0: Fourier RGB */
    int             valid;
} appear_thinfilm;

APPEAR_FUNC appear_thinfilm appear__thinfilm_check(appear_thinfilm t)
{
    int i;
    t.valid = t.eta_film > 0.0f && t.eta_film <= 1e3f && t.thickness_nm >= 0.0f && t.thickness_nm <= 1e5f;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i)
        t.valid &= t.eta_base.v[i] > 0.0f && t.eta_base.v[i] <= 1e6f && t.k_base.v[i] >= 0.0f &&
                   t.k_base.v[i] <= 1e6f && (!t.spectral || (t.lambda_nm.v[i] > 0.0f && t.lambda_nm.v[i] <= 1e6f));
    return t;
}
/* Reference: film index eta_film in (0, 1e3], thickness in [0, 1e5] nm,
   base index eta in (0, 1e6], k in [0, 1e6] per channel (k = 0 for a
   dielectric base, e.g. 1.5; relative to the outside medium). Invalid ->
   valid = 0 and appear_thinfilm_F returns 0. */
APPEAR_FUNC appear_thinfilm appear_thinfilm_make_rgb(float eta_film, float thickness_nm, appear_spectrum eta_base,
                                                     appear_spectrum k_base)
{
    appear_thinfilm t;
    t.eta_film = eta_film; t.thickness_nm = thickness_nm; t.eta_base = eta_base; t.k_base = k_base;
    t.lambda_nm = appear_spectrum_splat(550.0f); t.spectral = 0;
    return appear__thinfilm_check(t);
}
/* Spectral mode: channel i is the wavelength lambda_nm.v[i] (hero
   wavelengths), eta_base / k_base given at those wavelengths. */
APPEAR_FUNC appear_thinfilm appear_thinfilm_make_spectral(float eta_film, float thickness_nm, appear_spectrum eta_base,
                                                          appear_spectrum k_base, appear_spectrum lambda_nm)
{
    appear_thinfilm t;
    t.eta_film = eta_film; t.thickness_nm = thickness_nm; t.eta_base = eta_base; t.k_base = k_base;
    t.lambda_nm = lambda_nm; t.spectral = 1;
    return appear__thinfilm_check(t);
}
/* Reflectance of the film at incidence cos_i (|cos_i| is used), per channel. */
APPEAR_FUNC appear_spectrum appear_thinfilm_F(const appear_thinfilm *t, float cos_i)
{
    appear_spectrum r;
    int i;
    if (!t->valid) return appear_spectrum_splat(0.0f);
    if (!t->spectral) return appear_thinfilm_rgb(cos_i, t->eta_film, t->thickness_nm, t->eta_base, t->k_base);
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i)
        r.v[i] = appear_thinfilm_airy(cos_i, t->lambda_nm.v[i], t->eta_film, t->thickness_nm, t->eta_base.v[i], t->k_base.v[i]);
    return r;
}

#ifndef APPEAR_NO_MICROFACET
/* Rough conductor (or any opaque base) with a thin film: the microfacet
   BRDF of appear_conductor with F(wo.h) replaced by appear_thinfilm_F
   [BB17, Sec. 3: the film is locally flat on each microfacet]. The
   conductor's own eta/k are ignored; the film's base is the base. pdf and
   sampling are those of appear_conductor (they do not depend on F). */
typedef struct appear_thinfilm_conductor {
    appear_conductor c; /* distribution and sampling strategy */
    appear_thinfilm  tf;
    int valid;
} appear_thinfilm_conductor;

APPEAR_FUNC appear_thinfilm_conductor appear_thinfilm_conductor_make(appear_microfacet d, appear_thinfilm tf)
{
    appear_thinfilm_conductor m;
    m.c = appear_conductor_make(d, appear_spectrum_splat(1.0f), appear_spectrum_splat(0.0f));
    m.tf = tf;
    m.valid = m.c.valid && tf.valid;
    m.c.valid = m.valid;
    return m;
}
APPEAR_FUNC appear_spectrum appear_thinfilm_conductor_eval(const appear_thinfilm_conductor *m, appear_vec3 wo, appear_vec3 wi)
{
    float pdf, ch, f;
    int ok = m->valid && !m->c.d.smooth && appear_is_unit(wo) && appear_is_unit(wi) && wo.z * wi.z > 0.0f;
    if (!ok) return appear_spectrum_splat(0.0f);
    if (wo.z < 0.0f) { wo.z = -wo.z; wi.z = -wi.z; }
    f = appear__conductor_core(&m->c, wo, wi, &pdf, &ch);
    return appear_spectrum_scale(appear_thinfilm_F(&m->tf, ch), f);
}
APPEAR_FUNC float appear_thinfilm_conductor_pdf(const appear_thinfilm_conductor *m, appear_vec3 wo, appear_vec3 wi)
{ return appear_conductor_pdf(&m->c, wo, wi); }
/* As appear_conductor_sample; f and weight carry the film's F. */
APPEAR_FUNC int appear_thinfilm_conductor_sample(const appear_thinfilm_conductor *m, appear_vec3 wo, float uc, float u1,
                                                 float u2, appear_bsdf_sample *s)
{
    appear_spectrum F;
    int i;
    if (!appear_conductor_sample(&m->c, wo, uc, u1, u2, s)) return 0;
    /* the conductor's F with eta = 1, k = 0 is 0: recompute f from the film */
    if (s->flags & APPEAR_LOBE_SPECULAR) {
        F = appear_thinfilm_F(&m->tf, wo.z);
        s->weight = F;
        s->f = appear_spectrum_scale(F, 1.0f / APPEAR_FABSF(wo.z));
    } else {
        s->f = appear_thinfilm_conductor_eval(m, wo, s->wi);
        for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i)
            s->weight.v[i] = appear__finite_or_zero(s->f.v[i] * APPEAR_FABSF(s->wi.z) / s->pdf);
    }
    return 1;
}
#endif /* APPEAR_NO_MICROFACET */

#endif /* APPEAR_NO_THINFILM */
/* END SECTION multiscatter */

/* ======================================================================== */
/* SECTION media (APPEAR_NO_MEDIA)                                          */
/* ======================================================================== */
/* END SECTION media */

/* ======================================================================== */
/* SECTION flakes and more phase functions (APPEAR_NO_FLAKES)               */
/* ======================================================================== */
/* END SECTION flakes */

/* ======================================================================== */
/* SECTION batch (structure-of-arrays entry points)                         */
/* ======================================================================== */
/* END SECTION batch */

#ifdef __cplusplus
}
#endif

#endif /* APPEAR_H */

/* ======================================================================== */
/* Implementation (host-only code; define APPEAR_IMPLEMENTATION in one TU)  */
/* ======================================================================== */
#ifdef APPEAR_IMPLEMENTATION
#ifndef APPEAR_IMPLEMENTATION_DONE
#define APPEAR_IMPLEMENTATION_DONE

/* Host-side version query, so a program can check which header it linked. */
int appear_version(void);
int appear_version(void) { return APPEAR_VERSION; }

#endif /* APPEAR_IMPLEMENTATION_DONE */
#endif /* APPEAR_IMPLEMENTATION */

/*
   VERSION HISTORY
   0.1  (2026-11-22) frames, special functions, Lambert, isotropic and
        Henyey-Greenstein phase functions.

   ---------------------------------------------------------------------------
   LICENSE: choose whichever you prefer.
   A - MIT License. Copyright (c) 2026 the appear.h authors. Permission is
       hereby granted, free of charge, to any person obtaining a copy of this
       software and associated documentation files (the "Software"), to deal in
       the Software without restriction, including without limitation the
       rights to use, copy, modify, merge, publish, distribute, sublicense,
       and/or sell copies of the Software, and to permit persons to whom the
       Software is furnished to do so, subject to the following conditions:
       The above copyright notice and this permission notice shall be included
       in all copies or substantial portions of the Software. THE SOFTWARE IS
       PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND.
   B - Public Domain (www.unlicense.org). Anyone is free to copy, modify,
       publish, use, compile, sell, or distribute this software, for any
       purpose, commercial or non-commercial, and by any means.
   ---------------------------------------------------------------------------
*/
