/* tests/robust.c - the robustness contract under any build flags.
 *
 * A standalone program (compiler and libm only) that calls every public
 * eval / pdf / sample function, building block and estimator of appear.h
 * with adversarial inputs and checks the contract of the header's
 * ROBUSTNESS CONTRACT block after each call:
 *   - every value and pdf is finite and >= 0;
 *   - a failed sample is zeroed (flags 0, pdf 0, weight 0);
 *   - a successful sample has a finite unit wi, pdf > 0, finite f and
 *     weight >= 0, and (non-delta lobes) pdf(wo, wi) > 0 and eval finite
 *     at its own wi: a sample that eval() and pdf() call impossible is a
 *     side-test that underflowed;
 *   - a tracker terminates within its lookup budget with a finite T.
 * It is built by `make test` with gcc -O2, gcc -O3 -ffast-math and
 * clang -O3 -ffast-math (FTZ/DAZ on: -ffast-math links crtfastmath). The
 * checks look at the BITS of the results (an integer view of each float),
 * never at float comparisons, which -ffast-math may assume away.
 *
 * Inputs: raw bit patterns, NaN, +-Inf, denormals, +-0, values one ulp
 * from 0 and 1, grazing directions down to denormal cosines, exactly
 * tangent directions, wo = wi and wo = -wi, unnormalised vectors.
 *
 * Usage: robust [n_per_group [family...]] (default 200000, every family;
 * the names are rb_families' below). Prints one line per group with its
 * first violation and ends with "N passed, M failed".
 */
#include "../appear.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- bits, never float comparisons ---- */
static uint32_t rb_bits(float x) { uint32_t u; memcpy(&u, &x, 4); return u; }
static float rb_float(uint32_t u) { float x; memcpy(&x, &u, 4); return x; }
static int rb_finite(float x) { return (rb_bits(x) & 0x7f800000u) != 0x7f800000u; }
/* finite and >= 0 (-0 included) */
static int rb_value(float x) { uint32_t b = rb_bits(x); return b < 0x7f800000u || b == 0x80000000u; }
/* finite and > 0 */
static int rb_positive(float x) { uint32_t b = rb_bits(x); return b > 0u && b < 0x7f800000u; }
static int rb_zero(float x) { return (rb_bits(x) & 0x7fffffffu) == 0u; }
static int rb_spec_value(appear_spectrum s)
{
    int i, ok = 1;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) ok &= rb_value(s.v[i]);
    return ok;
}
static int rb_spec_zero(appear_spectrum s)
{
    int i, ok = 1;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) ok &= rb_zero(s.v[i]);
    return ok;
}
static int rb_vec_finite(appear_vec3 v) { return rb_finite(v.x) && rb_finite(v.y) && rb_finite(v.z); }
static int rb_vec_zero(appear_vec3 v) { return rb_zero(v.x) && rb_zero(v.y) && rb_zero(v.z); }
/* unit within the header's tolerance; |d| compared as bits */
static int rb_unit(appear_vec3 v)
{
    float d;
    if (!rb_vec_finite(v)) return 0;
    d = v.x * v.x + v.y * v.y + v.z * v.z - 1.0f;
    return (rb_bits(d) & 0x7fffffffu) <= rb_bits(APPEAR_UNIT_TOLERANCE);
}

/* ---- groups: count calls, violations, keep the first message ---- */
typedef struct { const char *name; long calls, bad; char first[512]; } rb_group;
static rb_group *g_cur;
static long g_soft; /* -ffast-math: samples whose pdf() is 0 (see rb_bsdf_check) */
static void rb_fail(const char *fmt, ...);
#include <stdarg.h>
/* the inputs of the current call, printed with its first violation */
static float g_in[16];
static int g_nin;
static void rb_inputs(int n, const float *v) { g_nin = n; memcpy(g_in, v, sizeof(float) * (size_t)n); }
#define RB_IN(...) do { const float in_[] = { __VA_ARGS__ }; rb_inputs((int)(sizeof in_ / sizeof in_[0]), in_); } while (0)
static void rb_fail(const char *fmt, ...)
{
    if (g_cur->bad++ == 0) {
        va_list ap;
        int k, len;
        va_start(ap, fmt);
        len = vsnprintf(g_cur->first, sizeof g_cur->first, fmt, ap);
        va_end(ap);
        for (k = 0; k < g_nin && len > 0 && len < (int)sizeof g_cur->first - 20; ++k)
            len += snprintf(g_cur->first + len, sizeof g_cur->first - (size_t)len, "%s%a", k ? " " : " | in: ",
                            (double)g_in[k]);
    }
}
#define RB_CHECK(cond, ...) do { ++g_cur->calls; if (!(cond)) rb_fail(__VA_ARGS__); } while (0)
/* a consistency between two computations of one number (sample record
   against eval()/pdf(), batch against scalar): exact in IEEE builds up to
   the tolerance; -ffast-math computes one expression differently in
   different inlining contexts, so there it is counted (g_soft), not failed */
static long g_soft_consist;
/* a lobe sharper than alpha 1e-3: eval() recomputes the half vector from
   (wo, wi), whose rounding the exponent -tan^2/alpha^2 amplifies by up to
   1/alpha^2 = 1e8 (Ward at alpha 1e-4: 45% under clang's FMA contraction),
   so its record-vs-eval consistency is counted, not failed, too */
static int g_sharp;
static char g_soft_first[400]; /* the first counted difference, printed with the count */
#define RB_SOFT(...) do { if (g_soft_consist++ == 0) snprintf(g_soft_first, sizeof g_soft_first, __VA_ARGS__); } while (0)
#ifdef __FAST_MATH__
#define RB_CONSIST(cond, ...) do { ++g_cur->calls; if (!(cond)) RB_SOFT(__VA_ARGS__); } while (0)
#else
#define RB_CONSIST(cond, ...) do { if (g_sharp) { ++g_cur->calls; if (!(cond)) RB_SOFT(__VA_ARGS__); } \
                                   else RB_CHECK(cond, __VA_ARGS__); } while (0)
#endif
static int rb_sharp(float ax, float ay) { return !(ax >= 1e-3f && ay >= 1e-3f); }
#include <math.h>
/* |a - b| <= tol max(|a|, |b|), or both below 1e-30 (double: no rounding of its own) */
static int rb_close(double a, double b, double tol)
{
    double d = fabs(a - b), m = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
    return d <= tol * m || m < 1e-30;
}

/* ---- adversarial inputs (splitmix64; under RB_FUZZ the fuzzer's bytes first) ---- */
static uint64_t g_s = 12345;
#ifdef RB_FUZZ
static const uint8_t *g_fz; /* tests/fuzz/fuzz.c: every choice below comes from these bytes */
static size_t g_fzn, g_fzi;
#endif
static uint64_t rb_next(void)
{
    uint64_t z;
#ifdef RB_FUZZ
    if (g_fzi + 8 <= g_fzn) { memcpy(&z, g_fz + g_fzi, 8); g_fzi += 8; return z; }
#endif
    z = (g_s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static float rb_uniform(void) { return (float)(rb_next() >> 40) * (1.0f / 16777216.0f); }
static uint32_t rb_pick(uint32_t n) { return (uint32_t)(rb_next() % n); }
/* NaN, +-Inf, denormals, +-0, 1 ulp around 0 and 1, huge, raw bit patterns */
static float rb_adv(void)
{
    static const uint32_t special[] = {
        0x00000000u, 0x80000000u, 0x3f800000u, 0xbf800000u, 0x00000001u, 0x80000001u, 0x007fffffu,
        0x00800000u, 0x3f7fffffu, 0x3f800001u, 0x7f7fffffu, 0xff7fffffu, 0x7f800000u, 0xff800000u,
        0x7fc00000u, 0xffc00000u, 0x7f800001u, 0x33800000u, 0x0da24260u, 0x40000000u, 0x3f000000u };
    uint32_t k = rb_pick(8);
    if (k <= 2) return rb_float(special[rb_pick(sizeof special / sizeof special[0])]);
    if (k == 3) return rb_float((uint32_t)rb_next());
    return 4.0f * rb_uniform() - 2.0f;
}
/* random numbers: mostly [0,1), plus 0, 1, 1-ulp, denormal, and bad ones */
static float rb_u(void)
{
    /* 1 + 1 ulp and -denormal: just outside [0, 1], where a range guard written
       as a float compare is folded by -ffast-math (issue 34, class 3) */
    static const uint32_t special[] = { 0x00000000u, 0x80000000u, 0x3f800000u, 0x3f7fffffu, 0x00000001u,
                                        0x00800000u, 0x33800000u, 0x3f000000u, 0x3f800001u, 0x80000001u };
    uint32_t k = rb_pick(16);
    if (k < 10) return rb_uniform();
    if (k < 14) return rb_float(special[rb_pick(sizeof special / sizeof special[0])]);
    return rb_adv();
}
static appear_vec3 rb_sphere(void)
{
    float z = 1.0f - 2.0f * rb_uniform(), p = 6.2831853f * rb_uniform();
    float s = z * z < 1.0f ? sqrtf(1.0f - z * z) : 0.0f;
    return appear_vec3_make(s * cosf(p), s * sinf(p), z);
}
/* grazing: z down to denormals and exactly +-0, xy renormalised */
static appear_vec3 rb_grazing(void)
{
    static const uint32_t zs[] = { 0x00000000u, 0x80000000u, 0x00000001u, 0x80000001u, 0x007fffffu,
                                   0x00800000u, 0x80800000u, 0x0da24260u, 0x358637bdu, 0xb58637bdu,
                                   0x38d1b717u, 0x1e3ce508u,
                                   /* cosines 1e-22 .. 8e-28: squares and products far below
                                      FLT_MIN, exponents of 1/alpha^2 cos^-2 past FLT_MAX (issue 34) */
                                   0x1baf4b54u, 0x9baf4b54u, 0x127d87b6u, 0x927d87b6u, 0x1af1c901u };
    float z = rb_float(zs[rb_pick(sizeof zs / sizeof zs[0])]);
    float p = 6.2831853f * rb_uniform();
    return appear_vec3_make(cosf(p), sinf(p), z);
}
static appear_vec3 g_last; /* the previous direction: wo = wi and wo = -wi */
static appear_vec3 rb_dir(void)
{
    appear_vec3 v = rb_sphere();
    switch (rb_pick(15)) {
    case 0: case 1: case 2: case 3: break;
    case 4: case 5: v = rb_grazing(); break;
    case 6: { static const float a[][3] = { {0,0,1}, {0,0,-1}, {1,0,0}, {0,1,0}, {-1,0,0}, {0,-1,0} };
              const float *p = a[rb_pick(6)]; v = appear_vec3_make(p[0], p[1], p[2]); } break;
    case 7: v = appear_scale(v, 0.5f + 2.0f * rb_uniform()); break;
    case 8: v = appear_vec3_make(0.0f, 0.0f, 0.0f); break;
    case 9: { float x = rb_adv(), y = rb_adv(), z = rb_adv(); v = appear_vec3_make(x, y, z); } break;
    case 10: v.x = rb_float(0x7fc00000u); break;
    case 11: v.z = rb_float(rb_pick(2) ? 0x7f800000u : 0xff800000u); break;
    case 12: v = g_last; break;
    case 13: v = appear_vec3_make(-g_last.x, -g_last.y, g_last.z); break; /* the mirror: wi = reflect(wo) */
    default: v = appear_neg(g_last); break;
    }
    g_last = v;
    return v;
}
/* a model parameter: an ordinary value in [lo, hi] or an adversarial one */
static float rb_param(float lo, float hi)
{
    uint32_t k = rb_pick(10);
    if (k < 6) return lo + (hi - lo) * rb_uniform();
    if (k < 7) return rb_pick(2) ? lo : hi;
    if (k < 8) { /* 1 or 2 ulp either side of a bound: the thresholds (alpha 1e-4, g, eta) */
        float b = rb_pick(2) ? lo : hi;
        uint32_t d = 1u + rb_pick(2);
        return rb_float(rb_pick(2) ? rb_bits(b) + d : rb_bits(b) - d);
    }
    return rb_adv();
}
static appear_spectrum rb_spec(float lo, float hi)
{
    appear_spectrum s; int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) s.v[i] = rb_param(lo, hi);
    return s;
}

/* ---- the contract of one call ---- */
typedef struct {
    const char *eval_name, *pdf_name, *sample_name;
    float (*pdf)(const void *m, appear_vec3 wo, appear_vec3 wi);
    appear_spectrum (*eval)(const void *m, appear_vec3 wo, appear_vec3 wi);
    int (*sample)(const void *m, appear_vec3 wo, float uc, float u1, float u2, appear_bsdf_record *s);
} rb_bsdf_fns;

static void rb_value_check(const char *fn, float v) { RB_CHECK(rb_value(v), "%s = %a", fn, (double)v); }
static void rb_spec_check(const char *fn, appear_spectrum s)
{
    RB_CHECK(rb_spec_value(s), "%s = (%a %a %a)", fn, (double)s.v[0], (double)s.v[1], (double)s.v[2]);
}
/* a medium an OpenPBR material returns (appear_openpbr_medium, _subsurface): finite values, albedo
   <= 1, g in [-1, 1], all 0 when it has none */
static void rb_openpbr_medium_check(const char *fn, int has, appear_spectrum sig, appear_spectrum alb, float g)
{
    char name[64];
    int k;
    snprintf(name, sizeof name, "%s sigma_t", fn);
    rb_spec_check(name, sig);
    snprintf(name, sizeof name, "%s albedo", fn);
    rb_spec_check(name, alb);
    for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) RB_CHECK(alb.v[k] <= 1.0f, "%s: albedo %g > 1", fn, (double)alb.v[k]);
    RB_CHECK(rb_finite(g) && g >= -1.0f && g <= 1.0f && (has || (rb_spec_zero(sig) && g == 0.0f)),
             "%s: has %d, g %g", fn, has, (double)g);
}

/* est: the record's pdf is a stochastic estimate that may be 0 for a successful sample
   (appear_layered_sample, documented): f must then be 0, the weight finite and >= 0 */
static void rb_bsdf_check_x(const char *fn, int ok, const appear_bsdf_record *s, const void *m, appear_vec3 wo,
                            const rb_bsdf_fns *f, int est)
{
    if (!ok) {
        RB_CHECK(s->flags == 0u && rb_zero(s->pdf) && rb_spec_zero(s->weight),
                 "%s failed but flags %u pdf %a weight %a", fn, s->flags, (double)s->pdf, (double)s->weight.v[0]);
        return;
    }
    if (est && rb_zero(s->pdf)) {
        RB_CHECK(s->flags != 0u && rb_unit(s->wi) && rb_spec_zero(s->f) && rb_spec_value(s->weight) &&
                     rb_positive(s->eta),
                 "%s ok with a pdf estimate 0 but flags %u wi (%a %a %a) weight %a f %a eta %a", fn, s->flags,
                 (double)s->wi.x, (double)s->wi.y, (double)s->wi.z, (double)s->weight.v[0], (double)s->f.v[0],
                 (double)s->eta);
        return;
    }
    RB_CHECK(s->flags != 0u && rb_unit(s->wi) && rb_positive(s->pdf) && rb_spec_value(s->weight) &&
                 rb_spec_value(s->f) && rb_positive(s->eta),
             "%s ok but flags %u wo (%a %a %a) wi (%a %a %a) |wi|^2-1 %.3g pdf %a weight %a f %a eta %a", fn,
             s->flags, (double)wo.x, (double)wo.y, (double)wo.z, (double)s->wi.x, (double)s->wi.y, (double)s->wi.z,
             (double)(appear_dot(s->wi, s->wi) - 1.0f), (double)s->pdf, (double)s->weight.v[0], (double)s->f.v[0],
             (double)s->eta);
    {   /* weight = f |cos| / pdf (delta lobes too: f is the delta coefficient) */
        double c = fabs((double)s->wi.z), want = (double)s->f.v[0] * c / (double)s->pdf, got = s->weight.v[0];
        int capped = s->f.v[0] >= 0.5f * APPEAR_FLT_MAX || s->weight.v[0] >= 0.5f * APPEAR_FLT_MAX;
        /* a throughput factor: 1e-9 absolute is far below anything a render shows; 1%
           relative: at alpha 1e-4 and cos 1e-20 the sampled half vector and the one
           eval() recomputes differ by rounding amplified 1/alpha^2 (Ward: 0.44%) */
        /* est: the record's f is computed from the weight, f = weight pdf / |cos| in float, so
           where f is denormal it carries up to 2^-150 (1 + 1/|cos|) of rounding: the weight is
           then f |cos| / pdf within 2^-148 / pdf */
        int denormal_f = est && fabs(got - want) * (double)s->pdf <= 0x1p-148;
        RB_CONSIST(capped || denormal_f || rb_close(got, want, 1e-2) || fabs(got - want) < 1e-9,
                   "%s: weight %a but f |cos| / pdf = %a (f %a cos %a pdf %a)",
                   fn, got, want, (double)s->f.v[0], c, (double)s->pdf);
    }
    if (f && !(s->flags & APPEAR_LOBE_SPECULAR) && rb_unit(s->wi)) {
        float p = f->pdf(m, wo, s->wi);
        appear_spectrum e = f->eval(m, wo, s->wi);
        RB_CHECK(rb_spec_value(e), "%s: eval() at the sampled wi = %a", fn, (double)e.v[0]);
        /* the record is pdf() and eval() at its own direction (MIS needs both) */
        RB_CONSIST(rb_close(s->pdf, p, 2e-3) && rb_close(s->f.v[0], e.v[0], 2e-3),
                   "%s: wo (%a %a %a) wi (%a %a %a): sample pdf %a f %a, pdf() %a eval() %a", fn, (double)wo.x,
                   (double)wo.y, (double)wo.z, (double)s->wi.x, (double)s->wi.y, (double)s->wi.z, (double)s->pdf,
                   (double)s->f.v[0], (double)p, (double)e.v[0]);
#ifdef __FAST_MATH__
        /* -ffast-math computes one expression differently in different
           inlining contexts, so the sampler's inlined copy and pdf()'s own
           can disagree where a sign test meets rounding noise (eta within
           1e-6 of 1 at cos 2^-126). Counted and printed, not failed: the
           contract above (finite, zeroed failures, unit wi) still holds. */
        if (!rb_positive(p)) ++g_soft;
        return;
#endif
        RB_CHECK(rb_positive(p) && rb_spec_value(e),
                 "%s: sampled wi (%a %a %a) from wo (%a %a %a) has pdf() %a eval() %a", fn, (double)s->wi.x,
                 (double)s->wi.y, (double)s->wi.z, (double)wo.x, (double)wo.y, (double)wo.z, (double)p,
                 (double)e.v[0]);
    }
}
static void rb_bsdf_check(const char *fn, int ok, const appear_bsdf_record *s, const void *m, appear_vec3 wo,
                          const rb_bsdf_fns *f)
{ rb_bsdf_check_x(fn, ok, s, m, wo, f, 0); }

/* stochastic: the record's f = pdf is a one-sample estimate that may be 0
   (appear_sggx_diffuse_sample, documented); weight must then be exactly 1 */
static void rb_phase_check_x(const char *fn, int ok, const appear_phase_record *s, int stochastic)
{
    if (!ok) {
        RB_CHECK(s->flags == 0u && rb_zero(s->pdf) && rb_zero(s->weight),
                 "%s failed but flags %u pdf %a weight %a", fn, s->flags, (double)s->pdf, (double)s->weight);
        return;
    }
    RB_CHECK(s->flags != 0u && rb_unit(s->wi) && rb_value(s->weight) && rb_value(s->f) &&
                 (stochastic ? rb_value(s->pdf) && s->weight == 1.0f : rb_positive(s->pdf)),
             "%s ok but flags %u wi (%a %a %a) |wi|^2-1 %.3g pdf %a weight %a f %a", fn, s->flags, (double)s->wi.x,
             (double)s->wi.y, (double)s->wi.z, (double)(appear_dot(s->wi, s->wi) - 1.0f), (double)s->pdf,
             (double)s->weight, (double)s->f);
}
static void rb_phase_check(const char *fn, int ok, const appear_phase_record *s) { rb_phase_check_x(fn, ok, s, 0); }
/* issue 34, class 8: a phase sample's record is pdf() and eval() at its own direction, within the
   BSDFs' tolerance; pdf() of a sampled direction is > 0 in IEEE builds (under -ffast-math a 0 is
   counted, g_soft, as for the BSDFs) */
static void rb_phase_consist(const char *fn, int ok, const appear_phase_record *s, float p, float e)
{
    if (!ok || (s->flags & APPEAR_LOBE_SPECULAR)) return;
#ifdef __FAST_MATH__
    if (!rb_positive(p)) { ++g_soft; return; }
#endif
    RB_CHECK(rb_positive(p), "%s: sampled wi (%a %a %a) has pdf() %a", fn, (double)s->wi.x, (double)s->wi.y,
             (double)s->wi.z, (double)p);
    RB_CONSIST(rb_close(s->pdf, p, 2e-3) && rb_close(s->f, e, 2e-3),
               "%s: wi (%a %a %a): sample pdf %a f %a, pdf() %a eval() %a", fn, (double)s->wi.x, (double)s->wi.y,
               (double)s->wi.z, (double)s->pdf, (double)s->f, (double)p, (double)e);
}
/* a direction-valued building block: unit or the zero vector */
static void rb_dir_check(const char *fn, appear_vec3 v)
{
    RB_CHECK(rb_unit(v) || rb_vec_zero(v), "%s = (%a %a %a)", fn, (double)v.x, (double)v.y, (double)v.z);
}

/* ---- one adapter per BSDF: eval, pdf, sample through a common shape ---- */
#define RB_ADAPT(name, type)                                                                          \
    static float rb_pdf_##name(const void *m, appear_vec3 wo, appear_vec3 wi)                        \
    { return appear_##name##_pdf((const type *)m, wo, wi); }                                          \
    static appear_spectrum rb_eval_##name(const void *m, appear_vec3 wo, appear_vec3 wi)             \
    { return appear_##name##_eval((const type *)m, wo, wi); }                                         \
    static int rb_sample_##name(const void *m, appear_vec3 wo, float uc, float u1, float u2,         \
                                appear_bsdf_record *s)                                                \
    { return appear_##name##_sample((const type *)m, wo, uc, u1, u2, s); }                            \
    static const rb_bsdf_fns rb_fns_##name = { #name "_eval", #name "_pdf", #name "_sample",          \
                                               rb_pdf_##name, rb_eval_##name, rb_sample_##name };
#ifndef APPEAR_NO_LAMBERT
RB_ADAPT(lambert, appear_lambert)
#endif
#ifndef APPEAR_NO_EON
RB_ADAPT(eon, appear_eon)
#endif
#ifndef APPEAR_NO_WARD
RB_ADAPT(ward, appear_ward)
#endif
#ifndef APPEAR_NO_SHEEN
RB_ADAPT(sheen, appear_sheen)
#endif
#ifndef APPEAR_NO_MICROFACET
RB_ADAPT(conductor, appear_conductor)
RB_ADAPT(dielectric, appear_dielectric)
#if !defined(APPEAR_NO_MULTISCATTER)
RB_ADAPT(conductor_comp, appear_conductor)
RB_ADAPT(dielectric_comp, appear_dielectric)
#endif
#if !defined(APPEAR_NO_THINFILM)
RB_ADAPT(thinfilm_conductor, appear_thinfilm_conductor)
#endif
#if !defined(APPEAR_NO_MATERIALS)
RB_ADAPT(dielectric_dispersive, appear_dielectric_dispersive)
#endif
#endif

/* the battery of one BSDF at (wo, wi): eval, pdf, and a sample from (uc, u1, u2) checked
   against eval and pdf at its own direction */
static void rb_bsdf_calls(const rb_bsdf_fns *f, const void *m, appear_vec3 wo, appear_vec3 wi, float uc,
                          float u1, float u2)
{
    appear_bsdf_record s;
    int ok;
    rb_spec_check(f->eval_name, f->eval(m, wo, wi));
    rb_value_check(f->pdf_name, f->pdf(m, wo, wi));
    ok = f->sample(m, wo, uc, u1, u2, &s);
    rb_bsdf_check(f->sample_name, ok, &s, m, wo, f);
}

/* ---- the families ---- */
static long g_n;
enum { G_MAX = 32 };
static rb_group g_groups[G_MAX];
static int g_ngroups;
static void rb_begin(const char *name)
{
    g_cur = &g_groups[g_ngroups++];
    memset(g_cur, 0, sizeof *g_cur);
    g_cur->name = name;
    g_sharp = 0;
}

static void fam_core(void)
{
    long i;
    rb_begin("core: normalize, frames, sincos");
    for (i = 0; i < g_n; ++i) {
        appear_vec3 v = rb_dir(), n = appear_normalize(v);
        float s, c, u = rb_adv();
        RB_CHECK(rb_unit(n) || rb_vec_zero(n), "normalize(%a %a %a) = (%a %a %a)", (double)v.x, (double)v.y,
                 (double)v.z, (double)n.x, (double)n.y, (double)n.z);
        appear_sincos_2pi(u, &s, &c);
        RB_CHECK(rb_finite(s) && rb_finite(c) && (rb_bits(s) & 0x7fffffffu) <= 0x3f800000u &&
                     (rb_bits(c) & 0x7fffffffu) <= 0x3f800000u,
                 "sincos_2pi(%a) = %a %a", (double)u, (double)s, (double)c);
        if (rb_unit(v)) {
            appear_frame f = appear_frame_from_normal(v);
            RB_CHECK(rb_unit(f.x) && rb_unit(f.y), "frame_from_normal(%a %a %a)", (double)v.x, (double)v.y,
                     (double)v.z);
        }
    }
    /* issue 34, classes 1 and 5: a tangent with NaN, Inf, huge or tiny
       components (a unit normal: the frame is orthonormal or the documented
       fallback from the normal), and normalize() at lengths 2^-75 .. 2^-50 and
       2^50 .. 2^75, where squares of the components fall below FLT_MIN (FTZ
       flushes them) or a comparison on the squared length is reassociated */
    rb_begin("core: frame from normal and tangent, normalize at extreme lengths");
    for (i = 0; i < g_n; ++i) {
        appear_vec3 n = appear_normalize(rb_sphere()), t, v, u;
        float sc = rb_float((uint32_t)(rb_pick(2) ? 52 + rb_pick(26) : 177 + rb_pick(26)) << 23);
        appear_frame f;
        switch (rb_pick(4)) {
        case 0: { float tx = rb_adv(), ty = rb_adv(), tz = rb_adv(); /* in this order */
                  t = appear_vec3_make(tx, ty, tz); } break;
        case 1: t = appear_scale(rb_sphere(), sc); break;
        case 2: t = n; t.y = rb_adv(); break;
        default: t = rb_dir(); break;
        }
        RB_IN(n.x, n.y, n.z, t.x, t.y, t.z);
        f = appear_frame_from_normal_tangent(n, t);
        RB_CHECK(rb_unit(f.x) && rb_unit(f.y) && rb_unit(f.z) && fabs(appear_dot(f.x, f.y)) < 1e-3 &&
                     fabs(appear_dot(f.x, f.z)) < 1e-3 && fabs(appear_dot(f.y, f.z)) < 1e-3,
                 "frame_from_normal_tangent: x (%a %a %a) y (%a %a %a)", (double)f.x.x, (double)f.x.y,
                 (double)f.x.z, (double)f.y.x, (double)f.y.y, (double)f.y.z);
        v = appear_scale(rb_sphere(), sc);
        if (rb_pick(4) == 0) v.x = rb_float(rb_pick(2) ? 0x00000001u : 0x1fec1e4au); /* one tiny component */
        RB_IN(v.x, v.y, v.z);
        u = appear_normalize(v);
        RB_CHECK(rb_unit(u) || rb_vec_zero(u), "normalize = (%a %a %a), |u|^2 - 1 = %.3g", (double)u.x,
                 (double)u.y, (double)u.z, (double)(appear_dot(u, u) - 1.0f));
    }
}

#ifndef APPEAR_NO_LAMBERT
static void fam_lambert(void)
{
    long i;
    rb_begin("lambert");
    for (i = 0; i < g_n; ++i) {
        appear_lambert m = appear_lambert_make(rb_spec(0.0f, 1.0f));
        appear_vec3 wo = rb_dir(), wi = rb_dir();
        float q111 = rb_u(), q112 = rb_u(), q113 = rb_u(); /* in this order */
        rb_bsdf_calls(&rb_fns_lambert, &m, wo, wi, q111, q112, q113);
    }
}
#endif

#ifndef APPEAR_NO_EON
/* EON: rho and sigma across [0, 1] and past it (NaN, Inf, 1 + 1 ulp: rejected), both samplers
   and a bad one; also appear_eon_albedo at any mu */
static void fam_eon(void)
{
    long i;
    rb_begin("eon");
    for (i = 0; i < g_n; ++i) {
        appear_spectrum rho = rb_spec(0.0f, 1.0f);
        float sigma = rb_param(0.0f, 1.0f);
        int sampling = rb_pick(16) ? (int)rb_pick(2) : 2;
        appear_eon m = appear_eon_make_sampled(rho, sigma, sampling);
        appear_vec3 wo = rb_dir(), wi = rb_dir();
        float q111 = rb_u(), q112 = rb_u(), q113 = rb_u(), mu = rb_u(); /* in this order */
        appear_spectrum e;
        int c;
        rb_bsdf_calls(&rb_fns_eon, &m, wo, wi, q111, q112, q113);
        e = appear_eon_albedo(&m, mu);
        for (c = 0; c < APPEAR_SPECTRUM_SAMPLES; ++c)
            RB_CHECK(rb_value(e.v[c]) && e.v[c] <= 1.0f + 1e-6f, "eon_albedo(mu %a) = %a", (double)mu,
                     (double)e.v[c]);
    }
}
#endif

#ifndef APPEAR_NO_SHEEN
/* the LTC sheen: roughness over (0, 1] with its edges and beyond (rb_param: 1-2 ulp either side,
   NaN, Inf, denormals), colours in [0, 1] and adversarial; grazing and bad directions come from
   rb_dir; the layering helper in both modes (and a bad mode) with an adversarial base f */
static void fam_sheen(void)
{
    long i;
    rb_begin("sheen");
    for (i = 0; i < g_n; ++i) {
        float r = rb_pick(4) ? rb_param(0.0f, 1.0f) : rb_param(0.0f, 0.02f);
        appear_spectrum c = rb_spec(0.0f, 1.0f), fb = rb_spec(0.0f, 1.0f);
        appear_sheen m = appear_sheen_make(c, r);
        appear_vec3 wo = rb_dir(), wi = rb_dir();
        float q121 = rb_u(), q122 = rb_u(), q123 = rb_u(); /* in this order */
        int mode = (int)rb_pick(3);
        RB_IN(r, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z);
        rb_bsdf_calls(&rb_fns_sheen, &m, wo, wi, q121, q122, q123);
        rb_value_check("sheen_albedo", appear_sheen_albedo(&m, wo.z));
        RB_CHECK(appear_sheen_albedo(&m, wo.z) <= 1.0f, "sheen_albedo = %a", (double)appear_sheen_albedo(&m, wo.z));
        rb_value_check("sheen_base_weight", appear_sheen_base_weight(&m, wo, wi, mode));
        rb_spec_check("sheen_layer_eval", appear_sheen_layer_eval(&m, wo, wi, fb, mode));
    }
}
#endif

#ifndef APPEAR_NO_PHASE
static void fam_phase(void)
{
    long i;
    rb_begin("phase: isotropic, hg");
    for (i = 0; i < g_n; ++i) {
        uint32_t gk = rb_pick(4), gd = rb_pick(3), gs = rb_pick(2); /* drawn in this order */
        float g = gk ? rb_param(-1.0f, 1.0f) : rb_float(rb_bits(1.0f) - gd) * (gs ? 1 : -1);
        appear_vec3 wo = rb_dir(), wi = rb_dir();
        appear_phase_record s;
        int ok;
        RB_IN(g, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z);
        rb_value_check("isotropic_eval", appear_isotropic_eval(wo, wi));
        float q109 = rb_u(), q110 = rb_u(); /* in this order */
        ok = appear_isotropic_sample(wo, q109, q110, &s);
        rb_phase_check("isotropic_sample", ok, &s);
        rb_phase_consist("isotropic_sample", ok, &s, appear_isotropic_pdf(wo, s.wi), appear_isotropic_eval(wo, s.wi));
        rb_value_check("hg_eval", appear_hg_eval_g(g, wo, wi));
        rb_value_check("hg_pdf", appear_hg_pdf_g(g, wo, wi));
        float q107 = rb_u(), q108 = rb_u(); /* in this order */
        ok = appear_hg_sample_g(g, wo, q107, q108, &s);
        rb_phase_check("hg_sample", ok, &s);
        rb_phase_consist("hg_sample", ok, &s, appear_hg_pdf_g(g, wo, s.wi), appear_hg_eval_g(g, wo, s.wi));
        if (ok && !(s.flags & APPEAR_LOBE_SPECULAR))
            RB_CHECK(rb_positive(appear_hg_pdf_g(g, wo, s.wi)), "hg g %a: pdf(sampled wi) = %a", (double)g,
                     (double)appear_hg_pdf_g(g, wo, s.wi));
    }
}
#endif

#ifndef APPEAR_NO_WARD
static void fam_ward(void)
{
    long i;
    rb_begin("ward");
    for (i = 0; i < g_n; ++i) {
        float ax = rb_param(1e-4f, 1.0f), ay = rb_pick(2) ? ax : rb_param(1e-4f, 1.0f);
        appear_spectrum rd = rb_spec(0.0f, 0.5f), rs = rb_spec(0.0f, 0.5f);
        appear_ward m = appear_ward_make(rd, rs, ax, ay, (appear_ward_variant)rb_pick(3));
        appear_vec3 wo = rb_dir(), wi = rb_dir();
        RB_IN(ax, ay, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z);
        g_sharp = rb_sharp(ax, ay);
        rb_value_check("ward_specular_eval",
                       appear_ward_specular_eval((appear_ward_variant)rb_pick(3), ax, ay, wo, wi));
        rb_value_check("ward_specular_pdf", appear_ward_specular_pdf(ax, ay, wo, wi));
        /* issue 34, class 2: h itself at cos 1e-22 and alpha 1e-4 (E = tan^2 / alpha^2 overflows) */
        rb_value_check("ward_specular_pdf_h", appear_ward_specular_pdf_h(ax, ay, wo));
        rb_value_check("ward_specular_pdf_h", appear_ward_specular_pdf_h(ax, ay, appear_normalize(appear_add(wo, wi))));
        float q103 = rb_u(), q104 = rb_u(); /* in this order */
        rb_dir_check("ward_specular_sample_h", appear_ward_specular_sample_h(ax, ay, q103, q104));
        float q100 = rb_u(), q101 = rb_u(), q102 = rb_u(); /* in this order */
        rb_bsdf_calls(&rb_fns_ward, &m, wo, wi, q100, q101, q102);
    }
}
#endif

#ifndef APPEAR_NO_MICROFACET
static void fam_microfacet_blocks(void)
{
    long i;
    rb_begin("microfacet building blocks (D, Lambda, G, visible normals, alpha_from_fuzz)");
    for (i = 0; i < g_n; ++i) {
        float ax = rb_param(1e-4f, 2.0f), ay = rb_pick(2) ? ax : rb_param(1e-4f, 2.0f), u1 = rb_u(), u2 = rb_u();
        appear_vec3 wo = rb_dir(), wi = rb_dir(), m = rb_dir();
        RB_IN(ax, ay, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, m.x, m.y, m.z, u1, u2);
        rb_value_check("ggx_D", appear_ggx_D(ax, ay, m));
        rb_value_check("beckmann_D", appear_beckmann_D(ax, ay, m));
        rb_value_check("ggx_lambda", appear_ggx_lambda(ax, ay, wo));
        rb_value_check("beckmann_lambda", appear_beckmann_lambda(ax, ay, wo));
        rb_value_check("beckmann_lambda_fast", appear_beckmann_lambda_fast(ax, ay, wo));
        rb_value_check("ggx_G1", appear_ggx_G1(ax, ay, wo, m));
        rb_value_check("beckmann_G2", appear_beckmann_G2(ax, ay, wo, wi, m));
        rb_value_check("ggx_pdf_visible", appear_ggx_pdf_visible(ax, ay, wo, m));
        rb_value_check("beckmann_pdf_visible", appear_beckmann_pdf_visible(ax, ay, wo, m));
        rb_value_check("ggx_pdf_reflect_bounded", appear_ggx_pdf_bounded_reflect(ax, ay, wo, wi));
        rb_dir_check("ggx_sample_visible", appear_ggx_sample_visible(ax, ay, wo, u1, u2));
        rb_dir_check("ggx_sample_visible_bounded", appear_ggx_sample_bounded_normal(ax, ay, wo, u1, u2));
        rb_dir_check("beckmann_sample_visible", appear_beckmann_sample_visible(ax, ay, wo, u1, u2));
        rb_dir_check("ggx_sample_D", appear_ggx_sample_D(ax, ay, u1, u2));
        rb_dir_check("beckmann_sample_D", appear_beckmann_sample_D(ax, ay, u1, u2));
        {
            appear_vec3 v = appear_ggx_sample_visible(ax, ay, wo, u1, u2);
            if (!rb_vec_zero(v))
                RB_CHECK(rb_positive(appear_ggx_pdf_visible(ax, ay, wo, v)),
                         "ggx_sample_visible a %a %a wo (%a %a %a) u %a %a: its pdf_visible is 0", (double)ax,
                         (double)ay, (double)wo.x, (double)wo.y, (double)wo.z, (double)u1, (double)u2);
        }
        { /* the porting map: finite, in [+0, alpha(1)], +0 for NaN, -0 and negatives, a valid alpha */
            float fz = rb_pick(2) ? rb_adv() : rb_param(0.0f, 1.0f), a = appear_alpha_from_fuzz(fz);
            RB_IN(fz);
            RB_CHECK(rb_value(a) && rb_bits(a) <= rb_bits(appear_alpha_from_fuzz(1.0f)) &&
                         (rb_bits(fz) <= 0x7f800000u || rb_bits(a) == 0u) &&
                         appear_microfacet_make(APPEAR_GGX, a, a, APPEAR_SAMPLE_VISIBLE).valid,
                     "alpha_from_fuzz(%a) = %a", (double)fz, (double)a);
        }
    }
    rb_begin("fresnel (in [0, 1])");
    for (i = 0; i < g_n; ++i) {
        float c = rb_param(-1.0f, 1.0f), eta = rb_param(0.3f, 3.0f), k = rb_param(0.0f, 5.0f), f0 = rb_param(0, 1);
        float v[4];
        int j;
        RB_IN(c, eta, k, f0);
        v[0] = appear_fresnel_dielectric(c, eta);
        v[1] = appear_fresnel_conductor(c, eta, k);
        v[2] = appear_fresnel_schlick(c, f0);
        v[3] = appear_fresnel_f82(c, f0, appear_fresnel_f82_coef(f0, rb_param(0, 1)));
        for (j = 0; j < 4; ++j)
            RB_CHECK(rb_value(v[j]) && rb_bits(v[j]) <= 0x3f800000u, "fresnel %d (cos %a eta %a k %a) = %a", j,
                     (double)c, (double)eta, (double)k, (double)v[j]);
    }
}

static appear_microfacet rb_microfacet(void)
{
    float ax = rb_param(1e-4f, 2.0f), ay = rb_pick(2) ? ax : rb_param(1e-4f, 2.0f);
    int type = (int)rb_pick(2), sampling = (int)rb_pick(3);
    return appear_microfacet_make(type, ax, ay, sampling);
}

static void fam_microfacet_models(void)
{
    long i;
    rb_begin("rough conductor, dielectric, thin dielectric");
    for (i = 0; i < g_n; ++i) {
        appear_microfacet d = rb_microfacet();
        int fk = (int)rb_pick(4); /* complex IOR (2 in 4), F82, constant F0 */
        /* drawn in this order whatever the kind */
        appear_spectrum c0 = fk < 2 ? rb_spec(0.1f, 3.0f) : rb_spec(0, 1), c1 = fk < 2 ? rb_spec(0.0f, 5.0f) : rb_spec(0, 1);
        appear_conductor c = fk < 2    ? appear_conductor_make(d, c0, c1)
                             : fk == 2 ? appear_conductor_make_f82(d, c0, c1)
                                       : appear_conductor_make_reflectance(d, c0);
        float eta = rb_pick(4) ? rb_param(1.0f / 2.4f, 2.4f) : rb_float(rb_bits(1.0f) + rb_pick(5) - 2);
        appear_dielectric e = appear_dielectric_make(d, eta);
        appear_thin_dielectric th = appear_thin_dielectric_make(eta);
        appear_vec3 wo = rb_dir(), wi = rb_dir();
        appear_bsdf_record s;
        int ok;
        float uc = rb_u(), u1 = rb_u(), u2 = rb_u();
        RB_IN(d.ax, d.ay, (float)d.type, (float)d.sampling, eta, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, uc, u1, u2);
        g_sharp = rb_sharp(d.ax, d.ay);
        float q93 = rb_u(), q94 = rb_u(), q95 = rb_u(); /* in this order */
        rb_bsdf_calls(&rb_fns_conductor, &c, wo, wi, q93, q94, q95);
        rb_bsdf_calls(&rb_fns_dielectric, &e, wo, wi, uc, u1, u2);
        rb_spec_check("thin_dielectric_eval", appear_thin_dielectric_eval(&th, wo, wi));
        float q90 = rb_u(), q91 = rb_u(), q92 = rb_u(); /* in this order */
        ok = appear_thin_dielectric_sample(&th, wo, q90, q91, q92, &s);
        rb_bsdf_check("thin_dielectric_sample", ok, &s, &th, wo, 0);
    }
#if !defined(APPEAR_NO_MULTISCATTER)
    rb_begin("energy compensation, random walk");
    for (i = 0; i < g_n / 8; ++i) {
        appear_microfacet d = rb_microfacet();
        appear_spectrum q88 = rb_spec(0.1f, 3.0f), q89 = rb_spec(0.0f, 5.0f); /* in this order */
        appear_conductor c = appear_conductor_make(d, q88, q89);
        appear_dielectric e = appear_dielectric_make(d, rb_param(1.0f / 2.4f, 2.4f));
        appear_vec3 wo = rb_dir(), wi = rb_dir();
        appear_rng rng = appear_rng_make((unsigned)i);
        if (rb_pick(4) == 0) { /* issue 34, class 4: a sharp lobe, wo at cos 1e-22 .. 8e-28, wi its mirror */
            int ty = (int)rb_pick(2);
            float ax = 1e-4f * (1.0f + 9.0f * rb_uniform());
            int st = (int)rb_pick(3);
            appear_spectrum ce = rb_spec(0.1f, 3.0f), ck = rb_spec(0.0f, 5.0f); /* in this order */
            d = appear_microfacet_make(ty, ax, 1e-4f, st);
            c = appear_conductor_make(d, ce, ck);
            e = appear_dielectric_make(d, rb_param(1.0f / 2.4f, 2.4f));
            wo = rb_grazing();
            wi = appear_vec3_make(-wo.x, -wo.y, wo.z);
        }
        appear_bsdf_record s;
        int ok;
        RB_IN(d.ax, d.ay, (float)d.type, c.p0.v[0], c.p1.v[0], c.p0.v[1], c.p1.v[1], c.p0.v[2], c.p1.v[2], wo.x,
              wo.y, wo.z, wi.x, wi.y, wi.z);
        g_sharp = rb_sharp(d.ax, d.ay);
        float q85 = rb_u(), q86 = rb_u(), q87 = rb_u(); /* in this order */
        rb_bsdf_calls(&rb_fns_conductor_comp, &c, wo, wi, q85, q86, q87);
        float q82 = rb_u(), q83 = rb_u(), q84 = rb_u(); /* in this order */
        rb_bsdf_calls(&rb_fns_dielectric_comp, &e, wo, wi, q82, q83, q84);
        rb_spec_check("conductor_ms_eval", appear_conductor_ms_eval(&c, wo, wi, &rng));
        rb_value_check("conductor_ms_pdf", appear_conductor_ms_pdf(&c, wo, wi));
        ok = appear_conductor_ms_sample(&c, wo, &rng, &s);
        rb_bsdf_check("conductor_ms_sample", ok, &s, &c, wo, 0);
        rb_spec_check("dielectric_ms_eval", appear_dielectric_ms_eval(&e, wo, wi, &rng));
        rb_value_check("dielectric_ms_pdf", appear_dielectric_ms_pdf(&e, wo, wi));
        ok = appear_dielectric_ms_sample(&e, wo, &rng, &s);
        rb_bsdf_check("dielectric_ms_sample", ok, &s, &e, wo, 0);
        { /* the anisotropic albedo lookup, at the lobe's alphas or adversarial ones */
            float ax = rb_pick(2) ? d.ax : rb_adv();
            float ay = rb_pick(2) ? d.ay : rb_adv();
            float a = appear_conductor_albedo_aniso(ax, ay, wo);
            rb_value_check("conductor_albedo_aniso", a);
            RB_CHECK(a <= 1.0f, "conductor_albedo_aniso(%a, %a, wo) = %a > 1", (double)ax, (double)ay, (double)a);
            a = appear_dielectric_albedo_aniso(ax, ay, e.eta, wo); /* and the dielectric's, at its eta */
            rb_value_check("dielectric_albedo_aniso", a);
            RB_CHECK(a <= 1.0f, "dielectric_albedo_aniso(%a, %a, %a, wo) = %a > 1", (double)ax, (double)ay, (double)e.eta,
                     (double)a);
            a = appear_dielectric_reflect_albedo_aniso(ax, ay, e.eta, wo);
            rb_value_check("dielectric_reflect_albedo_aniso", a);
            RB_CHECK(a <= 1.0f, "dielectric_reflect_albedo_aniso(%a, %a, %a, wo) = %a > 1", (double)ax, (double)ay,
                     (double)e.eta, (double)a);
        }
    }
#endif
#if !defined(APPEAR_NO_THINFILM)
    rb_begin("thin film");
    for (i = 0; i < g_n / 8; ++i) {
        float q78 = rb_param(1.0f, 2.5f); float q79 = rb_param(0.0f, 1000.0f); appear_spectrum q80 = rb_spec(0.1f, 3.0f); appear_spectrum q81 = rb_spec(0.0f, 5.0f); /* in this order */
        appear_thinfilm tf = appear_thinfilm_make_rgb(q78, q79,q80, q81);
        appear_thinfilm_conductor m = appear_thinfilm_conductor_make(rb_microfacet(), tf);
        appear_vec3 wo = rb_dir(), wi = rb_dir();
        g_sharp = rb_sharp(m.c.d.ax, m.c.d.ay);
        rb_spec_check("thinfilm_F", appear_thinfilm_reflectance(&tf, rb_param(-1, 1)));
        float q75 = rb_u(), q76 = rb_u(), q77 = rb_u(); /* in this order */
        rb_bsdf_calls(&rb_fns_thinfilm_conductor, &m, wo, wi, q75, q76, q77);
    }
#endif
}
#endif

#ifndef APPEAR_NO_MEDIA
static float rb_sigma(void) { return rb_pick(4) ? rb_param(0.0f, 10.0f) : rb_adv(); }
static void fam_media(void)
{
    long i;
    rb_begin("media: homogeneous");
    for (i = 0; i < g_n; ++i) {
        appear_spectrum st;
        float d = rb_pick(4) ? rb_param(0.0f, 10.0f) : rb_adv(), t = rb_param(0.0f, 10.0f);
        appear_medium_sample s;
        int j, ok;
        for (j = 0; j < APPEAR_SPECTRUM_SAMPLES; ++j) st.v[j] = rb_sigma();
        if (rb_pick(3) == 0) st = appear_spectrum_splat(st.v[0]);
        RB_IN(st.v[0], st.v[1], st.v[2], d, t);
        rb_value_check("homogeneous_transmittance1", appear_homogeneous_transmittance1(st.v[0], d));
        rb_spec_check("homogeneous_transmittance", appear_homogeneous_transmittance(st, d));
        rb_value_check("homogeneous_pdf", appear_homogeneous_pdf(st, d, t, (int)rb_pick(2)));
        float q73 = rb_u(), q74 = rb_u(); /* in this order */
        ok = appear_homogeneous_sample(st, d, q73, q74, &s);
        /* t = +Inf is the documented answer for a pass of d = +Inf */
        RB_CHECK((rb_finite(s.t) || (rb_bits(d) == 0x7f800000u && !s.scattered && rb_bits(s.t) == 0x7f800000u)) &&
                     rb_value(s.pdf) && rb_spec_value(s.tr) && rb_spec_value(s.weight) &&
                     (ok || (rb_zero(s.pdf) && rb_spec_zero(s.weight))),
                 "homogeneous_sample(sigma %a %a %a, d %a) = %d t %a pdf %a w %a", (double)st.v[0],
                 (double)st.v[1], (double)st.v[2], (double)d, ok, (double)s.t, (double)s.pdf,
                 (double)s.weight.v[0]);
        {
            appear_medium_sample1 s1;
            float u = rb_u();
            ok = appear_homogeneous_sample1(st.v[0], d, u, &s1);
            rb_value_check("homogeneous_pdf1",
                           appear_homogeneous_pdf1(st.v[0], d, t, (int)rb_pick(2)));
            RB_CHECK((rb_finite(s1.t) ||
                      (rb_bits(d) == 0x7f800000u && ok == 1 && rb_bits(s1.t) == 0x7f800000u)) &&
                         rb_value(s1.pdf) && rb_value(s1.tr) && rb_value(s1.weight) && ok >= 0 &&
                         ok <= 2 && (ok || (rb_zero(s1.pdf) && rb_zero(s1.weight))),
                     "homogeneous_sample1(sigma %a, d %a, u %a) = %d t %a pdf %a w %a",
                     (double)st.v[0], (double)d, (double)u, ok, (double)s1.t, (double)s1.pdf,
                     (double)s1.weight);
        }
    }
    rb_begin("media: trackers (terminate, finite T)");
    for (i = 0; i < g_n / 16; ++i) {
        appear_majorant_segment seg[3];
        appear_tracker tr;
        appear_tracker_params p;
        int kind = (int)rb_pick(APPEAR_TRACK_KIND_COUNT), nseg = 1 + (int)rb_pick(3), j, steps = 0;
        float tmax = rb_pick(8) ? rb_param(0.0f, 20.0f) : rb_adv(), t, dens_scale = rb_param(0.0f, 2.0f);
        for (j = 0; j < nseg; ++j) {
            float maj = rb_sigma(), mn = rb_pick(2) ? 0.0f : maj * rb_uniform();
            seg[j] = appear_majorant_make(j + 1 == nseg ? rb_float(0x7f800000u) : (float)(j + 1) * 5.0f, maj, mn);
        }
        p = appear_tracker_defaults(kind);
        p.max_lookups = 1 << 16;
        appear_tracker_init(&tr, kind, tmax, seg, nseg, &p);
        for (;;) {
            float ua = rb_u(), ub = rb_u();
            if (!appear_tracker_next(&tr, ua, ub, &t)) break;
            float sig = rb_pick(32) ? seg[0].sigma_maj * dens_scale * rb_uniform() : rb_adv();
            RB_CHECK(rb_finite(t), "tracker kind %d asks for a lookup at t = %a", kind, (double)t);
            appear_tracker_feed(&tr, sig);
            if (++steps > (1 << 17)) break;
        }
        RB_CHECK(tr.done && steps <= (1 << 16) + 1 && rb_finite(tr.T),
                 "tracker kind %d t_max %a: done %d after %d steps, T %a flags %u", kind, (double)tmax, tr.done,
                 steps, (double)tr.T, tr.flags);
    }
}
#endif

#ifndef APPEAR_NO_MEDIA
static void fam_media_chromatic(void)
{
    static const int kinds[] = { APPEAR_TRACK_DELTA, APPEAR_TRACK_RATIO, APPEAR_TRACK_NEXT_FLIGHT, APPEAR_TRACK_SPECTRAL };
    long i;
    rb_begin("media: chromatic trackers (terminate, finite results, flags)");
    for (i = 0; i < g_n / 16; ++i) {
        appear_cmajorant_segment seg[3];
        appear_ctracker tr;
        appear_tracker_params p;
        int kind = kinds[rb_pick(4)], nseg = 1 + (int)rb_pick(3), j, k, steps = 0, finite = 1;
        float tmax = rb_pick(8) ? rb_param(0.0f, 20.0f) : rb_adv(), t, dens_scale = rb_param(0.0f, 2.0f);
        for (j = 0; j < nseg; ++j) {
            appear_spectrum maj = rb_spec(0.0f, 10.0f);
            if (rb_pick(3) == 0) maj = appear_spectrum_splat(maj.v[0]); /* grey: the cheap path */
            seg[j] = appear_cmajorant_make(j + 1 == nseg ? rb_float(0x7f800000u) : (float)(j + 1) * 5.0f, maj);
        }
        p = appear_tracker_defaults(kind == APPEAR_TRACK_SPECTRAL ? APPEAR_TRACK_DELTA : kind);
        p.max_lookups = 1 << 16;
        appear_ctracker_init(&tr, kind, tmax, seg, nseg, rb_u(), &p);
        for (;;) {
            float ua = rb_u(), ub = rb_u();
            if (!appear_ctracker_next(&tr, ua, ub, &t)) break;
            appear_spectrum sig;
            for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k)
                sig.v[k] = rb_pick(32) ? seg[0].sigma_maj.v[k] * dens_scale * rb_uniform() : rb_adv();
            RB_CHECK(rb_finite(t), "ctracker kind %d asks for a lookup at t = %a", kind, (double)t);
            appear_ctracker_feed(&tr, sig);
            if (++steps > (1 << 17)) break;
        }
        for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) finite &= rb_finite(tr.T.v[k]) && rb_finite(tr.weight.v[k]);
        if (tr.flags & APPEAR_TRACK_MAJORANT_VIOLATED) { /* issue 34, class 12: a flagged estimate is bounded */
            const float nch = (float)APPEAR_SPECTRUM_SAMPLES;
            for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) {
                float w = tr.weight.v[k];
                int pass_ok = (rb_bits(w) & 0x7fffffffu) <= rb_bits(nch);
                /* a collision (DELTA, SPECTRAL): |weight sigma(t)| <= N, in double */
                int coll_ok = (kind == APPEAR_TRACK_DELTA || kind == APPEAR_TRACK_SPECTRAL) && rb_zero(tr.T.v[k]) &&
                              fabs((double)w * tr.sigma_[k]) <= nch * (1.0 + 1e-6);
                /* or ended with zero results (a bad density, truncated) */
                int zeroed = rb_zero(tr.T.v[k]) && rb_zero(w) && rb_zero(tr.beta.v[k]) && rb_zero(tr.r_u.v[k]);
                RB_CHECK(zeroed || ((rb_bits(tr.T.v[k]) & 0x7fffffffu) <= rb_bits(nch) && (pass_ok || coll_ok) &&
                                    rb_bits(tr.beta.v[k]) == rb_bits(w) && rb_bits(tr.r_u.v[k]) == rb_bits(1.0f)),
                         "ctracker kind %d flagged MAJORANT_VIOLATED: channel %d T %a weight %a sigma %a beta %a"
                         " r_u %a (bound N = %g)", kind, k, (double)tr.T.v[k], (double)w, (double)tr.sigma_[k],
                         (double)tr.beta.v[k], (double)tr.r_u.v[k], (double)nch);
            }
        }
        RB_CHECK(tr.done && steps <= (1 << 16) + 1 && finite && tr.hero >= 0 && tr.hero < APPEAR_SPECTRUM_SAMPLES,
                 "ctracker kind %d t_max %a: done %d after %d steps, T %a weight %a hero %d flags %u", kind,
                 (double)tmax, tr.done, steps, (double)tr.T.v[0], (double)tr.weight.v[0], tr.hero, tr.flags);
    }
}
#endif

#ifndef APPEAR_NO_FLAKES
/* what appear_fiber_make must have stored, field by field, on the bits: p
   (0 when invalid), a unit frame, positive sigma data, bins and a CDF from
   0 to 1. gcc 12 -O3 once dropped these stores and left stack garbage
   (see appear__flakes_gl16): a negative majorant only by chance, garbage
   in every make(), so every make() is checked */
static void rb_fiber_fields(const appear_fiber *fb, float p)
{
    int j, ok = (fb->valid == 0 || fb->valid == 1) && rb_unit(fb->f.x) && rb_unit(fb->f.y) && rb_unit(fb->f.z) &&
                rb_bits(fb->p) == (fb->valid ? rb_bits(p) : 0u) && rb_bits(fb->half_p) == rb_bits(0.5f * fb->p) &&
                rb_positive(fb->inv_norm) && rb_positive(fb->s_par) && rb_positive(fb->s_perp) &&
                rb_positive(fb->sigma_max) && rb_bits(fb->sigma_max) >= rb_bits(fb->s_perp) &&
                rb_value(fb->sigma_err) && rb_bits(fb->xedge[0]) == 0u && rb_bits(fb->cdf[0]) == 0u &&
                rb_bits(fb->xedge[APPEAR_FIBER_BINS]) == 0x3f800000u &&
                rb_bits(fb->cdf[APPEAR_FIBER_BINS]) == 0x3f800000u;
    for (j = 0; j <= APPEAR_FIBER_SIGMA_N; ++j) ok &= rb_positive(fb->sigma[j]);
    for (j = 0; j < APPEAR_FIBER_BINS; ++j) /* the last cdf step may come down from 1 + 1 ulp */
        ok &= rb_positive(fb->dens[j]) && rb_bits(fb->xedge[j + 1]) > rb_bits(fb->xedge[j]) &&
              rb_bits(fb->xedge[j + 1]) <= 0x3f800000u && rb_value(fb->cdf[j + 1]) &&
              (j + 1 == APPEAR_FIBER_BINS || rb_bits(fb->cdf[j + 1]) >= rb_bits(fb->cdf[j])) &&
              rb_bits(fb->cdf[j + 1]) <= 0x3f800008u;
    RB_CHECK(ok, "fiber_make fields: valid %d p %a half_p %a f.z (%a %a %a) s_par %a s_perp %a sigma_max %a "
             "sigma_err %a cdf[1] %a dens[0] %a", fb->valid, (double)fb->p, (double)fb->half_p, (double)fb->f.z.x,
             (double)fb->f.z.y, (double)fb->f.z.z, (double)fb->s_par, (double)fb->s_perp, (double)fb->sigma_max,
             (double)fb->sigma_err, (double)fb->cdf[1], (double)fb->dens[0]);
}
#endif

#if !defined(APPEAR_NO_FLAKES) || !defined(APPEAR_NO_PHASE_EXTRA)
static void fam_flakes(void)
{
    long i;
#ifndef APPEAR_NO_FLAKES
    rb_begin("flakes: sggx, fiber");
    {   /* the first violation found (gcc 12 -O3 -ffast-math, N = 100000):
           majorant -0x1.40d6b2p+1 at rho_max 10, make()'s stores dropped */
        appear_vec3 t = appear_vec3_make(-0x1.1ce1b8p-1f, 0x1.91369p-1f, -0x1.1af1d8p-2f);
        appear_fiber fb = appear_fiber_make(t, 0x1.8b500ep+4f);
        float maj = appear_fiber_majorant(&fb, 10.0f);
        RB_IN(t.x, t.y, t.z, 0x1.8b500ep+4f, 10.0f);
        rb_fiber_fields(&fb, 0x1.8b500ep+4f);
        RB_CHECK(fb.valid && rb_value(maj) && rb_close(maj, 0x1.8febeep+2, 1e-3), /* gcc -O2: 0x1.8febeep+2 */
                 "fiber_majorant = %a (valid %d, sigma_max %a)", (double)maj, fb.valid, (double)fb.sigma_max);
    }
    for (i = 0; i < g_n / 2; ++i) {
        appear_sggx m;
        appear_vec3 ft;
        float fp;
        appear_fiber fb;
        ft = rb_dir(); fp = rb_param(0.5f, 64.0f); /* in this order: a call's arguments have none */
        fb = appear_fiber_make(ft, fp);
        appear_vec3 wo, wi;
        appear_phase_record s;
        int ok;
        RB_IN(ft.x, ft.y, ft.z, fp);
        rb_fiber_fields(&fb, fp);
        wo = rb_dir(); wi = rb_dir();
        RB_IN(wo.x, wo.y, wo.z, wi.x, wi.y, wi.z);
        switch (rb_pick(3)) {
        case 0: {
            float sxx = rb_param(0, 1), syy = rb_param(0, 1), szz = rb_param(0, 1);
            float sxy = rb_param(-0.5f, 0.5f), sxz = rb_param(-0.5f, 0.5f), syz = rb_param(-0.5f, 0.5f);
            m = appear_sggx_make(sxx, syy, szz, sxy, sxz, syz);
        } break;
        case 1: { appear_vec3 t = rb_dir(); float a = rb_param(1e-4f, 1.0f); m = appear_sggx_make_fiber(t, a); } break;
        default: { appear_vec3 n = rb_dir(); float a = rb_param(1e-4f, 1.0f); m = appear_sggx_make_surface(n, a); } break;
        }
        rb_value_check("sggx_sigma", appear_sggx_sigma(&m, wo));
        rb_value_check("sggx_D", appear_sggx_D(&m, wi));
        rb_value_check("sggx_sigma_t", appear_sggx_sigma_t(&m, rb_param(0, 10), wo));
        rb_value_check("sggx_majorant", appear_sggx_majorant(&m, rb_param(0, 10)));
        float q57 = rb_u(), q58 = rb_u(); /* in this order */
        rb_dir_check("sggx_sample_visible", appear_sggx_sample_visible(&m, wo, q57, q58));
        {   /* issue 34, class 8: u1 within 2^-24 .. 2^-12 of 1 (cos of the visible normal near 0) */
            float u1 = rb_float(0x3f800000u - 1u - rb_pick(1u << 12));
            float u2 = rb_u();
            RB_IN(wo.x, wo.y, wo.z, u1);
            rb_dir_check("sggx_sample_visible (u1 near 1)", appear_sggx_sample_visible(&m, wo, u1, u2));
        }
        rb_value_check("sggx_specular_eval", appear_sggx_specular_eval(&m, wo, wi));
        rb_value_check("sggx_specular_pdf", appear_sggx_specular_pdf(&m, wo, wi));
        float q55 = rb_u(), q56 = rb_u(); /* in this order */
        ok = appear_sggx_specular_sample(&m, wo, q55, q56, &s);
        rb_phase_check("sggx_specular_sample", ok, &s);
        rb_phase_consist("sggx_specular_sample", ok, &s, appear_sggx_specular_pdf(&m, wo, s.wi), appear_sggx_specular_eval(&m, wo, s.wi));
        float q53 = rb_u(), q54 = rb_u(); /* in this order */
        rb_value_check("sggx_diffuse_eval", appear_sggx_diffuse_eval(&m, wo, wi, q53, q54));
        float q49 = rb_u(), q50 = rb_u(), q51 = rb_u(), q52 = rb_u(); /* in this order */
        ok = appear_sggx_diffuse_sample(&m, wo, q49, q50, q51, q52, &s);
        rb_phase_check_x("sggx_diffuse_sample", ok, &s, 1);
        rb_value_check("fiber_D", appear_fiber_D(&fb, wi));
        rb_value_check("fiber_sigma", appear_fiber_sigma(&fb, wo));
        rb_value_check("fiber_majorant", appear_fiber_majorant(&fb, rb_param(0, 10)));
        rb_value_check("fiber_eval", appear_fiber_eval(&fb, wo, wi));
        rb_value_check("fiber_pdf", appear_fiber_pdf(&fb, wo, wi));
        float q47 = rb_u(), q48 = rb_u(); /* in this order */
        ok = appear_fiber_sample(&fb, wo, q47, q48, &s);
        rb_phase_check("fiber_sample", ok, &s);
        rb_phase_consist("fiber_sample", ok, &s, appear_fiber_pdf(&fb, wo, s.wi), appear_fiber_eval(&fb, wo, s.wi));
    }
#endif
#ifndef APPEAR_NO_PHASE_EXTRA
    rb_begin("more phase functions: dhg, rayleigh, draine, mie, table");
    {
        static appear_phase_table tab;
        float vals[5] = { 4.0f, 2.0f, 1.0f, 0.5f, 0.25f }, mus[5] = { -1.0f, -0.5f, 0.0f, 0.5f, 1.0f };
        appear_phase_table_make(&tab, vals, mus, 5);
        for (i = 0; i < g_n / 2; ++i) {
            float q44 = rb_param(-1, 1), q45 = rb_param(-1, 1), q46 = rb_param(0, 1); /* in this order */
            appear_dhg dh = appear_dhg_make(q44, q45, q46);
            float q42 = rb_param(-1, 1), q43 = rb_param(0, 2); /* in this order */
            appear_draine dr = appear_draine_make(q42, q43);
            appear_mie mi = appear_mie_make(rb_param(0.1f, 50.0f));
            appear_vec3 wo = rb_dir(), wi = rb_dir();
            appear_phase_record s;
            int ok;
            RB_IN(wo.x, wo.y, wo.z, wi.x, wi.y, wi.z);
            rb_value_check("dhg_eval", appear_dhg_eval(&dh, wo, wi));
            float q40 = rb_u(), q41 = rb_u(); /* in this order */
            ok = appear_dhg_sample(&dh, wo, q40, q41, &s);
            rb_phase_check("dhg_sample", ok, &s);
            rb_phase_consist("dhg_sample", ok, &s, appear_dhg_pdf(&dh, wo, s.wi), appear_dhg_eval(&dh, wo, s.wi));
            rb_value_check("rayleigh_eval", appear_rayleigh_eval(wo, wi));
            float q38 = rb_u(), q39 = rb_u(); /* in this order */
            ok = appear_rayleigh_sample(wo, q38, q39, &s);
            rb_phase_check("rayleigh_sample", ok, &s);
            rb_phase_consist("rayleigh_sample", ok, &s, appear_rayleigh_pdf(wo, s.wi), appear_rayleigh_eval(wo, s.wi));
            /* issue 34, class 8: a sampled direction has pdf() > 0, in every build */
            if (ok) RB_CHECK(rb_positive(appear_rayleigh_pdf(wo, s.wi)), "rayleigh: pdf(sampled wi (%a %a %a)) = %a",
                             (double)s.wi.x, (double)s.wi.y, (double)s.wi.z, (double)appear_rayleigh_pdf(wo, s.wi));
            rb_value_check("draine_eval", appear_draine_eval(&dr, wo, wi));
            float q36 = rb_u(), q37 = rb_u(); /* in this order */
            ok = appear_draine_sample(&dr, wo, q36, q37, &s);
            rb_phase_check("draine_sample", ok, &s);
            rb_phase_consist("draine_sample", ok, &s, appear_draine_pdf(&dr, wo, s.wi), appear_draine_eval(&dr, wo, s.wi));
            if (ok && !(s.flags & APPEAR_LOBE_SPECULAR))
                RB_CHECK(rb_positive(appear_draine_pdf(&dr, wo, s.wi)), "draine: pdf(sampled wi (%a %a %a)) = %a",
                         (double)s.wi.x, (double)s.wi.y, (double)s.wi.z, (double)appear_draine_pdf(&dr, wo, s.wi));
            rb_value_check("mie_eval", appear_mie_eval(&mi, wo, wi));
            float q34 = rb_u(), q35 = rb_u(); /* in this order */
            ok = appear_mie_sample(&mi, wo, q34, q35, &s);
            rb_phase_check("mie_sample", ok, &s);
            rb_phase_consist("mie_sample", ok, &s, appear_mie_pdf(&mi, wo, s.wi), appear_mie_eval(&mi, wo, s.wi));
            rb_value_check("phase_table_eval", appear_phase_table_eval(&tab, wo, wi));
            float q32 = rb_u(), q33 = rb_u(); /* in this order */
            ok = appear_phase_table_sample(&tab, wo, q32, q33, &s);
            rb_phase_check("phase_table_sample", ok, &s);
            rb_phase_consist("phase_table_sample", ok, &s, appear_phase_table_pdf(&tab, wo, s.wi), appear_phase_table_eval(&tab, wo, s.wi));
        }
    }
#endif
}
#endif

/* ---- batch = scalar, bit for bit (IEEE builds; counted under -ffast-math) ---- */
enum { RB_B = 80 }; /* crosses the batch loops' 64-element blocks */
static float b_ox[RB_B], b_oy[RB_B], b_oz[RB_B], b_ix[RB_B], b_iy[RB_B], b_iz[RB_B], b_uc[RB_B], b_u1[RB_B],
    b_u2[RB_B], b_rx[RB_B], b_ry[RB_B], b_rz[RB_B], b_p[RB_B], b_w[RB_B * APPEAR_SPECTRUM_SAMPLES];
static unsigned b_fl[RB_B];
static int b_sc[RB_B];
static void rb_batch_inputs(int n)
{
    int i;
    for (i = 0; i < n; ++i) {
        appear_vec3 o = rb_dir(), w = rb_dir();
        b_ox[i] = o.x; b_oy[i] = o.y; b_oz[i] = o.z; b_ix[i] = w.x; b_iy[i] = w.y; b_iz[i] = w.z;
        b_uc[i] = rb_u(); b_u1[i] = rb_u(); b_u2[i] = rb_u();
    }
}
/* batch against scalar, measured (issue 34, class 7): per entry point, the
   elements that differ in their bits, those where one of the two is 0 and
   the other not (success or a zero value differs), and the largest relative
   difference elsewhere; printed at the end, and held to rb_batch_bound below */
static double g_brel, g_bdir;
static float g_bfa, g_bfb; /* the values of the last flip */
static int g_bflip;
static int rb_same(float a, float b)
{
    double x = a, y = b, m;
    if (rb_bits(a) == rb_bits(b)) return 1;
    m = fabs(x) > fabs(y) ? fabs(x) : fabs(y);
    if (m < 1e-30) return 0; /* where FTZ flushes intermediates: absolute agreement */
    if (rb_zero(a) != rb_zero(b) || !rb_finite(a) || !rb_finite(b)) { g_bflip = 1; g_bfa = a; g_bfb = b; return 0; }
    if (fabs(x - y) > g_brel * m) g_brel = fabs(x - y) / m;
    return 0;
}
typedef struct {
    const char *name;
    long n, differ, flip, dflip;
    double rel, dir, drel, ddir;
    char worst[240], wdir[240], flip1[320];
} rb_bstat;
static int g_bmodel_degenerate; /* the entry point's parameters are degenerate */
/* Batch against scalar under -ffast-math (issue 34, class 7): the README's bounds, outside the
   degenerate set (a cosine of wo or wi below 1e-3, a lobe sharper than alpha 1e-3), where the two
   differ in no success and no zero (values below 1e-30 agree). A direction's components differ by
   at most RB_BATCH_DIR; a value by at most rb_batch_bound relative: 4e-6, but 4e-3 for the
   dielectric (at the critical angle Fresnel's sqrt turns an ulp of the cosine into sqrt(ulp)) and
   Ward (the exponent tan^2/alpha^2 amplifies the half vector's rounding by 1/alpha). IEEE builds
   are bit for bit (RB_CONSIST). Measured in README ("Supported flags"). */
#define RB_BATCH_DIR 4e-6
static double rb_batch_bound(const char *name)
{
    return strncmp(name, "dielectric", 10) == 0 || strncmp(name, "ward", 4) == 0 ? 4e-3 : 4e-6;
}
static char g_bctx[96]; /* the entry point's parameters, for the worst element's report */
static rb_bstat g_bstat[16];
static int g_nbstat;
/* element i's inputs, with the entry point's parameters */
static void rb_bstat_where(char *where, int i)
{
    snprintf(where, 240, "%s wo (%a %a %a) wi (%a %a %a) u (%a %a %a)", g_bctx, (double)b_ox[i], (double)b_oy[i],
             (double)b_oz[i], (double)b_ix[i], (double)b_iy[i], (double)b_iz[i], (double)b_uc[i], (double)b_u1[i],
             (double)b_u2[i]);
}
static void rb_bstat_add(const char *name, int same, int i)
{
    int k;
    for (k = 0; k < g_nbstat && strcmp(g_bstat[k].name, name) != 0; ++k) {}
    if (k == g_nbstat) { if (g_nbstat == 16) return; g_bstat[g_nbstat++].name = name; }
    g_bstat[k].n++;
    g_bstat[k].differ += !same;
    {
        float wz = strstr(name, "sample") ? b_rz[i] : b_iz[i];
        if (g_bmodel_degenerate || !(fabsf(b_oz[i]) >= 1e-3f) || !(fabsf(wz) >= 1e-3f)) {
            g_bstat[k].dflip += g_bflip;
            if (!g_bflip && g_brel > g_bstat[k].drel) g_bstat[k].drel = g_brel;
            if (!g_bflip && g_bdir > g_bstat[k].ddir) g_bstat[k].ddir = g_bdir;
            return;
        }
    }
    g_bstat[k].flip += g_bflip;
    ++g_cur->calls; /* the stated bound (README), outside the degenerate set, in every build */
    if (g_bflip || g_brel > rb_batch_bound(name) || g_bdir > RB_BATCH_DIR) {
        char where[240];
        rb_bstat_where(where, i);
        rb_fail("%s element %d: batch and scalar differ beyond the stated bound (flip %d, relative %.3g, direction "
                "%.3g) at %s", name, i, g_bflip, g_brel, g_bdir, where);
    }
    if (!g_bflip && g_bdir > g_bstat[k].dir) {
        g_bstat[k].dir = g_bdir;
        rb_bstat_where(g_bstat[k].wdir, i);
    }
    if (g_bflip ? !g_bstat[k].flip1[0] : g_brel > g_bstat[k].rel) {
        if (!g_bflip) g_bstat[k].rel = g_brel;
        rb_bstat_where(g_bflip ? g_bstat[k].flip1 : g_bstat[k].worst, i);
        if (g_bflip) {
            size_t l = strlen(g_bstat[k].flip1);
            snprintf(g_bstat[k].flip1 + l, 320 - l, ": %a vs %a", (double)g_bfa, (double)g_bfb);
        }
    }
}
/* a direction: its components' absolute differences (an angle), not relative ones */
static int rb_same_dir(float a, float b)
{
    if (rb_bits(a) == rb_bits(b)) return 1;
    if (!rb_finite(a) || !rb_finite(b)) { g_bflip = 1; return 0; }
    if (fabs((double)a - b) > g_bdir) g_bdir = fabs((double)a - b);
    return 0;
}
static int rb_same_vec(appear_vec3 v, int i)
{
    int x = rb_same_dir(v.x, b_rx[i]), y = rb_same_dir(v.y, b_ry[i]), z = rb_same_dir(v.z, b_rz[i]);
    return x && y && z;
}
/* the planar sample arrays of element i against the scalar record */
static int rb_same_bsdf(const appear_bsdf_record *r, int i, int n, int with_weight)
{
    int k, ok = rb_same_vec(r->wi, i);
    ok &= rb_same(r->pdf, b_p[i]);
    ok &= r->flags == b_fl[i];
    for (k = 0; with_weight && k < APPEAR_SPECTRUM_SAMPLES; ++k) ok &= rb_same(r->weight.v[k], b_w[k * n + i]);
    return ok;
}
/* success or failure agrees in every build (a hard check: issue 34, class 6,
   wo.z = +-0 under -fno-signed-zeros) */
#define RB_BATCH_OK(name, scalar_ok, batch_ok) \
    RB_CHECK(!(scalar_ok) == !(batch_ok), "%s element %d of %d: scalar ok %d, batch ok %d: wo (%a %a %a)", name, i, \
             n, (int)(scalar_ok), (int)(batch_ok), (double)b_ox[i], (double)b_oy[i], (double)b_oz[i])
#define RB_BATCH_CHECK(name, cond) \
    do { int same_; g_brel = 0.0; g_bdir = 0.0; g_bflip = 0; same_ = (cond); rb_bstat_add(name, same_, i); \
         RB_CONSIST(same_, "%s element %d of %d differs from the scalar call: wo (%a %a %a)", name, i, n, \
                    (double)b_ox[i], (double)b_oy[i], (double)b_oz[i]); } while (0)

static void fam_batch(void)
{
    long it;
    rb_begin("batch = scalar (bits)");
    for (it = 0; it < g_n / 64; ++it) {
        int n = 1 + (int)rb_pick(RB_B), i;
        appear_vec3 wo, wi;
        rb_batch_inputs(n);
        g_bctx[0] = 0;
        g_bmodel_degenerate = 0;
#define RB_WO_WI(i) (wo = appear_vec3_make(b_ox[i], b_oy[i], b_oz[i]), wi = appear_vec3_make(b_ix[i], b_iy[i], b_iz[i]))
#ifndef APPEAR_NO_LAMBERT
        {
            appear_lambert m = appear_lambert_make(rb_spec(0.0f, 1.0f));
            appear_lambert_sample_batch(&m, b_ox, b_oy, b_oz, b_u1, b_u2, b_rx, b_ry, b_rz, b_p, b_w, b_fl, n);
            for (i = 0; i < n; ++i) {
                appear_bsdf_record r;
                RB_WO_WI(i);
                appear_lambert_sample(&m, wo, 0.0f, b_u1[i], b_u2[i], &r);
                RB_BATCH_OK("lambert_sample_batch", r.flags, b_fl[i]);
                RB_BATCH_CHECK("lambert_sample_batch", rb_same_bsdf(&r, i, n, 1));
            }
        }
#endif
/* a model's eval, pdf and (uc-free) sample batches against its scalar calls, on the bits */
#define RB_BATCH_EVAL_PDF_SAMPLE_U2(model, M)                                                          \
    do {                                                                                           \
        appear_##model##_eval_batch(&(M), b_ox, b_oy, b_oz, b_ix, b_iy, b_iz, b_w, n);             \
        appear_##model##_pdf_batch(&(M), b_ox, b_oy, b_oz, b_ix, b_iy, b_iz, b_p, n);              \
        for (i = 0; i < n; ++i) {                                                                  \
            appear_spectrum f;                                                                     \
            int k, ok;                                                                             \
            RB_WO_WI(i);                                                                           \
            f = appear_##model##_eval(&(M), wo, wi);                                               \
            ok = rb_same(appear_##model##_pdf(&(M), wo, wi), b_p[i]);                              \
            for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) ok &= rb_same(f.v[k], b_w[k * n + i]);   \
            RB_BATCH_CHECK(#model "_eval/pdf_batch", ok);                                          \
        }                                                                                          \
        appear_##model##_sample_batch(&(M), b_ox, b_oy, b_oz, b_u1, b_u2, b_rx, b_ry, b_rz, b_p,   \
                                      b_w, b_fl, n);                                               \
        for (i = 0; i < n; ++i) {                                                                  \
            appear_bsdf_record rec_;                                                               \
            RB_WO_WI(i);                                                                           \
            appear_##model##_sample(&(M), wo, 0.0f, b_u1[i], b_u2[i], &rec_);                         \
            RB_BATCH_OK(#model "_sample_batch", rec_.flags, b_fl[i]);                                 \
            RB_BATCH_CHECK(#model "_sample_batch", rb_same_bsdf(&rec_, i, n, 1));                     \
        }                                                                                          \
    } while (0)
#ifndef APPEAR_NO_EON
        {
            appear_spectrum rho = rb_spec(0.0f, 1.0f);
            float sigma = rb_param(0.0f, 1.0f);
            int sampling = (int)rb_pick(2); /* in this order */
            appear_eon m = appear_eon_make_sampled(rho, sigma, sampling);
            RB_BATCH_EVAL_PDF_SAMPLE_U2(eon, m);
        }
#endif
#ifndef APPEAR_NO_SHEEN
        {
            appear_spectrum col = rb_spec(0.0f, 1.0f);
            float r = rb_param(0.0f, 1.0f); /* in this order */
            appear_sheen m = appear_sheen_make(col, r);
            RB_BATCH_EVAL_PDF_SAMPLE_U2(sheen, m);
        }
#endif
#undef RB_BATCH_EVAL_PDF_SAMPLE_U2
#ifndef APPEAR_NO_PHASE
        {
            float g = rb_param(-1.0f, 1.0f);
            snprintf(g_bctx, sizeof g_bctx, "g %a", (double)g);
            appear_hg_sample_batch_g(g, b_ox, b_oy, b_oz, b_u1, b_u2, b_rx, b_ry, b_rz, b_p, n);
            for (i = 0; i < n; ++i) {
                appear_phase_record r;
                int ok;
                RB_WO_WI(i);
                ok = appear_hg_sample_g(g, wo, b_u1[i], b_u2[i], &r);
                RB_BATCH_CHECK("hg_sample_batch", rb_same_vec(r.wi, i) && rb_same(ok ? r.pdf : 0.0f, b_p[i]));
            }
            appear_hg_eval_batch_g(g, b_ox, b_oy, b_oz, b_ix, b_iy, b_iz, b_p, n);
            for (i = 0; i < n; ++i) {
                RB_WO_WI(i);
                RB_BATCH_CHECK("hg_eval_batch", rb_same(appear_hg_eval_g(g, wo, wi), b_p[i]));
            }
        }
#endif
#ifndef APPEAR_NO_WARD
        {
            float ax = rb_param(1e-4f, 1.0f), ay = rb_pick(2) ? ax : rb_param(1e-4f, 1.0f);
            appear_spectrum rd = rb_spec(0.0f, 0.5f), rs = rb_spec(0.0f, 0.5f);
            appear_ward m = appear_ward_make(rd, rs, ax, ay, (appear_ward_variant)rb_pick(3));
            snprintf(g_bctx, sizeof g_bctx, "ax %a ay %a variant %d", (double)ax, (double)ay, (int)m.variant);
            g_bmodel_degenerate = ax < 1e-3f || ay < 1e-3f;
            appear_ward_sample_batch(&m, b_ox, b_oy, b_oz, b_uc, b_u1, b_u2, b_rx, b_ry, b_rz, b_p, b_w, b_fl, n);
            for (i = 0; i < n; ++i) {
                appear_bsdf_record r;
                RB_WO_WI(i);
                appear_ward_sample(&m, wo, b_uc[i], b_u1[i], b_u2[i], &r);
                RB_BATCH_CHECK("ward_sample_batch", rb_same_bsdf(&r, i, n, 1));
            }
        }
#endif
#ifndef APPEAR_NO_MICROFACET
        {
            appear_microfacet d = rb_microfacet();
            int fk = (int)rb_pick(4); /* complex IOR (2 in 4), F82, constant F0 */
            /* drawn in this order whatever the kind */
            appear_spectrum c0 = fk < 2 ? rb_spec(0.1f, 3.0f) : rb_spec(0, 1), c1 = fk < 2 ? rb_spec(0.0f, 5.0f) : rb_spec(0, 1);
            appear_conductor c = fk < 2    ? appear_conductor_make(d, c0, c1)
                                 : fk == 2 ? appear_conductor_make_f82(d, c0, c1)
                                           : appear_conductor_make_reflectance(d, c0);
            /* eta within a few ulp of 1 in one case of four (the pass-through limit) */
            appear_dielectric e = appear_dielectric_make(d, rb_pick(4) ? rb_param(1.0f / 2.4f, 2.4f)
                                                                       : rb_float(rb_bits(1.0f) + rb_pick(9) - 4u));
            snprintf(g_bctx, sizeof g_bctx, "type %d ax %a ay %a eta %a", (int)d.type, (double)d.ax, (double)d.ay,
                     (double)e.eta);
            g_bmodel_degenerate = d.ax < 1e-3f || d.ay < 1e-3f;
            (d.type == APPEAR_GGX ? appear_ggx_sample_visible_batch : appear_beckmann_sample_visible_batch)(
                d.ax, d.ay, b_ox, b_oy, b_oz, b_u1, b_u2, b_rx, b_ry, b_rz, n);
            for (i = 0; i < n; ++i) {
                RB_WO_WI(i);
                RB_BATCH_CHECK("sample_visible_batch",
                               rb_same_vec(d.type == APPEAR_GGX ? appear_ggx_sample_visible(d.ax, d.ay, wo, b_u1[i], b_u2[i])
                                                                : appear_beckmann_sample_visible(d.ax, d.ay, wo, b_u1[i], b_u2[i]),
                                           i));
            }
            appear_conductor_sample_batch(&c, b_ox, b_oy, b_oz, b_uc, b_u1, b_u2, b_rx, b_ry, b_rz, b_p, b_w, b_fl, n);
            for (i = 0; i < n; ++i) {
                appear_bsdf_record r;
                RB_WO_WI(i);
                appear_conductor_sample(&c, wo, b_uc[i], b_u1[i], b_u2[i], &r);
                RB_BATCH_CHECK("conductor_sample_batch", rb_same_bsdf(&r, i, n, 1));
            }
            appear_dielectric_sample_batch(&e, b_ox, b_oy, b_oz, b_uc, b_u1, b_u2, b_rx, b_ry, b_rz, b_p, b_w, b_fl, n);
            for (i = 0; i < n; ++i) {
                appear_bsdf_record r;
                RB_WO_WI(i);
                appear_dielectric_sample(&e, wo, b_uc[i], b_u1[i], b_u2[i], &r);
                RB_BATCH_CHECK("dielectric_sample_batch", rb_same_bsdf(&r, i, n, 1));
            }
            appear_conductor_eval_batch(&c, b_ox, b_oy, b_oz, b_ix, b_iy, b_iz, b_w, n);
            appear_conductor_pdf_batch(&c, b_ox, b_oy, b_oz, b_ix, b_iy, b_iz, b_p, n);
            for (i = 0; i < n; ++i) {
                appear_spectrum f;
                int k, ok;
                RB_WO_WI(i);
                f = appear_conductor_eval(&c, wo, wi);
                ok = rb_same(appear_conductor_pdf(&c, wo, wi), b_p[i]);
                for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) ok &= rb_same(f.v[k], b_w[k * n + i]);
                RB_BATCH_CHECK("conductor_eval/pdf_batch", ok);
            }
            appear_dielectric_eval_batch(&e, b_ox, b_oy, b_oz, b_ix, b_iy, b_iz, b_w, n);
            appear_dielectric_pdf_batch(&e, b_ox, b_oy, b_oz, b_ix, b_iy, b_iz, b_p, n);
            for (i = 0; i < n; ++i) {
                RB_WO_WI(i);
                RB_BATCH_CHECK("dielectric_eval/pdf_batch", rb_same(appear_dielectric_eval(&e, wo, wi).v[0], b_w[i]) &&
                                                                rb_same(appear_dielectric_pdf(&e, wo, wi), b_p[i]));
            }
        }
#endif
#ifndef APPEAR_NO_MEDIA
        {
            appear_spectrum st;
            int k;
            for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) st.v[k] = rb_pick(4) ? rb_param(0.0f, 10.0f) : rb_adv();
            if (rb_pick(3) == 0) st = appear_spectrum_splat(st.v[0]);
            for (i = 0; i < n; ++i) b_ix[i] = rb_pick(4) ? rb_param(0.0f, 10.0f) : rb_adv(); /* d */
            appear_homogeneous_sample_batch(st, b_ix, b_uc, b_u1, b_rx, b_sc, b_p, b_w, n);
            for (i = 0; i < n; ++i) {
                appear_medium_sample r;
                int ok = 1;
                appear_homogeneous_sample(st, b_ix[i], b_uc[i], b_u1[i], &r);
                ok = rb_same(r.t, b_rx[i]) && rb_same(r.pdf, b_p[i]) && r.scattered == b_sc[i];
                for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) ok &= rb_same(r.weight.v[k], b_w[k * n + i]);
                RB_BATCH_CHECK("homogeneous_sample_batch", ok);
            }
        }
#endif
        (void)wo; (void)wi;
#undef RB_WO_WI
    }
}

/* the families, by name (tests/fuzz/fuzz.c runs one of them per binary) */
/* ---- issue 34, items 9-12: IEEE builds at extreme magnitudes ----
   Each class draws its inputs log-uniformly over the float bit patterns
   (denormal to 1e30 and beyond), where rounding, not the formula, decides. */
/* a positive float log-uniform over the bit patterns [lo, hi] */
static float rb_logu(float lo, float hi) { return rb_float(rb_bits(lo) + rb_pick(rb_bits(hi) - rb_bits(lo) + 1u)); }
#ifndef APPEAR_NO_MEDIA
/* item 9: appear_homogeneous_sample's pdf and weights against a double
   reference (and appear_homogeneous_pdf) with channel densities spanning
   denormal to 1e30, d and u likewise */
static void rb_x_homogeneous(void)
{
    long i;
    rb_begin("extremes: homogeneous sample vs pdf() (sigma_t denormal..1e30)");
    for (i = 0; i < g_n; ++i) {
        appear_spectrum st;
        appear_medium_sample s;
        float d, uc, u, x, p;
        double ref = 0.0, tr[APPEAR_SPECTRUM_SAMPLES];
        int j, r;
        for (j = 0; j < APPEAR_SPECTRUM_SAMPLES; ++j) st.v[j] = rb_pick(8) ? rb_logu(0x1p-149f, 1e30f) : 0.0f;
        d = rb_logu(0x1p-149f, 1e30f);
        uc = rb_uniform();
        u = rb_pick(2) ? rb_logu(0x1p-149f, 0x1.fffffep-1f) : rb_uniform();
        RB_IN(st.v[0], st.v[1], st.v[2], d, uc, u);
        r = appear_homogeneous_sample(st, d, uc, u, &s);
        RB_CHECK(r == 1 || r == 2, "homogeneous_sample = %d", r);
        x = s.scattered ? s.t : d;
        for (j = 0; j < APPEAR_SPECTRUM_SAMPLES; ++j) {
            tr[j] = exp(-(double)st.v[j] * (double)x);
            ref += (s.scattered ? (double)st.v[j] : 1.0) * tr[j] / APPEAR_SPECTRUM_SAMPLES;
        }
        p = appear_homogeneous_pdf(st, d, s.t, s.scattered);
        RB_CONSIST(rb_close(s.pdf, ref, 3e-5) && rb_close(p, ref, 3e-5),
                   "homogeneous_sample: scattered %d t %a pdf %a, pdf() %a, exact %a", s.scattered, (double)s.t,
                   (double)s.pdf, (double)p, ref);
        for (j = 0; j < APPEAR_SPECTRUM_SAMPLES; ++j) {
            /* 0 where it would overflow (documented); not compared where T_j
               underflows float (its tr_j is 0 or denormal: e_j / den keeps no bits) */
            double w = ref > 0.0 ? tr[j] / ref : 0.0;
            RB_CONSIST(rb_close(s.weight.v[j], w, 3e-5) || (w > 0x1p127 && rb_zero(s.weight.v[j])) ||
                           tr[j] < 0x1p-126,
                       "homogeneous_sample: scattered %d t %a weight[%d] %a, T / pdf %a", s.scattered,
                       (double)s.t, j, (double)s.weight.v[j], w);
        }
    }
}
#endif
#ifndef APPEAR_NO_MICROFACET
/* item 10: alpha up to FLT_MAX. make() rejects alpha above
   APPEAR_ALPHA_MAX (every model that takes alpha: microfacet, Ward); up
   to it, the visible-normal samplers (building blocks, which clamp alpha
   to the same maximum) give normals whose pdf_visible is > 0, a random
   number outside [0, 1] included (a failure then) */
static void rb_x_alpha(void)
{
    long i;
    rb_begin("extremes: alpha up to FLT_MAX (make rejects above the max; sample vs pdf_visible)");
    for (i = 0; i < g_n; ++i) {
        float ax = rb_logu(1e-4f, 0x1.fffffep127f), ay = rb_pick(2) ? ax : rb_logu(1e-4f, 0x1.fffffep127f);
        float u1 = rb_pick(2) ? rb_u() : rb_logu(0x1p-149f, 1.0f), u2 = rb_pick(2) ? rb_uniform() : rb_u();
        int type = (int)rb_pick(2), over = !(ax <= APPEAR_ALPHA_MAX && ay <= APPEAR_ALPHA_MAX);
        appear_vec3 wo = rb_dir(), m;
        appear_microfacet d = appear_microfacet_make(type, ax, ay, APPEAR_SAMPLE_VISIBLE);
        RB_IN(ax, ay, (float)type, wo.x, wo.y, wo.z, u1, u2);
        RB_CHECK(d.valid == !over, "microfacet_make(type %d, %a, %a): valid %d", type, (double)ax, (double)ay,
                 d.valid);
#ifndef APPEAR_NO_WARD
        {
            appear_ward w = appear_ward_make(appear_spectrum_splat(0.2f), appear_spectrum_splat(0.5f), ax, ay,
                                             APPEAR_WARD_DUER);
            RB_CHECK(w.valid == !over, "ward_make(%a, %a): valid %d", (double)ax, (double)ay, w.valid);
        }
#endif
        m = type ? appear_beckmann_sample_visible(ax, ay, wo, u1, u2) : appear_ggx_sample_visible(ax, ay, wo, u1, u2);
        if (!rb_vec_zero(m)) {
            float pv = type ? appear_beckmann_pdf_visible(ax, ay, wo, m) : appear_ggx_pdf_visible(ax, ay, wo, m);
            RB_CHECK(rb_positive(pv), "%s_sample_visible: m (%a %a %a) has pdf_visible %a",
                     type ? "beckmann" : "ggx", (double)m.x, (double)m.y, (double)m.z, (double)pv);
        }
    }
}
#endif
#ifndef APPEAR_NO_WARD
/* item 11: Ward's sample weight against f |cos_i| / pdf of its own record,
   at alphas down to 1e-4 and wo down to denormal cosines, where f reaches
   1e36 and pdf 1e34 with wi.z 1e-29 (|cos_i| / pdf underflowed: weight 0
   for 3e-27) */
static void rb_x_ward(void)
{
    long i;
    rb_begin("extremes: ward sample weight = f |cos| / pdf (grazing, sharp lobes)");
    for (i = 0; i < g_n; ++i) {
        float ax = rb_logu(1e-4f, 1.0f), ay = rb_pick(2) ? ax : rb_logu(1e-4f, 1.0f);
        float rd = rb_uniform() * 0.5f, rs = rb_uniform() * 0.5f; /* in this order */
        appear_ward_variant var = (appear_ward_variant)rb_pick(3);
        appear_ward m = appear_ward_make(appear_spectrum_splat(rd), appear_spectrum_splat(rs), ax, ay, var);
        appear_vec3 wo = rb_pick(2) ? rb_grazing() : rb_sphere();
        float uc = rb_uniform(), u1 = rb_uniform(), u2 = rb_uniform();
        appear_bsdf_record s;
        int ok, j;
        if (rb_pick(2)) {
            float z = rb_logu(0x1p-149f, 1e-3f);
            wo.z = rb_pick(2) ? z : -z;
        }
        if (rb_pick(2)) { /* u1 -> 0: h -> n, wi.z -> wo.z */
            int zero = (int)rb_pick(2);
            u1 = zero ? 0.0f : rb_logu(0x1p-149f, 1e-6f);
        }
        RB_IN(ax, ay, (float)m.variant, wo.x, wo.y, wo.z, uc, u1, u2);
        ok = appear_ward_sample(&m, wo, uc, u1, u2, &s);
        if (!ok) continue;
        for (j = 0; j < APPEAR_SPECTRUM_SAMPLES; ++j) {
            double w = (double)s.f.v[j] * fabs((double)s.wi.z) / (double)s.pdf;
            RB_CHECK(rb_close(s.weight.v[j], w, 1e-5) || (w > 0x1p127 && rb_zero(s.weight.v[j])),
                     "ward_sample: f %a wi.z %a pdf %a: weight %a, f |cos| / pdf %a", (double)s.f.v[j],
                     (double)s.wi.z, (double)s.pdf, (double)s.weight.v[j], w);
        }
    }
}
#endif
#ifndef APPEAR_NO_MEDIA
/* item 12: every tracker kind fed densities up to 1e30 times its majorant:
   a flagged (MAJORANT_VIOLATED) estimate is bounded, |T| <= 1 (was T =
   -2.6e29 for next-flight at 1e30 against 1.18) */
static void rb_x_tracker(void)
{
    long i;
    rb_begin("extremes: trackers, majorant violated by up to 1e30 (flagged T in [-1, 1])");
    for (i = 0; i < g_n / 16; ++i) {
        appear_majorant_segment seg;
        appear_tracker tr;
        appear_tracker_params p;
        int kind = (int)rb_pick(APPEAR_TRACK_KIND_COUNT), steps = 0;
        float maj = rb_logu(1e-3f, 100.0f), tmax = rb_logu(1e-3f, 20.0f), t, over = rb_logu(1.0f, 1e30f);
        seg = appear_majorant_make(HUGE_VALF, maj, rb_pick(2) ? 0.0f : maj * rb_uniform());
        p = appear_tracker_defaults(kind);
        p.max_lookups = 1 << 12;
        RB_IN((float)kind, maj, tmax, over);
        appear_tracker_init(&tr, kind, tmax, &seg, 1, &p);
        for (;;) {
            float ua = rb_uniform(), ub = rb_uniform(); /* in this order */
            int over_maj;
            if (!appear_tracker_next(&tr, ua, ub, &t)) break;
            over_maj = rb_pick(4) != 0;
            appear_tracker_feed(&tr, over_maj ? maj * over * rb_uniform() : maj * rb_uniform());
            if (++steps > (1 << 13)) break;
        }
        RB_CHECK(tr.done && rb_finite(tr.T) &&
                     (!(tr.flags & APPEAR_TRACK_MAJORANT_VIOLATED) || (rb_bits(tr.T) & 0x7fffffffu) <= 0x3f800000u),
                 "tracker kind %d: done %d T %a flags %u", kind, tr.done, (double)tr.T, tr.flags);
    }
}
#endif
/* item 6: a wo in the tangent plane, its cosine +0, -0 or a denormal of either sign: every
   BSDF sampler fails (scalar and batch alike: flags 0) and eval and pdf are 0, in every
   build. -ffast-math implies -fno-signed-zeros, so the rule may not rest on a zero's sign
   (appear__off_plane and appear__same_side read the bits). Deterministic: 4 cosines x 64
   azimuths x 64 (u1, u2) x 32 wi per model. */
static void rb_x_tangent(void)
{
    static const uint32_t zb[4] = { 0x00000000u, 0x80000000u, 0x00000001u, 0x807fffffu };
    enum { NPHI = 64, NU = 64, NWI = 32, NB = NPHI * NU };
    static float bx[NB], by[NB], bz[NB], bu1[NB], bu2[NB], rx[NB], ry[NB], rz[NB], rp[NB];
    static float rw[NB * APPEAR_SPECTRUM_SAMPLES];
    static unsigned rf[NB];
    appear_spectrum half = appear_spectrum_splat(0.5f);
    int zi, i, j, k;
    rb_begin("extremes: wo in the tangent plane (cos +-0, +-denormal): samplers fail, eval and pdf 0, "
             "scalar and batch");
    for (zi = 0; zi < 4; ++zi) {
        for (i = 0; i < NB; ++i) {
            float ph = 6.2831853f * (float)(i / NU) / NPHI;
            bx[i] = cosf(ph); by[i] = sinf(ph); bz[i] = rb_float(zb[zi]);
            bu1[i] = (float)(i % NU) / (NU - 1); bu2[i] = (float)((i * 7) % NU) / NU;
        }
#define RB_TANGENT(NAME, M, PREFIX)                                                                   \
        for (i = 0; i < NB; ++i) {                                                                   \
            appear_vec3 wo = appear_vec3_make(bx[i], by[i], bz[i]);                                   \
            appear_bsdf_record s;                                                                     \
            int ok = PREFIX##_sample(&M, wo, bu2[i], bu1[i], bu2[i], &s);                             \
            RB_IN(wo.x, wo.y, wo.z, bu1[i], bu2[i]);                                                  \
            RB_CHECK(!ok && s.flags == 0u, NAME "_sample succeeded at wo.z %a", (double)wo.z);        \
            if (i % (NB / NWI) == 0)                                                                  \
                for (j = 0; j < NWI; ++j) {                                                           \
                    float t = 6.2831853f * (float)j / NWI;                                            \
                    appear_vec3 wi = appear_vec3_make(0.6f * cosf(t), 0.6f * sinf(t), j & 1 ? 0.8f : -0.8f); \
                    appear_spectrum f = PREFIX##_eval(&M, wo, wi);                                    \
                    float p = PREFIX##_pdf(&M, wo, wi);                                               \
                    for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k)                                     \
                        RB_CHECK(rb_zero(f.v[k]), NAME "_eval = %a at wo.z %a", (double)f.v[k], (double)wo.z); \
                    RB_CHECK(rb_zero(p), NAME "_pdf = %a at wo.z %a", (double)p, (double)wo.z);       \
                }                                                                                     \
        }
#define RB_TANGENT_BATCH(NAME, CALL)                                                                  \
        CALL;                                                                                         \
        for (i = 0; i < NB; ++i) RB_CHECK(rf[i] == 0u, NAME "_sample_batch succeeded at wo.z %a", (double)bz[i]);
#ifndef APPEAR_NO_LAMBERT
        {
            appear_lambert m = appear_lambert_make(half);
            RB_TANGENT("lambert", m, appear_lambert)
            RB_TANGENT_BATCH("lambert", appear_lambert_sample_batch(&m, bx, by, bz, bu1, bu2, rx, ry, rz, rp, rw, rf, NB))
        }
#endif
#ifndef APPEAR_NO_EON
        for (k = 0; k < 2; ++k) {
            appear_eon m = appear_eon_make_sampled(half, 0.8f, k);
            RB_TANGENT("eon", m, appear_eon)
            RB_TANGENT_BATCH("eon", appear_eon_sample_batch(&m, bx, by, bz, bu1, bu2, rx, ry, rz, rp, rw, rf, NB))
        }
#endif
#ifndef APPEAR_NO_SHEEN
        {
            appear_sheen m = appear_sheen_make(half, 0.4f);
            RB_TANGENT("sheen", m, appear_sheen)
            RB_TANGENT_BATCH("sheen", appear_sheen_sample_batch(&m, bx, by, bz, bu1, bu2, rx, ry, rz, rp, rw, rf, NB))
        }
#endif
#ifndef APPEAR_NO_WARD
        {
            appear_ward m = appear_ward_make(half, half, 0.2f, 0.3f, APPEAR_WARD_BALANCED);
            RB_TANGENT("ward", m, appear_ward)
            RB_TANGENT_BATCH("ward", appear_ward_sample_batch(&m, bx, by, bz, bu2, bu1, bu2, rx, ry, rz, rp, rw, rf, NB))
        }
#endif
#ifndef APPEAR_NO_MICROFACET
        {
            appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE);
            appear_conductor c = appear_conductor_make_reflectance(d, half);
            appear_dielectric e = appear_dielectric_make(d, 1.5f);
            RB_TANGENT("conductor", c, appear_conductor)
            RB_TANGENT_BATCH("conductor", appear_conductor_sample_batch(&c, bx, by, bz, bu2, bu1, bu2, rx, ry, rz, rp, rw, rf, NB))
            RB_TANGENT("dielectric", e, appear_dielectric)
            RB_TANGENT_BATCH("dielectric", appear_dielectric_sample_batch(&e, bx, by, bz, bu2, bu1, bu2, rx, ry, rz, rp, rw, rf, NB))
        }
#endif
#undef RB_TANGENT
#undef RB_TANGENT_BATCH
    }
}

static void fam_extremes(void)
{
    rb_x_tangent();
#ifndef APPEAR_NO_MEDIA
    rb_x_homogeneous();
#endif
#ifndef APPEAR_NO_MICROFACET
    rb_x_alpha();
#endif
#ifndef APPEAR_NO_WARD
    rb_x_ward();
#endif
#ifndef APPEAR_NO_MEDIA
    rb_x_tracker();
#endif
}

#ifndef APPEAR_NO_MATERIALS
/* SECTION materials: ids in and out of the enums, wavelengths in and out of 360..830 nm
   (NaN, +-Inf, raw bits), the Abbe form on adversarial n_d, V_d; the named metals as conductors
   through the BSDF battery */
static int rb_material_id(int count)
{
    switch (rb_pick(6)) {
    case 0: return -1;
    case 1: return count;
    case 2: return (int)(uint32_t)rb_next();
    default: return (int)rb_pick((uint32_t)count);
    }
}
static float rb_lambda(void) { return rb_pick(3) ? rb_param(360.0f, 830.0f) : rb_adv() * 1000.0f; }
static void fam_materials(void)
{
    long i;
    rb_begin("materials: metal and dielectric lookups, the Abbe form");
    for (i = 0; i < g_n; ++i) {
        int m = rb_material_id(APPEAR_METAL_COUNT), d = rb_material_id(APPEAR_DIELECTRIC_COUNT), c;
        float l = rb_lambda(), e = -1.0f, k = -1.0f, lam[APPEAR_SPECTRUM_SAMPLES], nd, vd, n;
        appear_spectrum es, ks, ns;
        appear_metal_rgb r;
        RB_IN((float)m, (float)d, l);
        (void)appear_metal_eta_k(m, l, &e, &k);
        RB_CHECK(rb_positive(e) && rb_value(k), "metal_eta_k(%d, %a) = %a %a", m, (double)l, (double)e, (double)k);
        n = appear_dielectric_ior(d, l);
        RB_CHECK(rb_positive(n), "dielectric_ior(%d, %a) = %a", d, (double)l, (double)n);
        for (c = 0; c < APPEAR_SPECTRUM_SAMPLES; ++c) lam[c] = rb_lambda();
        (void)appear_metal_spectrum(m, rb_pick(8) ? lam : NULL, &es, &ks);
        ns = appear_dielectric_ior_spectrum(d, rb_pick(8) ? lam : NULL);
        rb_spec_check("metal_spectrum eta", es);
        rb_spec_check("metal_spectrum k", ks);
        rb_spec_check("dielectric_ior_spectrum", ns);
        r = appear_metal_to_rgb(m);
        for (c = 0; c < 3; ++c)
            RB_CHECK(rb_value(r.f0[c]) && r.f0[c] <= 1.0f && rb_value(r.f82[c]) && r.f82[c] <= 1.0f &&
                         rb_value(r.f82_tint[c]) && r.f82_tint[c] <= 1.0f && rb_positive(r.eta[c]) && rb_value(r.k[c]),
                     "metal_to_rgb(%d) channel %d", m, c);
        nd = rb_pick(2) ? rb_param(1.0f, 3.0f) : rb_adv();
        vd = rb_pick(2) ? rb_param(5.0f, 100.0f) : rb_adv();
        RB_IN(nd, vd, l);
        n = appear_ior_cauchy_abbe(nd, vd, l);
        RB_CHECK(rb_positive(n) && n >= 1e-4f && n <= 1e4f, "ior_cauchy_abbe(%a, %a, %a) = %a", (double)nd,
                 (double)vd, (double)l, (double)n);
    }
#ifndef APPEAR_NO_MICROFACET
    rb_begin("materials: named metals as conductors (appear_conductor_make_metal)");
    for (i = 0; i < g_n / 8; ++i) {
        float lam[APPEAR_SPECTRUM_SAMPLES];
        int c, m = rb_material_id(APPEAR_METAL_COUNT);
        appear_conductor cm;
        appear_vec3 wo = rb_dir(), wi = rb_dir();
        appear_microfacet d;
        float q1, q2, q3;
        int spectral;
        for (c = 0; c < APPEAR_SPECTRUM_SAMPLES; ++c) lam[c] = rb_lambda();
        d = rb_microfacet();
        spectral = (int)rb_pick(2);
        cm = appear_conductor_make_metal(d, m, spectral ? lam : NULL);
        q1 = rb_u(); q2 = rb_u(); q3 = rb_u(); /* in this order */
        rb_bsdf_calls(&rb_fns_conductor, &cm, wo, wi, q1, q2, q3);
    }
    rb_begin("materials: dispersive dielectric (named glass, Abbe form, adversarial eta)");
    for (i = 0; i < g_n / 4; ++i) {
        float lam[APPEAR_SPECTRUM_SAMPLES];
        int c, g = rb_material_id(APPEAR_DIELECTRIC_COUNT), kind = (int)rb_pick(3);
        appear_spectrum eta;
        appear_dielectric_dispersive dm;
        appear_vec3 wo = rb_dir(), wi = rb_dir();
        appear_microfacet d;
        float q1, q2, q3, nd = rb_param(1.0f, 2.5f), vd = rb_param(10.0f, 90.0f);
        for (c = 0; c < APPEAR_SPECTRUM_SAMPLES; ++c) lam[c] = rb_lambda();
        if (kind == 0) eta = appear_dielectric_ior_spectrum(g, lam);
        else if (kind == 1)
            for (c = 0; c < APPEAR_SPECTRUM_SAMPLES; ++c) eta.v[c] = appear_ior_cauchy_abbe(nd, vd, lam[c]);
        else eta = rb_spec(1e-4f, 1e4f);
        d = rb_microfacet();
        dm = appear_dielectric_make_dispersive(d, eta);
        q1 = rb_u(); q2 = rb_u(); q3 = rb_u(); /* in this order */
        rb_bsdf_calls(&rb_fns_dielectric_dispersive, &dm, wo, wi, q1, q2, q3);
    }
#endif
}
#endif

typedef struct { const char *name; void (*run)(void); } rb_family;
/* the generic interface: a value of every kind (NONE included) from adversarial parameters,
   through appear_bsdf_* / appear_phase_* */
#if defined(APPEAR_HAS_GENERIC) && defined(APPEAR_HAS_WARD) && defined(APPEAR_HAS_MULTISCATTER) && \
    defined(APPEAR_HAS_THINFILM) && defined(APPEAR_HAS_FLAKES) && defined(APPEAR_HAS_PHASE_EXTRA)
#define RB_HAS_GENERIC 1
RB_ADAPT(bsdf, appear_bsdf)
static appear_bsdf rb_bsdf_value(int kind, appear_rng *rng)
{
    appear_microfacet d = rb_microfacet();
    appear_bsdf b;
    /* every draw in a fixed order, before the calls (C leaves the order of a call's
       arguments unspecified: gcc and clang would draw them differently) */
    appear_spectrum s0 = rb_spec(0.0f, 1.0f), s1 = rb_spec(0.0f, 1.0f);
    appear_spectrum k0 = rb_spec(0.1f, 3.0f), k1 = rb_spec(0.0f, 5.0f);
    float x0 = rb_param(0.0f, 1.0f), x1 = rb_param(0.0f, 1.0f), eta = rb_param(1.0f / 2.4f, 2.4f);
    float film_n = rb_param(1.0f, 2.5f), film_d = rb_param(0.0f, 1000.0f);
    appear_ward_variant wv = (appear_ward_variant)rb_pick(3);
    appear_rng *r = rb_pick(8) ? rng : NULL;
    float rough = rb_param(0.0f, 1.0f);
    g_sharp = rb_sharp(d.ax, d.ay);
    switch (kind) {
    case APPEAR_BSDF_LAMBERT: return appear_bsdf_lambert(appear_lambert_make(s0));
#ifdef APPEAR_HAS_EON
    case APPEAR_BSDF_EON: return appear_bsdf_eon(appear_eon_make_sampled(s0, x0, (int)(wv == 0)));
#endif
    case APPEAR_BSDF_WARD:
        g_sharp = 1;
        return appear_bsdf_ward(appear_ward_make(s0, s1, x0, x1, wv));
    case APPEAR_BSDF_CONDUCTOR: return appear_bsdf_conductor(appear_conductor_make(d, k0, k1));
    case APPEAR_BSDF_CONDUCTOR_COMP: return appear_bsdf_conductor_comp(appear_conductor_make_f82(d, s0, s1));
    case APPEAR_BSDF_CONDUCTOR_MS: return appear_bsdf_conductor_ms(appear_conductor_make_reflectance(d, s0), r);
    case APPEAR_BSDF_THINFILM_CONDUCTOR:
        return appear_bsdf_thinfilm_conductor(
            appear_thinfilm_conductor_make(d, appear_thinfilm_make_rgb(film_n, film_d, k0, k1)));
    case APPEAR_BSDF_DIELECTRIC:
        return appear_bsdf_dielectric(appear_dielectric_make(d, eta));
    case APPEAR_BSDF_DIELECTRIC_COMP: return appear_bsdf_dielectric_comp(appear_dielectric_make(d, eta));
    case APPEAR_BSDF_DIELECTRIC_MS: return appear_bsdf_dielectric_ms(appear_dielectric_make(d, eta), r);
    case APPEAR_BSDF_THIN_DIELECTRIC: return appear_bsdf_thin_dielectric(appear_thin_dielectric_make(eta));
#ifdef APPEAR_HAS_SHEEN
    case APPEAR_BSDF_SHEEN: return appear_bsdf_sheen(appear_sheen_make(s0, rough));
#endif
#ifdef APPEAR_HAS_LAYERED
    case APPEAR_BSDF_LAYERED: {
        /* the value refers to its model: one static model, rebuilt by each call (a value is used
           only until the next call); a dielectric coat over a Lambert or a conductor base, a slab
           of adversarial depth, albedo s1 and g; its own draws after the common ones */
        static appear_layered lm;
        int conductor_base = (int)rb_pick(2), depth = (int)rb_pick(24) - 2;
        appear_spectrum tau = rb_spec(0.0f, 3.0f);
        float g = rb_param(-1.0f, 1.0f);
        appear_bsdf top = appear_bsdf_dielectric(appear_dielectric_make(d, eta));
        appear_bsdf base = conductor_base ? appear_bsdf_conductor(appear_conductor_make(d, k0, k1))
                                          : appear_bsdf_lambert(appear_lambert_make(s0));
        appear_slab slab = appear_slab_make(1.0f, tau, s1, g);
        lm = appear_layered_make(&top, &base, slab, 1, depth);
        return appear_bsdf_layered(&lm, r);
    }
#endif
#ifdef APPEAR_HAS_COATED
    case APPEAR_BSDF_COATED: {
        /* the value refers to its model: one static model, rebuilt by each call; a dielectric coat
           (eta as drawn: outside [1, 3] make() rejects it) over a Lambert, EON or conductor base,
           colour s1 (adversarial channels: make() rejects NaN, 0 and > 1), either mode */
        static appear_coated cm;
        int which = (int)rb_pick(3), mode = (int)rb_pick(2);
        appear_bsdf base = which == 0 ? appear_bsdf_lambert(appear_lambert_make(s0))
                         : which == 1 ? appear_bsdf_eon(appear_eon_make(s0, x0))
                                      : appear_bsdf_conductor(appear_conductor_make(d, k0, k1));
        cm = appear_coated_make(appear_dielectric_make(d, eta), &base, s1, mode);
        return appear_bsdf_coated(&cm);
    }
#endif
    default: memset(&b, 0, sizeof b); return b;
    }
}
static appear_phase rb_phase_value(int kind, appear_rng *rng, const appear_phase_table *t,
                                   const appear_fiber *fb)
{
    appear_phase p;
    float g = rb_param(-1.0f, 1.0f);
    /* every draw in a fixed order, before the calls (see rb_bsdf_value) */
    float g2 = rb_param(-1, 1), w = rb_param(0, 1), alpha = rb_param(-1.0f, 10.0f), d = rb_param(0.0f, 50.0f);
    float sxx = rb_param(0, 1), syy = rb_param(0, 1), szz = rb_param(0, 1);
    float sxy = rb_param(-1, 1), sxz = rb_param(-1, 1), syz = rb_param(-1, 1), a = rb_param(0.0f, 1.0f);
    appear_vec3 n = rb_dir();
    int mie = (int)rb_pick(2), keep = rb_pick(8) != 0;
    switch (kind) {
    case APPEAR_PHASE_ISOTROPIC: return appear_phase_isotropic();
    case APPEAR_PHASE_HG: return appear_phase_hg(appear_hg_make(g));
    case APPEAR_PHASE_DHG: return appear_phase_dhg(appear_dhg_make(g, g2, w));
    case APPEAR_PHASE_RAYLEIGH: return appear_phase_rayleigh();
    case APPEAR_PHASE_DRAINE: return appear_phase_draine(appear_draine_make(g, alpha));
    case APPEAR_PHASE_MIE:
        return appear_phase_mie(mie ? appear_mie_make(d) : appear_hg_draine_make(g, g2, alpha, w));
    case APPEAR_PHASE_TABULATED: return appear_phase_tabulated(keep ? t : NULL);
    case APPEAR_PHASE_SGGX_SPECULAR:
        return appear_phase_sggx_specular(appear_sggx_make(sxx, syy, szz, sxy, sxz, syz));
    case APPEAR_PHASE_SGGX_DIFFUSE:
        return appear_phase_sggx_diffuse(appear_sggx_make_surface(n, a), keep ? rng : NULL);
    case APPEAR_PHASE_FIBER: return appear_phase_fiber(keep ? fb : NULL);
    default: memset(&p, 0, sizeof p); return p;
    }
}
static void fam_generic(void)
{
    static appear_phase_table t;
    static const float tv[4] = { 0.3f, 0.1f, 0.5f, 2.0f };
    appear_fiber fb = appear_fiber_make(appear_normalize(appear_vec3_make(0.2f, 0.3f, 0.9f)), 6.0f);
    long i;
    appear_phase_table_make(&t, tv, NULL, 4);
    rb_begin("generic: appear_bsdf, appear_phase (every kind)");
    for (i = 0; i < g_n / 4; ++i) {
        appear_rng rng = appear_rng_make((unsigned)i);
        int bk = (int)rb_pick(APPEAR_BSDF_KIND_COUNT), pk = (int)rb_pick(APPEAR_PHASE_KIND_COUNT);
        appear_bsdf b = rb_bsdf_value(bk, &rng);
        appear_phase p = rb_phase_value(pk, &rng, &t, &fb);
        appear_vec3 wo = rb_dir(), wi = rb_dir();
        appear_bsdf_record s;
        appear_phase_record q;
        float uc = rb_u(), u1 = rb_u(), u2 = rb_u();
        int ok, stochastic = (appear_phase_flags(&p) & APPEAR_MODEL_STOCHASTIC) != 0;
        RB_IN((float)bk, (float)pk, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, uc, u1, u2);
        rb_spec_check("bsdf_eval", appear_bsdf_eval(&b, wo, wi));
        rb_value_check("bsdf_pdf", appear_bsdf_pdf(&b, wo, wi));
        ok = appear_bsdf_sample(&b, wo, uc, u1, u2, &s);
        /* the estimated evals are not compared at the sampled direction; the layered record's
           pdf is an estimate that may be 0 */
        rb_bsdf_check_x("bsdf_sample", ok, &s, &b, wo,
                        appear_bsdf_flags(&b) & APPEAR_MODEL_STOCHASTIC ? 0 : &rb_fns_bsdf,
                        bk == APPEAR_BSDF_LAYERED);
        RB_CHECK(!ok || !(s.flags & ~appear_bsdf_flags(&b)), "bsdf_sample (kind %d): flags %#x outside %#x",
                 bk, s.flags, appear_bsdf_flags(&b));
        rb_value_check("phase_eval", appear_phase_eval(&p, wo, wi));
        rb_value_check("phase_pdf", appear_phase_pdf(&p, wo, wi));
        ok = appear_phase_sample(&p, wo, uc, u1, u2, &q);
        rb_phase_check_x("phase_sample", ok, &q, stochastic);
        RB_CHECK(!ok || !(q.flags & ~appear_phase_flags(&p)), "phase_sample (kind %d): flags %#x outside %#x",
                 pk, q.flags, appear_phase_flags(&p));
    }
}
#endif

#ifdef APPEAR_HAS_OPENPBR
RB_ADAPT(openpbr, appear_openpbr)
/* OpenPBR Surface (SECTION openpbr): every parameter ordinary, at or 1-2 ulp beyond its range's
   ends, or adversarial (NaN, +-Inf, denormals, huge), thin-walled or not; make() is invalid
   exactly when a parameter is NaN or infinite or an unsupported mode is on (checked on the
   bits), and then every call answers 0 / failure; eval, pdf, emission finite and >= 0, samples
   checked as every BSDF's (records against eval() and pdf()) */
static float rb_op(float lo, float hi, int *finite)
{
    float x = rb_param(lo, hi);
    *finite &= rb_finite(x);
    return x;
}
static appear_spectrum rb_op_s(float lo, float hi, int *finite)
{
    appear_spectrum c;
    int k;
    for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) c.v[k] = rb_op(lo, hi, finite);
    return c;
}
static void fam_openpbr(void)
{
    long i;
    rb_begin("openpbr: make, eval, pdf, sample, emission");
    for (i = 0; i < g_n / 4; ++i) {
        appear_openpbr_params p = appear_openpbr_params_default();
        appear_openpbr m;
        appear_bsdf_record s;
        int fin = 1, unsup, want, ok;
        int clean = (int)rb_pick(2); /* half the models: only the weights drawn, the rest default */
        p.base_weight = rb_op(0.0f, 1.0f, &fin);
        p.base_metalness = rb_op(0.0f, 1.0f, &fin);
        p.coat_weight = rb_op(0.0f, 1.0f, &fin);
        p.fuzz_weight = rb_op(0.0f, 1.0f, &fin);
        p.specular_weight = rb_op(0.0f, 2.0f, &fin);
        p.subsurface_weight = rb_op(0.0f, 1.0f, &fin);
        if (!clean) {
            p.base_color = rb_op_s(0.0f, 1.0f, &fin);
            p.base_diffuse_roughness = rb_op(0.0f, 1.0f, &fin);
            p.specular_color = rb_op_s(0.0f, 1.0f, &fin);
            p.specular_roughness = rb_op(0.0f, 1.0f, &fin);
            p.specular_roughness_anisotropy = rb_op(0.0f, 1.0f, &fin);
            p.specular_ior = rb_op(1.0f, 3.0f, &fin);
            p.subsurface_color = rb_op_s(0.0f, 1.0f, &fin);
            p.subsurface_radius = rb_op(0.0f, 10.0f, &fin);
            p.subsurface_radius_scale = rb_op_s(0.0f, 1.0f, &fin);
            p.subsurface_scatter_anisotropy = rb_op(-1.0f, 1.0f, &fin);
            p.coat_color = rb_op_s(0.0f, 1.0f, &fin);
            p.coat_roughness = rb_op(0.0f, 1.0f, &fin);
            p.coat_roughness_anisotropy = rb_op(0.0f, 1.0f, &fin);
            p.coat_ior = rb_op(1.0f, 3.0f, &fin);
            p.coat_darkening = rb_op(0.0f, 1.0f, &fin);
            p.fuzz_color = rb_op_s(0.0f, 1.0f, &fin);
            p.fuzz_roughness = rb_op(0.0f, 1.0f, &fin);
            p.emission_luminance = rb_op(0.0f, 1000.0f, &fin);
            p.emission_color = rb_op_s(0.0f, 1.0f, &fin);
            p.geometry_opacity = rb_op(0.0f, 1.0f, &fin);
            p.transmission_weight = rb_pick(3) ? 0.0f : rb_op(0.0f, 1.0f, &fin);
            p.transmission_color = rb_op_s(0.0f, 1.0f, &fin);
            p.transmission_depth = rb_pick(2) ? 0.0f : rb_op(0.0f, 10.0f, &fin);
            p.transmission_scatter = rb_op_s(0.0f, 1.0f, &fin);
            p.transmission_scatter_anisotropy = rb_op(-1.0f, 1.0f, &fin);
            p.transmission_dispersion_scale = rb_op(0.0f, 1.0f, &fin);
            p.transmission_dispersion_abbe_number = rb_op(9.0f, 91.0f, &fin);
            p.thin_film_weight = rb_pick(4) ? 0.0f : rb_op(0.0f, 1.0f, &fin);
            p.thin_film_thickness = rb_op(0.0f, 2.0f, &fin); /* micrometres */
            p.thin_film_ior = rb_op(1.0f, 3.0f, &fin);
            p.geometry_thin_walled = rb_pick(4) == 0;
        }
        if (rb_pick(4) == 0) { /* a spectral make: wavelengths adversarial too (NaN: n_d, clamped to the range) */
            float lam[APPEAR_SPECTRUM_SAMPLES];
            int k, lfin = 1;
            for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) lam[k] = rb_op(360.0f, 830.0f, &lfin);
            m = appear_openpbr_make_spectral(&p, lam);
        } else
            m = appear_openpbr_make(&p);
#ifdef APPEAR_HAS_THINFILM
        unsup = 0;
#else
        /* unsupported without SECTION thinfilm: a film weight > 0 (a finite one clamps into [0, 1];
           NaN is caught by fin) */
        unsup = rb_finite(p.thin_film_weight) && p.thin_film_weight > 0.0f;
#endif
        want = fin && !unsup;
        RB_CHECK(m.valid == want, "openpbr_make: valid %d, expected %d (finite %d, unsupported %d)", m.valid, want,
                 fin, unsup);
        {
            appear_vec3 wo = rb_dir(), wi = rb_dir();
            float uc = rb_u(), u1 = rb_u(), u2 = rb_u(); /* in this order */
            RB_IN(wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, uc, u1, u2);
            /* lobes sharper than alpha 1e-3 (roughness 0.032): their records are counted */
            g_sharp = !(p.specular_roughness >= 0.04f && (p.coat_roughness == 0.0f || p.coat_roughness >= 0.04f));
            rb_spec_check("openpbr_eval", appear_openpbr_eval(&m, wo, wi));
            rb_value_check("openpbr_pdf", appear_openpbr_pdf(&m, wo, wi));
            rb_spec_check("openpbr_emission", appear_openpbr_emission(&m, wo));
            rb_value_check("openpbr_opacity", appear_openpbr_opacity(&m));
            {
                appear_spectrum sig, alb;
                float g;
                int has = appear_openpbr_medium(&m, &sig, &alb, &g);
                rb_openpbr_medium_check("openpbr_medium", has, sig, alb, g);
                has = appear_openpbr_subsurface(&m, &sig, &alb, &g);
                rb_openpbr_medium_check("openpbr_subsurface", has, sig, alb, g);
            }
            ok = appear_openpbr_sample(&m, wo, uc, u1, u2, &s);
            rb_bsdf_check("openpbr_sample", ok, &s, &m, wo, &rb_fns_openpbr);
            RB_CHECK(!ok || !(s.flags & ~(appear_openpbr_flags(&m) |
                                          (appear_openpbr_terminates_secondary(&m)
                                               ? (unsigned)APPEAR_SAMPLE_TERMINATE_SECONDARY : 0u))),
                     "openpbr_sample: flags %#x outside %#x", s.flags, appear_openpbr_flags(&m));
            RB_CHECK(m.valid || (!ok && rb_spec_zero(appear_openpbr_eval(&m, wo, wi)) &&
                                 rb_zero(appear_openpbr_pdf(&m, wo, wi))),
                     "openpbr: an invalid model answered (sample %d)", ok);
            g_sharp = 0;
        }
    }
}
#endif

#if defined(APPEAR_HAS_LAYERED) && defined(APPEAR_HAS_MULTISCATTER) && defined(APPEAR_HAS_LAMBERT)
#define RB_HAS_LAYERED 1
/* the layered reference (SECTION layered): make() on adversarial parts and slabs (tau NaN, +-Inf,
   negative, huge; albedo and g outside their ranges, 1 or 2 ulp out; invalid and zero parts;
   samples and max_depth < 1), then eval, pdf and sample on adversarial directions: make()'s
   verdict is the one its contract names (checked on the bits), an invalid model or a NULL rng
   answers 0 / failure, values are finite and >= 0, a failed sample is zeroed, a successful one
   has a unit wi and flags within the model's (its pdf is an estimate that may be 0, f then 0).
   The parts: a dielectric (rough or smooth), compensated or thin coat, a Lambert or zero top;
   a Lambert, conductor, dielectric (transmitting), random-walk dielectric, zero or layered base
   (a static model: the base refers to it). Half of the iterations draw every parameter inside
   its domain (so that most of those models are valid and their walks run), half adversarial.
   g_n / 8 iterations: each call runs up to samples x max_depth events. */
static int rb_slab_ok(appear_slab s)
{
    int i, ok = (rb_bits(s.g) & 0x7fffffffu) <= 0x3f800000u;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) {
        uint32_t t = rb_bits(s.tau.v[i]), a = rb_bits(s.albedo.v[i]);
        ok &= (t < 0x7f800000u || t == 0x80000000u) && (a <= 0x3f800000u || a == 0x80000000u);
    }
    return ok;
}
/* a spectrum uniform in [lo, hi) per channel (a valid parameter) */
static appear_spectrum rb_spec_in(float lo, float hi)
{
    appear_spectrum s; int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) s.v[i] = lo + (hi - lo) * rb_uniform();
    return s;
}
static void fam_layered(void)
{
    static appear_layered inner; /* the layered base refers to it */
    long i;
    rb_begin("layered: make, eval, pdf, sample");
    for (i = 0; i < g_n / 8; ++i) {
        appear_rng rng = appear_rng_make((unsigned)i);
        /* every draw in a fixed order, before the calls */
        int tk = (int)rb_pick(6), bk = (int)rb_pick(7), sk = (int)rb_pick(4), clean = (int)rb_pick(2);
        int dt = (int)rb_pick(2);
        float ca = rb_pick(4) ? rb_uniform() : 0.0f;
        appear_microfacet d = clean ? appear_microfacet_make(dt, ca, ca, APPEAR_SAMPLE_VISIBLE) : rb_microfacet();
        float eta = clean ? 1.05f + 1.5f * rb_uniform() : rb_param(1.0f / 2.4f, 2.4f);
        appear_spectrum c0 = clean ? rb_spec_in(0.0f, 1.0f) : rb_spec(0.0f, 1.0f);
        appear_spectrum c1 = clean ? rb_spec_in(0.0f, 1.0f) : rb_spec(0.0f, 1.0f);
        appear_spectrum tau = clean ? rb_spec_in(0.0f, 3.0f) : sk == 3 ? rb_spec(0.0f, 10.0f) : rb_spec(0.0f, 3.0f);
        appear_spectrum alb = clean ? rb_spec_in(0.0f, 1.0f) : rb_spec(0.0f, 1.0f);
        float g = clean ? 2.0f * rb_uniform() - 1.0f : rb_param(-1.0f, 1.0f);
        float thick = clean ? rb_uniform() : rb_param(0.0f, 2.0f);
        int samples = rb_pick(8) ? 1 + (int)rb_pick(3) : -(int)rb_pick(3);
        int depth = rb_pick(8) ? 1 + (int)rb_pick(32) : 1 - (int)rb_pick(3);
        int null_rng = rb_pick(16) == 0;
        appear_vec3 wo = rb_dir(), wi = rb_dir();
        appear_rng *rp = null_rng ? NULL : &rng;
        appear_bsdf top, base, gv;
        appear_slab slab;
        appear_layered m;
        appear_spectrum f;
        appear_bsdf_record s;
        unsigned fl;
        float p;
        int ok, valid;
        switch (tk) {
        case 0: top = appear_bsdf_dielectric(appear_dielectric_make(d, eta)); break;
        case 1: top = appear_bsdf_dielectric_comp(appear_dielectric_make(d, eta)); break;
        case 2: top = appear_bsdf_thin_dielectric(appear_thin_dielectric_make(eta)); break;
        case 3: top = appear_bsdf_lambert(appear_lambert_make(c0)); break;
        case 4: memset(&top, 0, sizeof top); break;
        default: top = appear_bsdf_dielectric(appear_dielectric_make(
                     appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f, APPEAR_SAMPLE_VISIBLE), eta)); break;
        }
        switch (bk) {
        case 0: base = appear_bsdf_lambert(appear_lambert_make(c1)); break;
        case 1: base = appear_bsdf_conductor(appear_conductor_make_reflectance(d, c1)); break;
        case 2: base = appear_bsdf_dielectric(appear_dielectric_make(d, 1.0f / eta)); break;
        case 3: base = appear_bsdf_dielectric_ms(appear_dielectric_make(d, 1.0f / eta), rp); break;
        case 4: memset(&base, 0, sizeof base); break;
        case 5: { /* a smooth coat over Lambert c1, as the base */
            appear_bsdf t2 = appear_bsdf_dielectric(appear_dielectric_make(
                appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f, APPEAR_SAMPLE_VISIBLE), 1.3f));
            appear_bsdf b2 = appear_bsdf_lambert(appear_lambert_make(c1));
            inner = appear_layered_make(&t2, &b2, appear_slab_none(), 1, 8);
            base = appear_bsdf_layered(&inner, rp);
        } break;
        default: base = appear_bsdf_lambert(appear_lambert_make(c1)); break;
        }
        switch (sk) {
        case 0: slab = appear_slab_none(); break;
        case 1: slab = appear_slab_make(thick, tau, alb, g); break;
        case 2: slab = appear_slab_from_transmittance(c0, alb, g); break;
        default: slab.tau = tau; slab.albedo = alb; slab.g = g; break;
        }
        RB_IN((float)tk, (float)bk, (float)sk, slab.tau.v[0], slab.tau.v[1], slab.tau.v[2], slab.albedo.v[0],
              slab.g, (float)samples, (float)depth, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z);
        m = appear_layered_make(&top, &base, slab, samples, depth);
        fl = appear_layered_flags(&m);
        valid = top.flags != 0u && base.flags != 0u && rb_slab_ok(slab);
        RB_CHECK(m.valid == valid && (fl != 0u) == valid && m.samples >= 1 && m.max_depth >= 1,
                 "layered_make: valid %d (expected %d), flags %#x, samples %d, max_depth %d", m.valid, valid, fl,
                 m.samples, m.max_depth);
        gv = appear_bsdf_layered(&m, rp);
        RB_CHECK(appear_bsdf_flags(&gv) == (null_rng ? 0u : fl), "bsdf_layered: flags %#x, model %#x, rng %d",
                 appear_bsdf_flags(&gv), fl, !null_rng);
        f = appear_layered_eval(&m, wo, wi, rp);
        rb_spec_check("layered_eval", f);
        p = appear_layered_pdf(&m, wo, wi, rp);
        rb_value_check("layered_pdf", p);
        ok = appear_layered_sample(&m, wo, rp, &s);
        rb_bsdf_check_x("layered_sample", ok, &s, &m, wo, 0, 1);
        RB_CHECK(!ok || !(s.flags & ~fl), "layered_sample: flags %#x outside the model's %#x", s.flags, fl);
        RB_CHECK((valid && !null_rng) || (rb_spec_zero(f) && rb_zero(p) && !ok),
                 "layered: an invalid model or a NULL rng answered f %a pdf %a ok %d", (double)f.v[0], (double)p, ok);
        /* the generic verbs on the same model */
        rb_spec_check("bsdf_eval (layered)", appear_bsdf_eval(&gv, wo, wi));
        rb_value_check("bsdf_pdf (layered)", appear_bsdf_pdf(&gv, wo, wi));
        ok = appear_bsdf_sample(&gv, wo, 0.5f, 0.5f, 0.5f, &s);
        rb_bsdf_check_x("bsdf_sample (layered)", ok, &s, &gv, wo, 0, 1);
    }
}
#endif

static const rb_family rb_families[] = {
    { "core", fam_core },
#ifndef APPEAR_NO_LAMBERT
    { "lambert", fam_lambert },
#endif
#ifndef APPEAR_NO_EON
    { "eon", fam_eon },
#endif
#ifndef APPEAR_NO_SHEEN
    { "sheen", fam_sheen },
#endif
#ifndef APPEAR_NO_PHASE
    { "phase", fam_phase },
#endif
#ifndef APPEAR_NO_WARD
    { "ward", fam_ward },
#endif
#ifndef APPEAR_NO_MICROFACET
    { "microfacet_blocks", fam_microfacet_blocks },
    { "microfacet_models", fam_microfacet_models },
#endif
#ifndef APPEAR_NO_MEDIA
    { "media", fam_media },
    { "media_chromatic", fam_media_chromatic },
#endif
#if !defined(APPEAR_NO_FLAKES) || !defined(APPEAR_NO_PHASE_EXTRA)
    { "flakes", fam_flakes }, /* SGGX and fiber flakes, and the phase_extra part */
#endif
    { "batch", fam_batch },
    { "extremes", fam_extremes }, /* issue 34, items 9-12 */
#ifndef APPEAR_NO_MATERIALS
    { "materials", fam_materials },
#endif
#ifdef RB_HAS_GENERIC
    { "generic", fam_generic },
#endif
#ifdef RB_HAS_LAYERED
    { "layered", fam_layered },
#endif
#ifdef APPEAR_HAS_OPENPBR
    { "openpbr", fam_openpbr },
#endif
};
enum { RB_NFAM = (int)(sizeof rb_families / sizeof rb_families[0]) };

#ifndef RB_FUZZ
int main(int argc, char **argv)
{
    int k, failed = 0;
    long total = 0;
    g_n = argc > 1 ? atol(argv[1]) : 200000;
    for (k = 0; k < RB_NFAM; ++k) {
        int a, run = argc < 3;
        for (a = 2; a < argc; ++a) run |= strcmp(argv[a], rb_families[k].name) == 0;
        if (run) rb_families[k].run();
    }
    for (k = 0; k < g_ngroups; ++k) {
        rb_group *g = &g_groups[k];
        total += g->calls;
        if (g->bad) printf("FAIL robust %s: %ld of %ld checks violated; first: %s\n", g->name, g->bad, g->calls, g->first);
        else printf("ok   robust %s: %ld checks\n", g->name, g->calls);
        failed += g->bad != 0;
    }
    for (k = 0; k < g_nbstat; ++k)
        if (g_bstat[k].differ)
            printf("batch vs scalar %s: %ld of %ld elements differ in bits; %ld in success or a zero;"
                   " largest relative difference of values elsewhere %.3g, of direction components %.3g;"
                   " degenerate: %ld flips, %.3g, %.3g\n",
                   g_bstat[k].name, g_bstat[k].differ, g_bstat[k].n, g_bstat[k].flip, g_bstat[k].rel, g_bstat[k].dir,
                   g_bstat[k].dflip, g_bstat[k].drel, g_bstat[k].ddir);
    for (k = 0; k < g_nbstat; ++k) {
        if (g_bstat[k].rel > 0) printf("batch vs scalar %s: largest value difference at %s\n", g_bstat[k].name, g_bstat[k].worst);
        if (g_bstat[k].dir > 0) printf("batch vs scalar %s: largest direction difference at %s\n", g_bstat[k].name, g_bstat[k].wdir);
    }
    for (k = 0; k < g_nbstat; ++k)
        if (g_bstat[k].flip1[0]) printf("batch vs scalar %s: first flip at %s\n", g_bstat[k].name, g_bstat[k].flip1);
    if (g_soft) printf("note: %ld sampled directions (of all BSDF samples) have pdf() = 0 in this -ffast-math build\n", g_soft);
    if (g_soft_consist)
        printf("note: %ld consistency checks (record vs eval/pdf, batch vs scalar) differ, counted only"
               " (-ffast-math, or lobes sharper than alpha 1e-3); the first: %s\n", g_soft_consist, g_soft_first);
    printf("robust (%s): %ld checks; %d passed, %d failed\n",
#ifdef __FAST_MATH__
           "-ffast-math",
#else
           "IEEE",
#endif
           total, g_ngroups - failed, failed);
    return failed != 0;
}
#endif /* !RB_FUZZ */
