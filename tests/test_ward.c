/* tests/test_ward.c - Ward BRDF family (original, Duer, balanced) and
   Walter's half-vector sampling. See the SECTION ward comment in appear.h.

   References in double precision are transcribed here from the papers in
   their ANGLE form (Eq. 17.1 of the seed text / Ward 1992 Eq. 5a with
   theta_h, phi_h from acos and atan2), so they check the header's
   half-vector form (Eq. 17.2 with its minus sign restored) independently.
   The model's chi-square, pdf integral, sample consistency, mean weight
   against the albedo, reciprocity and adversarial inputs are rows of
   tests/test_models.c. */
#include "harness.h"
#include <math.h>
#include <string.h>

#define W_PI 3.14159265358979323846

static const char *const ward_names[3] = { "original", "duer", "balanced" };

/* ---- double references -------------------------------------------------- */

typedef struct { double x, y, z; } dvec;
static dvec dv(appear_vec3 v) { dvec r; r.x = v.x; r.y = v.y; r.z = v.z; return r; }
static double ddot(dvec a, dvec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static dvec dnorm(dvec a) { double l = sqrt(ddot(a, a)); a.x /= l; a.y /= l; a.z /= l; return a; }

/* Eq. 17.1 (Ward 1992 Eq. 5a): exponent -tan^2(theta_h) (cos^2 phi_h / ax^2 + sin^2 phi_h / ay^2),
   angles from acos/atan2. Returns the specular lobe without rho_s; wo, wi upper hemisphere. */
static double ref_exponent_angles(double ax, double ay, dvec wo, dvec wi)
{
    dvec h; double th, ph, t;
    h.x = wo.x + wi.x; h.y = wo.y + wi.y; h.z = wo.z + wi.z;
    h = dnorm(h);
    th = acos(h.z > 1 ? 1 : h.z);
    ph = atan2(h.y, h.x);
    t = tan(th);
    return -t * t * (cos(ph) * cos(ph) / (ax * ax) + sin(ph) * sin(ph) / (ay * ay));
}

static double ref_lobe(int variant, double ax, double ay, dvec wo, dvec wi)
{
    double ci = wi.z, co = wo.z, ex;
    dvec H;
    if (!(ci > 0 && co > 0)) return 0;
    ex = exp(ref_exponent_angles(ax, ay, wo, wi));
    H.x = wo.x + wi.x; H.y = wo.y + wi.y; H.z = wo.z + wi.z;
    if (variant == APPEAR_WARD_ORIGINAL) return ex / (4 * W_PI * ax * ay * sqrt(ci * co));     /* Ward92 Eq. 5a */
    if (variant == APPEAR_WARD_DUER) return ex / (4 * W_PI * ax * ay * ci * co);                /* Duer06 */
    return ddot(H, H) / (W_PI * ax * ay * pow(H.z, 4)) * ex;                                    /* GMD10 */
}

/* Walter 2005: p(h) = exp(-E) / (pi ax ay cos^3 theta_h); p(wi) = p(h) / (4 wo.h). */
static double ref_pdf_h(double ax, double ay, dvec h)
{
    double t2x, t2y;
    if (!(h.z > 0)) return 0;
    t2x = h.x / h.z; t2y = h.y / h.z;
    return exp(-(t2x * t2x / (ax * ax) + t2y * t2y / (ay * ay))) / (W_PI * ax * ay * h.z * h.z * h.z);
}
static double ref_pdf_spec(double ax, double ay, dvec wo, dvec wi)
{
    dvec h;
    if (!(wo.z > 0 && wi.z > 0)) return 0;
    h.x = wo.x + wi.x; h.y = wo.y + wi.y; h.z = wo.z + wi.z;
    h = dnorm(h);
    return ref_pdf_h(ax, ay, h) / (4 * ddot(wo, h));
}

/* full model in double, two-sided, channel 0 */
typedef struct { int variant; double ax, ay, rd, rs, ps; } ref_model;
static double ref_eval(const ref_model *r, dvec wo, dvec wi)
{
    if (!(wo.z * wi.z > 0)) return 0;
    if (wo.z < 0) { wo.z = -wo.z; wi.z = -wi.z; }
    return r->rd / W_PI + r->rs * ref_lobe(r->variant, r->ax, r->ay, wo, wi);
}
static double ref_pdf(const ref_model *r, dvec wo, dvec wi)
{
    if (!(wo.z * wi.z > 0)) return 0;
    if (wo.z < 0) { wo.z = -wo.z; wi.z = -wi.z; }
    return (1 - r->ps) * wi.z / W_PI + r->ps * ref_pdf_spec(r->ax, r->ay, wo, wi);
}

static appear_vec3 dir_theta_phi(double th, double ph)
{
    return appear_vec3_make((float)(sin(th) * cos(ph)), (float)(sin(th) * sin(ph)), (float)cos(th));
}
static appear_vec3 rand_upper(h_rng *r)
{
    appear_vec3 v = h_rand_dir(r);
    v.z = fabsf(v.z);
    return v;
}
static double rel_diff(double a, double b) { return fabs(a - b) / fmax(fmax(fabs(a), fabs(b)), 1e-30); }

/* ---- Eq. 17.1 == Eq. 17.2 (sign fixed), variants, float vs double ------ */

void suite_ward_formula(void)
{
    static const float al[][2] = { {0.1f, 0.1f}, {0.1f, 0.2f}, {0.02f, 0.05f}, {0.5f, 0.3f}, {1.0f, 1.0f} };
    h_rng r = h_rng_make(17);
    int v, a;
    long i, n = h_n(200000);
    h_case("ward: Eq. 17.1 (angles) equals the half-vector Eq. 17.2 with exp(-...), printed sign gives different values");
    {
        long wrong_sign_off = 0, tested = 0;
        double maxrel = 0;
        for (i = 0; i < n; ++i) {
            appear_vec3 wo = rand_upper(&r), wi = rand_upper(&r);
            float ax = 0.05f + 0.5f * h_randf(&r), ay = 0.05f + 0.5f * h_randf(&r);
            double e171 = ref_exponent_angles(ax, ay, dv(wo), dv(wi));
            /* Eq. 17.2 as printed: ((h.x/ax)^2 + (h.y/ay)^2) / (h.n)^2, no minus */
            dvec h, a = dv(wo), b = dv(wi);
            double e172;
            h.x = a.x + b.x; h.y = a.y + b.y; h.z = a.z + b.z;
            h = dnorm(h);
            e172 = ((h.x / ax) * (h.x / ax) + (h.y / ay) * (h.y / ay)) / (h.z * h.z);
            float got = appear_ward_specular_eval(APPEAR_WARD_ORIGINAL, ax, ay, wo, wi);
            double ref = ref_lobe(APPEAR_WARD_ORIGINAL, ax, ay, dv(wo), dv(wi));
            if (wo.z < 1e-3f || wi.z < 1e-3f || e171 < -80) continue;
            ++tested;
            H_CHECK(fabs(e171 + e172) <= 1e-9 * fmax(1.0, fabs(e171)), "exponent 17.1 %.12g vs -(17.2) %.12g", e171, -e172);
            wrong_sign_off += e172 > 1e-3 && rel_diff(exp(e172), ref * 4 * W_PI * ax * ay * sqrt((double)wo.z * wi.z)) > 1e-3;
            /* exp(-E) turns an absolute error of E into a relative one: scale by 1 + E */
            if (ref > 1e-30) maxrel = fmax(maxrel, rel_diff(got, ref) / (1.0 - e171));
        }
        H_CHECK(maxrel < 2e-6, "half-vector float eval vs Eq. 17.1 double: max rel err / (1 + E) %.3g", maxrel);
        H_CHECK(wrong_sign_off > tested / 2, "the printed Eq. 17.2 (exp(+...)) should differ on most inputs: %ld of %ld", wrong_sign_off, tested);
        h_measure("ward Eq.17.1 vs 17.2", "max (rel err / (1 + E)) of the float half-vector form vs double Eq. 17.1: %.3g over %ld pairs; printed sign wrong on %ld",
                  maxrel, tested, wrong_sign_off);
    }

    for (v = 0; v < 3; ++v) {
        h_err ef = { 0, 0, 0, 0, 0, 0 }, ep = { 0, 0, 0, 0, 0, 0 };
        char nf[64], np[64];
        sprintf(nf, "ward %s eval", ward_names[v]); sprintf(np, "ward %s pdf", ward_names[v]);
        ef.name = nf; ep.name = np;
        h_case("ward %s: eval and pdf float vs double (angle-form papers), side flip, normal incidence", ward_names[v]);
        for (a = 0; a < 5; ++a) {
            ref_model rm;
            appear_ward m = appear_ward_make(appear_spectrum_splat(0.25f), appear_spectrum_splat(0.7f), al[a][0], al[a][1], (appear_ward_variant)v);
            rm.variant = v; rm.ax = al[a][0]; rm.ay = al[a][1]; rm.rd = 0.25; rm.rs = 0.7; rm.ps = m.p_spec;
            H_CHECK(m.valid, "make valid");
            for (i = 0; i < n / 5; ++i) {
                appear_vec3 wo = rand_upper(&r), wi = rand_upper(&r);
                appear_vec3 wo2 = wo, wi2 = wi;
                float f = appear_ward_eval(&m, wo, wi).v[0], p = appear_ward_pdf(&m, wo, wi);
                double fr = ref_eval(&rm, dv(wo), dv(wi)), pr = ref_pdf(&rm, dv(wo), dv(wi));
                if (wo.z < 1e-3f || wi.z < 1e-3f) continue;
                h_err_add(&ef, f, fr, 1e-30);
                h_err_add(&ep, p, pr, 1e-30);
                wo2.z = -wo2.z; wi2.z = -wi2.z; /* two-sided: lower hemisphere mirror */
                H_CHECK(appear_ward_eval(&m, wo2, wi2).v[0] == f && appear_ward_pdf(&m, wo2, wi2) == p,
                        "two-sided mismatch");
                H_CHECK(appear_ward_eval(&m, wo2, wi).v[0] == 0.0f && appear_ward_pdf(&m, wo2, wi) == 0.0f, "opposite sides not 0");
            }
        }
        H_CHECK(ef.max_rel < 1e-4, "eval max rel err %.3g (ref %.9g got %.9g)", ef.max_rel, ef.at_ref, ef.at_got);
        H_CHECK(ep.max_rel < 1e-4, "pdf max rel err %.3g (ref %.9g got %.9g)", ep.max_rel, ep.at_ref, ep.at_got);
        h_err_report(&ef); h_err_report(&ep);
        {   /* all variants agree at normal incidence: rho_s / (4 pi ax ay) */
            appear_vec3 n0 = appear_vec3_make(0, 0, 1);
            float f = appear_ward_specular_eval((appear_ward_variant)v, 0.1f, 0.2f, n0, n0);
            H_CHECK(rel_diff(f, 1.0 / (4 * W_PI * 0.1 * 0.2)) < 1e-6, "normal incidence %.9g", f);
        }
    }

    h_case("ward: building blocks: pdf_h, specular_pdf = pdf_h/(4 wo.h) and the free eval match the model");
    {
        long bad = 0;
        for (i = 0; i < n / 4; ++i) {
            appear_vec3 wo = rand_upper(&r), wi = rand_upper(&r), h = appear_normalize(appear_add(wo, wi));
            float ax = 0.03f + h_randf(&r), ay = 0.03f + h_randf(&r);
            double ph = appear_ward_specular_pdf_h(ax, ay, h), ps = appear_ward_specular_pdf(ax, ay, wo, wi);
            double ph_r = ref_pdf_h(ax, ay, dv(h)), ps_r = ref_pdf_spec(ax, ay, dv(wo), dv(wi));
            if (wo.z < 1e-2f || wi.z < 1e-2f || ph_r < 1e-20) continue;
            bad += rel_diff(ph, ph_r) > 1e-4 || rel_diff(ps, ps_r) > 1e-4;
        }
        H_CHECK(bad == 0, "%ld pdf mismatches", bad);
    }
}

/* ---- chi-square of the free half-vector sampler against p(h) ------------- */

typedef struct { float ax, ay; } chi_ctx;
static int chi_sample(void *c, float uc, float u1, float u2, appear_vec3 *wi)
{
    chi_ctx *x = (chi_ctx *)c;
    (void)uc;
    *wi = appear_ward_specular_sample_h(x->ax, x->ay, u1, u2);
    return wi->z > 0;
}
static double chi_pdf(void *c, appear_vec3 wi)
{
    chi_ctx *x = (chi_ctx *)c;
    return ref_pdf_h(x->ax, x->ay, dv(wi));
}
static void chi_run(const char *name, float ax, float ay, int cap)
{
    chi_ctx c;
    h_chi2_spec sp;
    memset(&sp, 0, sizeof sp);
    c.ax = ax; c.ay = ay;
    h_case("ward chi2 %s", name);
    sp.name = name; sp.sample = chi_sample; sp.pdf = chi_pdf; sp.ctx = &c;
    sp.seed = (uint64_t)(1000 + 37 * ax * 1000 + ay * 100 + 1);
    if (cap) {   /* a cap about +z */
        sp.axis = appear_vec3_make(0, 0, 1);
        sp.zmin = cos(4.0 * (ax > ay ? ax : ay));
        sp.n_z = 24; sp.n_phi = 48;
    }
    h_chi2(&sp);
}

void suite_ward_chi2(void)
{
    /* the free half-vector sampler against p(h) in double (Walter 2005) */
    chi_run("sample_h 0.3/0.1", 0.3f, 0.1f, 0);
    chi_run("sample_h 0.02/0.04 cap", 0.02f, 0.04f, 1);
}

/* ---- sampling: record consistency, pdf mass = success rate, quadrants ---- */

void suite_ward_sample(void)
{
    h_rng r = h_rng_make(99);
    long i;
    int v;
    h_case("ward: Walter's phi_h lands in the quadrant of (cos 2 pi u2, sin 2 pi u2), phi_h = atan2(ay sin, ax cos)");
    {
        long bad = 0;
        for (i = 0; i < 4096; ++i) {
            float u2 = (float)(i + 0.5) / 4096.0f, ax = 0.1f, ay = 0.4f;
            appear_vec3 h = appear_ward_specular_sample_h(ax, ay, 0.5f, u2);
            double c = cos(2 * W_PI * u2), s = sin(2 * W_PI * u2);
            double ph = atan2(h.y, h.x), pw = atan2(ay * s, ax * c);
            double d = fabs(ph - pw);
            d = fmin(d, 2 * W_PI - d);
            bad += d > 1e-4 || (c > 1e-3 && h.x <= 0) || (c < -1e-3 && h.x >= 0) || (s > 1e-3 && h.y <= 0) || (s < -1e-3 && h.y >= 0);
        }
        H_CHECK(bad == 0, "%ld quadrant errors", bad);
    }

    h_case("ward: -log(1-u1) written stably: tan^2 theta_h / (ax^2 cos^2 + ...) matches -log1p(-u1) for tiny and large u1; u1 = 0 and 1");
    {
        static const float us[] = { 0.0f, 1e-30f, 1e-12f, 3e-8f, 1e-7f, 1e-4f, 0.3f, 0.5f, 0.9f, 0.999f, 0.99999994f, 1.0f };
        int k;
        for (k = 0; k < (int)(sizeof us / sizeof us[0]); ++k) {
            float ax = 0.3f, ay = 0.3f;
            appear_vec3 h = appear_ward_specular_sample_h(ax, ay, us[k], 0.125f);
            double t2 = ((double)h.x * h.x + (double)h.y * h.y) / ((double)h.z * h.z);
            double L = t2 / (ax * ax), Lr = -log1p(-(double)(us[k] < 0.99999994f ? us[k] : 0.99999994f));
            H_CHECK(appear_is_unit(h) && h.z > 0, "u1 %g: h not a unit upper vector (%g %g %g)", us[k], h.x, h.y, h.z);
            H_CHECK(us[k] == 0.0f ? L == 0.0 : rel_diff(L, Lr) < 2e-4, "u1 %g: -log(1-u) %.9g vs %.9g", us[k], L, Lr);
        }
    }

    h_case("ward: delta limit (max alpha < 1e-4) matches alpha = 3e-4 by mean weight; mirror direction; flags");
    for (v = 0; v < 3; ++v) {
        appear_ward md = appear_ward_make(appear_spectrum_splat(0.0f), appear_spectrum_splat(0.8f), 5e-5f, 2e-5f, (appear_ward_variant)v);
        appear_ward mr = appear_ward_make(appear_spectrum_splat(0.0f), appear_spectrum_splat(0.8f), 3e-4f, 3e-4f, (appear_ward_variant)v);
        appear_vec3 wo = dir_theta_phi(1.2, 0.4);
        appear_bsdf_record s;
        double acc = 0;
        long j, ns = h_n(100000);
        int ok = appear_ward_sample(&md, wo, 0.3f, 0.4f, 0.6f, &s);
        H_CHECK(md.delta && ok && (s.flags & APPEAR_LOBE_SPECULAR) && fabsf(s.wi.x + wo.x) < 1e-6f && fabsf(s.wi.y + wo.y) < 1e-6f
                && fabsf(s.wi.z - wo.z) < 1e-6f, "%s: mirror sample", ward_names[v]);
        H_CHECK(appear_ward_eval(&md, wo, s.wi).v[0] == 0.0f && appear_ward_pdf(&md, wo, s.wi) == 0.0f, "%s: eval/pdf exclude delta", ward_names[v]);
        for (j = 0; j < ns; ++j) {
            appear_bsdf_record t;
            float uc = h_randf(&r), u1 = h_randf(&r), u2 = h_randf(&r); /* in this order */
            if (appear_ward_sample(&mr, wo, uc, u1, u2, &t)) acc += t.weight.v[0];
        }
        acc /= ns;
        H_CHECK(rel_diff(acc, s.weight.v[0]) < 2e-3, "%s: delta weight %.6f vs alpha 3e-4 mean weight %.6f", ward_names[v], s.weight.v[0], acc);
    }
}

/* ---- albedo -------------------------------------------------------------- */

typedef struct { const appear_ward *m; appear_vec3 wo; } alb_ctx;
static double alb_fn(void *c, appear_vec3 wi)
{
    alb_ctx *x = (alb_ctx *)c;
    return wi.z > 0 ? (double)appear_ward_eval(x->m, x->wo, wi).v[0] * wi.z : 0.0;
}

void suite_ward_albedo(void)
{
    static const float alphas[] = { 0.02f, 0.05f, 0.1f, 0.2f, 0.35f, 0.5f, 0.75f, 1.0f };
    static const double thetas_deg[] = { 0, 30, 60, 75, 85, 89, 89.9 };
    int v, a, t;
    double maxalb[3] = { 0, 0, 0 }, maxat_a[3] = { 0, 0, 0 }, maxat_t[3] = { 0, 0, 0 };
    double grazing_small[3] = { 0, 0, 0 }, normal_small[3] = { 0, 0, 0 };
    /* (the mean sample weight against this quadrature: rows "ward ... mean weight" of
       tests/test_models.c) */
    int na = h_quick() ? 4 : 8, nt = 7;
    for (v = 0; v < 3; ++v) {
        char row[400];
        int len = 0;
        h_case("ward %s: directional albedo (rho_d = 0, rho_s = 1) by quadrature", ward_names[v]);
        for (a = 0; a < na; ++a)
            for (t = 0; t < nt; ++t) {
                appear_ward m = appear_ward_make(appear_spectrum_splat(0.0f), appear_spectrum_splat(1.0f), alphas[a * 8 / na], alphas[a * 8 / na], (appear_ward_variant)v);
                alb_ctx c;
                double alb;
                c.m = &m; c.wo = dir_theta_phi(thetas_deg[t] * W_PI / 180.0, 0.0);
                alb = h_integrate_sphere(alb_fn, &c, appear_vec3_make(-c.wo.x, -c.wo.y, c.wo.z), 1e-6);
                if (alb > maxalb[v]) { maxalb[v] = alb; maxat_a[v] = alphas[a * 8 / na]; maxat_t[v] = thetas_deg[t]; }
                if ((a * 8 / na) % 2 == 0 && len < 360)
                    len += sprintf(row + len, "%s%g/%g:%.3f", len ? " " : "", alphas[a * 8 / na], thetas_deg[t], alb);
                if (a == 0 && t == 0) normal_small[v] = alb;
                if (a == 0 && t == 5) grazing_small[v] = alb;
                if (v == APPEAR_WARD_BALANCED) H_CHECK(alb <= 1.0 + 1e-3, "albedo %.6f > 1 at alpha %g theta_o %g", alb, alphas[a * 8 / na], thetas_deg[t]);
            }
        h_measure("ward albedo table", "%s (alpha/theta_o deg:albedo) %s", ward_names[v], row);
        h_measure("ward albedo", "%s: max albedo %.4f at alpha %g theta_o %g deg; alpha 0.02: %.4f at 0 deg, %.4f at 89 deg",
                  ward_names[v], maxalb[v], maxat_a[v], maxat_t[v], normal_small[v], grazing_small[v]);
        /* all three are normalised at normal incidence: near 1 for a narrow lobe */
        H_CHECK(fabs(normal_small[v] - 1.0) < 0.01, "albedo at normal incidence, alpha 0.02: %.5f", normal_small[v]);
    }
    h_case("ward: documented albedo failures of the original and Duer normalisations are real");
    H_CHECK(maxalb[APPEAR_WARD_DUER] > 1.05, "Duer's albedo should exceed 1 at grazing: max %.4f", maxalb[APPEAR_WARD_DUER]);
    H_CHECK(grazing_small[APPEAR_WARD_ORIGINAL] < 0.5, "original, alpha 0.02, 89 deg should lose energy (delta limit cos_o): %.4f",
            grazing_small[APPEAR_WARD_ORIGINAL]);
}

/* ---- stability ----------------------------------------------------------- */

static int spec_ok(appear_spectrum s)
{
    int k, ok = 1;
    for (k = 0; k < APPEAR_SPECTRUM_SAMPLES; ++k) ok &= H_OK_VALUE(s.v[k]);
    return ok;
}

/* returns 0 when every output obeys the contract, else a bit mask of what failed */
static int check_all(const appear_ward *m, appear_vec3 wo, appear_vec3 wi, float uc, float u1, float u2, float ax, float ay)
{
    appear_bsdf_record s;
    int ok = 0, got;
    appear_vec3 h;
    ok |= !spec_ok(appear_ward_eval(m, wo, wi)) << 0;
    ok |= !H_OK_VALUE(appear_ward_pdf(m, wo, wi)) << 1;
    got = appear_ward_sample(m, wo, uc, u1, u2, &s);
    ok |= !(spec_ok(s.f) && spec_ok(s.weight) && H_OK_VALUE(s.pdf) && h_finite(s.wi.x) && h_finite(s.wi.y) && h_finite(s.wi.z)) << 2;
    ok |= !(got ? (appear_is_unit(s.wi) && s.pdf > 0 && s.flags != 0) : (s.pdf == 0 && s.flags == 0 && s.weight.v[0] == 0)) << 3;
    ok |= !H_OK_VALUE(appear_ward_specular_eval(APPEAR_WARD_BALANCED, ax, ay, wo, wi)) << 4;
    ok |= !H_OK_VALUE(appear_ward_specular_eval(APPEAR_WARD_ORIGINAL, ax, ay, wo, wi)) << 5;
    ok |= !H_OK_VALUE(appear_ward_specular_pdf(ax, ay, wo, wi)) << 6;
    ok |= !H_OK_VALUE(appear_ward_specular_pdf_h(ax, ay, wi)) << 7;
    h = appear_ward_specular_sample_h(ax, ay, u1, u2);
    ok |= !(h_finite(h.x) && h_finite(h.y) && h_finite(h.z) && h.z >= 0) << 8;
    return ok; /* 0 = all fine, else a bit mask of the failed checks */
}

void suite_ward_stability(void)
{
    static const float cosv[] = { 1.0f, 0.5f, 1e-2f, 1e-4f, 1e-6f, 0.0f };
    static const float alv[] = { 1e-6f, 5e-5f, 1e-4f, 1e-3f, 1e-2f, 0.1f, 0.5f, 1.0f, 2.0f, 100.0f };
    static const float uv[] = { 0.0f, 0.5f, 0.99999994f, 1.0f };
    h_rng r = h_rng_make(5);
    int v, i, j, k, a, b, q;
    long n, bad = 0, cnt = 0;
    h_case("ward: stability sweep over cos theta x alpha x variant x u (incl. 0, 1)");
    for (v = 0; v < 3; ++v)
        for (a = 0; a < 10; ++a)
            for (b = 0; b < 10; b += 3) {
                appear_ward m = appear_ward_make(appear_spectrum_splat(0.3f), appear_spectrum_splat(0.7f), alv[a], alv[b], (appear_ward_variant)v);
                H_CHECK(m.valid, "alpha %g %g rejected", alv[a], alv[b]);
                for (i = 0; i < 6; ++i)
                    for (j = 0; j < 6; ++j)
                        for (q = 0; q < 4; ++q)
                            for (k = 0; k < 3; ++k) {
                                float so = sqrtf(1 - cosv[i] * cosv[i]), si = sqrtf(1 - cosv[j] * cosv[j]);
                                float phis[3] = { 0.0f, 1.0f, 3.14159f };
                                appear_vec3 wo = appear_vec3_make(so, 0, cosv[i]);
                                appear_vec3 wi = appear_vec3_make(si * cosf(phis[k]), si * sinf(phis[k]), cosv[j]);
                                ++cnt;
                                int e = check_all(&m, wo, wi, uv[q], uv[q], uv[(q + k) & 3], alv[a], alv[b]);
                                if (e) {
                                    ++bad;
                                    if (bad < 5) h_fail("mask %x: %s alpha %g/%g cos_o %g cos_i %g phi %g u %g", e, ward_names[v], alv[a], alv[b], cosv[i], cosv[j], phis[k], uv[q]);
                                }
                            }
            }
    h_measure("ward stability sweep", "%ld grid inputs, %ld bad", cnt, bad);

    h_case("ward: invalid parameters give valid = 0 and zero / failed calls");
    {
        static const float badf[] = { -1.0f, 0.0f, -0.0f, 1e-45f * 0.0f, 101.0f, 1e30f };
        appear_vec3 wo = appear_vec3_make(0, 0.6f, 0.8f), wi = appear_vec3_make(0, -0.6f, 0.8f);
        appear_bsdf_record s;
        for (i = 0; i < 6; ++i) {
            appear_ward m = appear_ward_make(appear_spectrum_splat(0.3f), appear_spectrum_splat(0.3f), badf[i], 0.1f, APPEAR_WARD_BALANCED);
            H_CHECK(!m.valid && appear_ward_eval(&m, wo, wi).v[0] == 0 && appear_ward_pdf(&m, wo, wi) == 0
                    && !appear_ward_sample(&m, wo, 0.5f, 0.5f, 0.5f, &s), "alpha %g accepted", badf[i]);
        }
        {
            appear_ward m1 = appear_ward_make(appear_spectrum_splat(0.6f), appear_spectrum_splat(0.6f), 0.1f, 0.1f, APPEAR_WARD_DUER);
            appear_ward m2 = appear_ward_make(appear_spectrum_splat(NAN), appear_spectrum_splat(0.1f), 0.1f, 0.1f, APPEAR_WARD_DUER);
            appear_ward m3 = appear_ward_make(appear_spectrum_splat(0.1f), appear_spectrum_splat(0.1f), NAN, 0.1f, APPEAR_WARD_DUER);
            appear_ward m4 = appear_ward_make(appear_spectrum_splat(0.1f), appear_spectrum_splat(0.1f), 0.1f, 0.1f, (appear_ward_variant)7);
            appear_ward m5 = appear_ward_make(appear_spectrum_splat(0.1f), appear_spectrum_splat(-0.1f), 0.1f, 0.1f, APPEAR_WARD_DUER);
            H_CHECK(!m1.valid && !m2.valid && !m3.valid && !m4.valid && !m5.valid, "rho_d + rho_s > 1, NaN, bad variant or negative accepted");
        }
    }

    h_case("ward: adversarial inputs (NaN, Inf, denormals, +-0, unnormalised, u out of range)");
    n = h_n(2000000);
    bad = 0;
    for (i = 0; i < n; ++i) {
        float ax = (i & 3) ? h_adv_float(&r) : 0.5f * h_randf(&r), ay = (i & 5) ? h_adv_float(&r) : h_randf(&r);
        appear_spectrum rd = appear_spectrum_splat((i & 7) ? 0.3f * h_randf(&r) : h_adv_float(&r));
        appear_spectrum rs = appear_spectrum_splat((i & 7) ? 0.6f * h_randf(&r) : h_adv_float(&r));
        appear_ward m = appear_ward_make(rd, rs, ax, ay, (appear_ward_variant)(i % 3));
        appear_vec3 wo = h_adv_dir(&r), wi = h_adv_dir(&r);
        float uc = h_adv_u(&r), u1 = h_adv_u(&r), u2 = h_adv_u(&r);
        int e = check_all(&m, wo, wi, uc, u1, u2, ax, ay);
        if (e) {
            ++bad;
            if (bad < 5) h_fail("mask %x: u %g %g %g ax %g ay %g wo (%g %g %g) wi (%g %g %g)", e, uc, u1, u2, ax, ay, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z);
        }
    }
    h_measure("ward adversarial", "%ld random adversarial inputs, %ld bad", n, bad);
}
