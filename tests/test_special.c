/* tests/test_special.c - accuracy of appear.h's own special functions
   (section "Special functions") against double libm, over dense sweeps of
   each whole domain: a sweep over the float bit patterns (log-uniform, so
   every binade from the subnormals to the top is visited) plus a uniform
   grid in value, plus the special inputs of each documented contract.
   Each function's maximum error is reported with h_measure and asserted
   against the bound stated in its comment in appear.h (the constants
   below must stay equal to those comments). */
#include "harness.h"
#include <math.h>
#include <string.h>

/* Stated bounds (keep in sync with appear.h). */
#define B_SINCOS_ABS  1.5e-7   /* abs error of sin, cos(2 pi u) */
#define B_EXP_REL     2.5e-7   /* rel, results >= FLT_MIN */
#define B_EXP_SUBABS  1.5e-45  /* abs, subnormal results (1 subnormal ulp) */
#define B_LOG_REL     2.0e-7   /* rel, all positive floats */
#define B_POW_REL0    3.0e-7   /* rel <= B_POW_REL0 + B_POW_REL1 |y ln x| */
#define B_POW_REL1    2.5e-7
#define B_ERF_REL     3.0e-7   /* |x| <= 1 */
#define B_ERF_ABS     1.5e-7   /* all x */
#define B_ERFC_REL    6.0e-7   /* results >= FLT_MIN */
#define B_ERFINV_REL  4.0e-7   /* all floats in (-1, 1) */
#define B_ATAN2_ABS   3.5e-7
#define B_ATAN2_REL   3.5e-7
#define B_CBRT_REL    2.5e-7

static float f_from_bits(unsigned int u) { float f; memcpy(&f, &u, 4); return f; }
static unsigned int bits_of(float f) { unsigned int u; memcpy(&u, &f, 4); return u; }
static int is_nan(float x) { return x != x; }

typedef struct { double max_rel, max_abs, at_rel, at_abs; long n; } acc;
static void acc_init(acc *a) { memset(a, 0, sizeof *a); }
/* relative error where |ref| >= rel_floor, absolute error everywhere */
static void acc_add(acc *a, double x, double got, double ref, double rel_floor)
{
    double e = fabs(got - ref);
    if (!(e <= a->max_abs)) { a->max_abs = e; a->at_abs = x; }
    if (fabs(ref) >= rel_floor) {
        double r = e / fabs(ref);
        if (!(r <= a->max_rel)) { a->max_rel = r; a->at_rel = x; }
    }
    a->n++;
}

/* visit ~n floats: bit-pattern stride over [lo, hi] (lo >= 0) */
#define SWEEP_BITS(lo, hi, n, ...) do { \
    unsigned int b0_ = bits_of(lo), b1_ = bits_of(hi), st_, b_; \
    st_ = (unsigned int)((b1_ - b0_) / (unsigned long)(n)); if (st_ < 1) st_ = 1; \
    for (b_ = b0_; b_ <= b1_ && b_ >= b0_; b_ += st_) { float x = f_from_bits(b_); __VA_ARGS__; } \
    { float x = (hi); __VA_ARGS__; } } while (0)
/* visit n+1 floats uniformly spaced in value over [lo, hi] */
#define SWEEP_LIN(lo, hi, n, ...) do { long i_; for (i_ = 0; i_ <= (long)(n); ++i_) { \
    float x = (float)((lo) + ((double)(hi) - (lo)) * (double)i_ / (double)(n)); __VA_ARGS__; } } while (0)

static void test_sincos(void)
{
    acc a; long n = h_n(1L << 23), differ = 0;
    h_case("special: sincos_2pi vs double sin/cos; scalar form == lanes form, bit for bit");
    acc_init(&a);
    SWEEP_LIN(0.0, 1.0, n, {
        float s, c; double t = 6.283185307179586 * (double)x;
        appear_sincos_2pi(x, &s, &c);
        acc_add(&a, x, s, sin(t), 1e-3); acc_add(&a, x, c, cos(t), 1e-3);
        { float s1, c1; appear__sincos_2pi(x, &s1, &c1); differ += (bits_of(s) != bits_of(s1)) | (bits_of(c) != bits_of(c1)); } });
    SWEEP_BITS(1e-30f, 4194304.0f, n, {
        float s, c; double fr = (double)x - floor((double)x), t = 6.283185307179586 * fr;
        appear_sincos_2pi(x, &s, &c);  acc_add(&a, x, s, sin(t), 1e-3); acc_add(&a, x, c, cos(t), 1e-3);
        { float s1, c1; appear__sincos_2pi(x, &s1, &c1); differ += (bits_of(s) != bits_of(s1)) | (bits_of(c) != bits_of(c1)); }
        appear_sincos_2pi(-x, &s, &c); acc_add(&a, -x, s, -sin(t), 1e-3); acc_add(&a, -x, c, cos(t), 1e-3); });
    h_measure("special sincos_2pi", "max abs %.3g at u=%.9g, max rel %.3g (|ref|>=1e-3) at u=%.9g, n=%ld",
              a.max_abs, a.at_abs, a.max_rel, a.at_rel, a.n);
    H_CHECK(a.max_abs <= B_SINCOS_ABS, "sincos abs err %g > %g at u=%.9g", a.max_abs, B_SINCOS_ABS, a.at_abs);
    H_CHECK(differ == 0, "%ld inputs differ between the scalar and the lanes sincos", differ);
    {   /* specials: NaN, Inf, huge give (0, 1); exact quarters */
        const float sp[] = { f_from_bits(0x7fc00000u), f_from_bits(0x7f800000u), -f_from_bits(0x7f800000u), 1e30f };
        int i; float s, c;
        for (i = 0; i < 4; ++i) { appear_sincos_2pi(sp[i], &s, &c);
            H_CHECK(s == 0.0f && c == 1.0f, "sincos(%g) = (%g, %g), want (0, 1)", sp[i], s, c); }
        appear_sincos_2pi(0.25f, &s, &c); H_CHECK(s == 1.0f && fabsf(c) <= 1e-7f, "sincos(1/4) = (%g,%g)", s, c);
        appear_sincos_2pi(0.5f, &s, &c);  H_CHECK(fabsf(s) <= 1e-7f && c == -1.0f, "sincos(1/2) = (%g,%g)", s, c);
    }
}

/* appear__sincos_pi (the half-angle pair of the GGX caps sampler): s^2, s c
   and c^2 against sin^2, sin cos, cos^2 of pi u in double (the common sign
   is free), s relative where |sin| >= 1e-3, both `lanes` modes bit-equal. */
static void test_sincos_pi(void)
{
    acc a, r; long n = h_n(1L << 22), differ = 0;
    h_case("special: sincos_pi (half-angle pair) vs double, both lanes modes");
    acc_init(&a); acc_init(&r);
#define SCP_BODY { float s, c, s1, c1; double fr = (double)x - floor((double)x), t = 3.141592653589793 * fr; \
        double S = sin(t), C = cos(t); \
        appear__sincos_pi(APPEAR__SCALAR, x, &s, &c); appear__sincos_pi(APPEAR__LANES, x, &s1, &c1); \
        differ += bits_of(s) != bits_of(s1) || bits_of(c) != bits_of(c1); \
        acc_add(&a, x, (double)s * s, S * S, 1e300); acc_add(&a, x, (double)s * c, S * C, 1e300); \
        acc_add(&a, x, (double)c * c, C * C, 1e300); acc_add(&r, x, fabs((double)s), fabs(S), 1e-3); }
    SWEEP_LIN(0.0, 1.0, n, SCP_BODY);
    SWEEP_BITS(1e-30f, 4194304.0f, n, SCP_BODY);
    SWEEP_BITS(1e-30f, 4194304.0f, n, { x = -x; SCP_BODY; });
#undef SCP_BODY
    h_measure("special sincos_pi", "max abs err of s^2, sc, c^2 %.3g at u=%.9g; max rel err of |s| %.3g at u=%.9g; n=%ld",
              a.max_abs, a.at_abs, r.max_rel, r.at_rel, a.n / 3);
    H_CHECK(a.max_abs <= 5e-7, "sincos_pi products abs err %g at u=%.9g", a.max_abs, a.at_abs);
    H_CHECK(r.max_rel <= 3e-7, "sincos_pi |s| rel err %g at u=%.9g", r.max_rel, r.at_rel);
    H_CHECK(differ == 0, "%ld inputs differ between lanes 0 and 1", differ);
    {   /* NaN, Inf, huge -> (0, 1) */
        const float sp[] = { f_from_bits(0x7fc00000u), f_from_bits(0x7f800000u), -f_from_bits(0x7f800000u), 1e30f, -1e30f };
        int i; float s, c;
        for (i = 0; i < 5; ++i) { appear__sincos_pi(APPEAR__COMMON, sp[i], &s, &c);
            H_CHECK(s == 0.0f && c == 1.0f, "sincos_pi(%g) = (%g, %g), want (0, 1)", sp[i], s, c); }
    }
}

static void test_exp(void)
{
    acc a, sub; long n = h_n(1L << 22), differ = 0; float inf = f_from_bits(0x7f800000u);
    h_case("special: exp vs double exp; scalar form (branches) == lanes form (selects), bit for bit");
    acc_init(&a); acc_init(&sub);
#define EXP_BODY { double r = exp((double)x); float g = appear__exp(x); \
        differ += bits_of(g) != bits_of(appear__exp_s(x)) || bits_of(appear__media_exp(x)) != bits_of(appear__media_exp_m(1, x)); \
        if (r >= 1.1754943508222875e-38) acc_add(&a, x, g, r, 0.0); else acc_add(&sub, x, g, r, 1e300); }
    SWEEP_BITS(0.0f, 88.72f, n, EXP_BODY);
    SWEEP_BITS(0.0f, 104.0f, n, { x = -x; EXP_BODY; });
    SWEEP_LIN(-104.0, 88.72, n, EXP_BODY);
    h_measure("special exp", "max rel %.3g at x=%.9g; subnormal results max abs %.3g at x=%.9g; n=%ld",
              a.max_rel, a.at_rel, sub.max_abs, sub.at_abs, a.n + sub.n);
    H_CHECK(a.max_rel <= B_EXP_REL, "exp rel err %g > %g at x=%.9g", a.max_rel, B_EXP_REL, a.at_rel);
    H_CHECK(sub.max_abs <= B_EXP_SUBABS, "exp subnormal abs err %g at x=%.9g", sub.max_abs, sub.at_abs);
    H_CHECK(appear__exp(0.0f) == 1.0f, "exp(0) = %.9g", appear__exp(0.0f));
    H_CHECK(appear__exp(-inf) == 0.0f && appear__exp(-200.0f) == 0.0f, "exp(-Inf), exp(-200) not 0");
    H_CHECK(h_finite(appear__exp(inf)) && appear__exp(inf) > 3.3e38f, "exp(+Inf) = %g, want saturation", appear__exp(inf));
    H_CHECK(appear__exp(89.0f) == appear__exp(88.72f) && h_finite(appear__exp(1e30f)), "exp saturation");
    H_CHECK(is_nan(appear__exp(f_from_bits(0x7fc00000u))), "exp(NaN) not NaN");
    {   /* the clamps, on both paths */
        const float sp[] = { -104.0f, -103.9f, -103.8f, 88.6f, 88.7f, 88.72f, 89.0f, 1e30f, -1e30f, inf, -inf,
                             f_from_bits(0x7fc00000u), f_from_bits(0xffc00000u), 0.0f, -0.0f, 1e-45f, -1e-45f };
        int i;
        for (i = 0; i < (int)(sizeof sp / sizeof sp[0]); ++i) {
            float x = sp[i];
            differ += bits_of(appear__exp(x)) != bits_of(appear__exp_s(x));
            differ += bits_of(appear__media_exp(x)) != bits_of(appear__media_exp_m(1, x));
        }
    }
    H_CHECK(differ == 0, "%ld inputs differ between the scalar and the lanes exp", differ);
}

static void test_log(void)
{
    acc a; long n = h_n(1L << 23), differ = 0; float inf = f_from_bits(0x7f800000u);
    h_case("special: log vs double log; scalar form (branches) == lanes form (selects), bit for bit");
    acc_init(&a);
#define LOG_BODY { double r = log((double)x); float g = appear__log(x); \
        differ += bits_of(g) != bits_of(appear__log_s(x)); acc_add(&a, x, g, r, 0.0); }
    SWEEP_BITS(f_from_bits(1u), 3.4028235e38f, n, LOG_BODY);
    SWEEP_LIN(0.5, 2.0, n, LOG_BODY);
    h_measure("special log", "max rel %.3g at x=%.9g, max abs %.3g at x=%.9g, n=%ld",
              a.max_rel, a.at_rel, a.max_abs, a.at_abs, a.n);
    H_CHECK(a.max_rel <= B_LOG_REL, "log rel err %g > %g at x=%.9g", a.max_rel, B_LOG_REL, a.at_rel);
    H_CHECK(appear__log(1.0f) == 0.0f, "log(1) = %g", appear__log(1.0f));
    H_CHECK(appear__log(0.0f) == -inf && appear__log(-0.0f) == -inf, "log(0) not -Inf");
    H_CHECK(appear__log(inf) == inf, "log(Inf) = %g", appear__log(inf));
    H_CHECK(is_nan(appear__log(-1.0f)) && is_nan(appear__log(-inf)) && is_nan(appear__log(f_from_bits(0x7fc00000u))),
            "log(<0 or NaN) not NaN");
    {
        const float sp[] = { 0.0f, -0.0f, -1.0f, inf, -inf, f_from_bits(0x7fc00000u), f_from_bits(0xffc00000u),
                             f_from_bits(1u), f_from_bits(0x007fffffu), f_from_bits(0x00800000u), 3.4028235e38f };
        int i;
        for (i = 0; i < (int)(sizeof sp / sizeof sp[0]); ++i)
            differ += bits_of(appear__log(sp[i])) != bits_of(appear__log_s(sp[i]));
    }
    H_CHECK(differ == 0, "%ld inputs differ between the scalar and the lanes log", differ);
}

static void test_pow(void)
{
    acc a; long n = h_n(1L << 22), i; h_rng rng = h_rng_make(9); double worst = 0; float wx = 0, wy = 0;
    float inf = f_from_bits(0x7f800000u);
    h_case("special: pow vs double pow");
    acc_init(&a);
    for (i = 0; i < n; ++i) {
        /* x log-uniform over all positive floats, y uniform in [-8, 8] and
           log-uniform in magnitude; keep |y ln x| <= 87 (no overflow) */
        float x = f_from_bits(1u + (unsigned int)(h_rand(&rng) * 2139095038.0));
        double us = h_rand(&rng), um = h_rand(&rng); /* in this order */
        float y = (i & 1) ? (float)(16.0 * us - 8.0) : (float)((us < 0.5 ? -1 : 1) * pow(2.0, 40.0 * um - 30.0));
        double t = (double)y * log((double)x), r, g, rel;
        if (fabs(t) > 87.0) continue;
        r = exp(t); g = appear__pow(x, y);
        rel = fabs(g - r) / r;
        acc_add(&a, x, g, r, 0.0);
        rel = rel / (B_POW_REL0 + B_POW_REL1 * fabs(t));
        if (rel > worst) { worst = rel; wx = x; wy = y; }
    }
    h_measure("special pow", "max rel %.3g; max of rel/(%.2g + %.2g |y ln x|) = %.3g at x=%.9g y=%.9g; n=%ld",
              a.max_rel, B_POW_REL0, B_POW_REL1, worst, wx, wy, a.n);
    H_CHECK(worst <= 1.0, "pow error over bound by %g at x=%.9g y=%.9g", worst, wx, wy);
    H_CHECK(appear__pow(0.0f, 2.0f) == 0.0f && appear__pow(0.0f, 0.0f) == 1.0f && appear__pow(inf, 0.0f) == 1.0f
            && appear__pow(f_from_bits(0x7fc00000u), 0.0f) == 1.0f, "pow zero cases");
    H_CHECK(h_finite(appear__pow(0.0f, -1.0f)) && h_finite(appear__pow(inf, 1.0f)) && appear__pow(inf, -1.0f) == 0.0f,
            "pow saturation cases");
    H_CHECK(is_nan(appear__pow(-2.0f, 2.0f)), "pow(-2, 2) not NaN (documented)");
}

static void test_erf(void)
{
    acc a, b; long n = h_n(1L << 22); float inf = f_from_bits(0x7f800000u);
    h_case("special: erf and erfc vs double");
    acc_init(&a); acc_init(&b);
#define ERF_BODY { double r = erf((double)x); float g = appear__erf(x), gm = appear__erf(-x); \
        acc_add(&a, x, g, r, fabs(x) <= 1.0f ? 0.0 : 1e300); \
        H_CHECK(gm == -g, "erf not odd at %.9g", x); }
    SWEEP_BITS(f_from_bits(1u), 12.0f, n, ERF_BODY);
    SWEEP_LIN(0.0, 6.0, n, ERF_BODY);
    h_measure("special erf", "max rel %.3g (|x|<=1) at x=%.9g, max abs %.3g at x=%.9g, n=%ld",
              a.max_rel, a.at_rel, a.max_abs, a.at_abs, a.n);
    H_CHECK(a.max_rel <= B_ERF_REL, "erf rel err %g at x=%.9g", a.max_rel, a.at_rel);
    H_CHECK(a.max_abs <= B_ERF_ABS, "erf abs err %g at x=%.9g", a.max_abs, a.at_abs);
    H_CHECK(appear__erf(inf) == 1.0f && appear__erf(-inf) == -1.0f && appear__erf(0.0f) == 0.0f, "erf(+-Inf, 0)");
    H_CHECK(is_nan(appear__erf(f_from_bits(0x7fc00000u))), "erf(NaN) not NaN");
#define ERFC_BODY { double r = erfc((double)x); float g = appear__erfc(x); \
        if (r >= 1.1754943508222875e-38) acc_add(&b, x, g, r, 0.0); \
        else H_CHECK(fabs(g - r) <= 1.5e-45 + B_ERFC_REL * r, "erfc(%.9g) = %g, want %g", x, g, r); }
    SWEEP_BITS(f_from_bits(1u), 10.2f, n, ERFC_BODY);
    SWEEP_BITS(f_from_bits(1u), 12.0f, n, { x = -x; ERFC_BODY; });
    SWEEP_LIN(-6.0, 10.2, n, ERFC_BODY);
    h_measure("special erfc", "max rel %.3g at x=%.9g (results >= FLT_MIN), n=%ld", b.max_rel, b.at_rel, b.n);
    H_CHECK(b.max_rel <= B_ERFC_REL, "erfc rel err %g at x=%.9g", b.max_rel, b.at_rel);
    H_CHECK(appear__erfc(inf) == 0.0f && appear__erfc(-inf) == 2.0f && appear__erfc(0.0f) == 1.0f, "erfc(+-Inf, 0)");
    H_CHECK(is_nan(appear__erfc(f_from_bits(0x7fc00000u))), "erfc(NaN) not NaN");
}

/* double erfinv by Newton from a start value, on erf or erfc by side */
static double erfinv_ref(double x, double y)
{
    int i;
    for (i = 0; i < 4; ++i) {
        double d = 1.1283791670955126 * exp(-y * y);
        if (x > 0.5) y += (erfc(y) - (1.0 - x)) / d;
        else if (x < -0.5) y -= (erfc(-y) - (1.0 + x)) / d;
        else y -= (erf(y) - x) / d;
    }
    return y;
}

static void test_erfinv(void)
{
    acc a; long n = h_n(1L << 22); float inf = f_from_bits(0x7f800000u), top = 0.99999994f;
    h_case("special: erfinv vs double Newton on erf/erfc");
    acc_init(&a);
#define ERFINV_BODY { float g = appear__erfinv(x); double r = erfinv_ref(x, g); acc_add(&a, x, g, r, 0.0); \
        H_CHECK(appear__erfinv(-x) == -g, "erfinv not odd at %.9g", x); }
    SWEEP_BITS(f_from_bits(1u), top, n, ERFINV_BODY);
    SWEEP_LIN(0.0, top, n, ERFINV_BODY);
    SWEEP_BITS(0.99f, top, n, ERFINV_BODY);
    h_measure("special erfinv", "max rel %.3g at x=%.9g, max abs %.3g at x=%.9g, n=%ld",
              a.max_rel, a.at_rel, a.max_abs, a.at_abs, a.n);
    H_CHECK(a.max_rel <= B_ERFINV_REL, "erfinv rel err %g at x=%.9g", a.max_rel, a.at_rel);
    H_CHECK(appear__erfinv(1.0f) == appear__erfinv(top) && appear__erfinv(inf) == appear__erfinv(top)
            && appear__erfinv(-inf) == -appear__erfinv(top) && h_finite(appear__erfinv(1.0f)), "erfinv saturation");
    H_CHECK(is_nan(appear__erfinv(f_from_bits(0x7fc00000u))), "erfinv(NaN) not NaN");
}

static void test_atan2(void)
{
    acc a; long n = h_n(1L << 23), i; float inf = f_from_bits(0x7f800000u);
    h_case("special: atan2 vs double atan2");
    acc_init(&a);
#define ATAN2_BODY(yy, xx) { float y_ = (yy), x_ = (xx); \
        acc_add(&a, (double)y_ / x_, appear__atan2(y_, x_), atan2((double)y_, (double)x_), 0.0); }
    /* the ratio over every binade, all four quadrants, at three scales */
    SWEEP_BITS(f_from_bits(1u), 1.0f, n / 8, {
        float sc; for (sc = 1e-30f; sc < 1e31f; sc *= 1e15f) {
            ATAN2_BODY(x * sc, sc); ATAN2_BODY(sc, x * sc); ATAN2_BODY(-x * sc, sc); ATAN2_BODY(sc, -x * sc);
            ATAN2_BODY(x * sc, -sc); ATAN2_BODY(-sc, x * sc); ATAN2_BODY(-x * sc, -sc); ATAN2_BODY(-sc, -x * sc); } });
    for (i = 0; i <= n / 2; ++i) { double t = 6.283185307179586 * i / (n / 2) - 3.141592653589793;
        ATAN2_BODY((float)sin(t), (float)cos(t)); }
    h_measure("special atan2", "max abs %.3g, max rel %.3g at y/x=%.9g, n=%ld", a.max_abs, a.max_rel, a.at_rel, a.n);
    H_CHECK(a.max_abs <= B_ATAN2_ABS, "atan2 abs err %g at y/x=%.9g", a.max_abs, a.at_abs);
    H_CHECK(a.max_rel <= B_ATAN2_REL, "atan2 rel err %g at y/x=%.9g", a.max_rel, a.at_rel);
    {   /* C99 special values */
        const float v[] = { 0.0f, -0.0f, 1.0f, -1.0f, 0, 0 }; int j, k;
        float vv[6]; memcpy(vv, v, sizeof vv); vv[4] = inf; vv[5] = -inf;
        for (j = 0; j < 6; ++j) for (k = 0; k < 6; ++k) {
            float g = appear__atan2(vv[j], vv[k]), r = (float)atan2((double)vv[j], (double)vv[k]);
            H_CHECK(fabsf(g - r) <= 2.5e-7f && bits_of(g) >> 31 == bits_of(r) >> 31,
                    "atan2(%g, %g) = %.9g, want %.9g", vv[j], vv[k], g, r); }
        H_CHECK(is_nan(appear__atan2(f_from_bits(0x7fc00000u), 1.0f)) && is_nan(appear__atan2(1.0f, f_from_bits(0x7fc00000u))),
                "atan2 NaN");
    }
}

static void test_cbrt(void)
{
    acc a; long n = h_n(1L << 22); float inf = f_from_bits(0x7f800000u);
    h_case("special: cbrt vs double cbrt");
    acc_init(&a);
    SWEEP_BITS(f_from_bits(1u), 3.4028235e38f, n, {
        float g = appear__cbrt(x); acc_add(&a, x, g, cbrt((double)x), 0.0);
        H_CHECK(appear__cbrt(-x) == -g, "cbrt not odd at %g", x); });
    h_measure("special cbrt", "max rel %.3g at x=%.9g, n=%ld", a.max_rel, a.at_rel, a.n);
    H_CHECK(a.max_rel <= B_CBRT_REL, "cbrt rel err %g at x=%.9g", a.max_rel, a.at_rel);
    H_CHECK(appear__cbrt(0.0f) == 0.0f && (bits_of(appear__cbrt(-0.0f)) >> 31) && appear__cbrt(inf) == inf
            && appear__cbrt(-inf) == -inf && appear__cbrt(8.0f) == 2.0f, "cbrt specials");
    H_CHECK(is_nan(appear__cbrt(f_from_bits(0x7fc00000u))), "cbrt(NaN) not NaN");
}

void suite_special(void)
{
    test_sincos();
    test_sincos_pi();
    test_exp();
    test_log();
    test_pow();
    test_erf();
    test_erfinv();
    test_atan2();
    test_cbrt();
}
