/* bench/bench_ward.c - Ward BRDF family: appear.h (half-vector form,
   Box-Muller form of Walter's sampling) against a plain transcription of the
   formulas as printed (Eq. 17.1 with acos/atan2/tan; Walter 2005 Eqs. 6-9
   with atan of a tangent plus a quadrant fix, libm log/sin/cos), in one run.
   The error column is the max relative error against a double evaluation. */
#include "bench.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define BW_PI 3.14159265358979323846

/* ---- plain transcription (float, libm) ---- */
typedef struct { int variant; float ax, ay, rd, rs, ps; } plain_ward;

static float plain_lobe(const plain_ward *m, appear_vec3 wo, appear_vec3 wi)
{
    appear_vec3 H = appear_add(wo, wi), h;
    float th, ph, t, e, ci = wi.z, co = wo.z;
    if (!(ci > 0 && co > 0)) return 0;
    h = appear_normalize(H);
    th = acosf(h.z);
    ph = atan2f(h.y, h.x);
    t = tanf(th);
    e = -t * t * (cosf(ph) * cosf(ph) / (m->ax * m->ax) + sinf(ph) * sinf(ph) / (m->ay * m->ay));
    if (m->variant == APPEAR_WARD_ORIGINAL) return expf(e) / (4.0f * (float)BW_PI * m->ax * m->ay * sqrtf(ci * co));
    if (m->variant == APPEAR_WARD_DUER) return expf(e) / (4.0f * (float)BW_PI * m->ax * m->ay * ci * co);
    return appear_dot(H, H) / ((float)BW_PI * m->ax * m->ay * powf(H.z, 4.0f)) * expf(e);
}
static float plain_eval(const plain_ward *m, appear_vec3 wo, appear_vec3 wi)
{
    return m->rd / (float)BW_PI + m->rs * plain_lobe(m, wo, wi);
}
static float plain_pdf(const plain_ward *m, appear_vec3 wo, appear_vec3 wi)
{
    appear_vec3 h;
    float th, ph, t, ph_h;
    if (!(wo.z > 0 && wi.z > 0)) return 0;
    h = appear_normalize(appear_add(wo, wi));
    th = acosf(h.z); ph = atan2f(h.y, h.x); t = tanf(th);
    ph_h = expf(-t * t * (cosf(ph) * cosf(ph) / (m->ax * m->ax) + sinf(ph) * sinf(ph) / (m->ay * m->ay)))
         / ((float)BW_PI * m->ax * m->ay * h.z * h.z * h.z);
    return (1 - m->ps) * wi.z / (float)BW_PI + m->ps * ph_h / (4.0f * appear_dot(wo, h));
}
/* Walter 2005 Eqs. 6-7 as printed: phi = atan(ay/ax tan(2 pi u2)) moved to
   the quadrant of 2 pi u2, theta = atan(sqrt(-log u1 / (...))). */
static int plain_sample(const plain_ward *m, appear_vec3 wo, float uc, float u1, float u2, appear_vec3 *wi, float *w)
{
    float f, p;
    if (uc < m->ps) {
        float a = 2.0f * (float)BW_PI * u2, phi = atanf(m->ay / m->ax * tanf(a)), c, s, th, st;
        appear_vec3 h;
        if (a > 0.5f * (float)BW_PI && a <= 1.5f * (float)BW_PI) phi += (float)BW_PI;
        c = cosf(phi); s = sinf(phi);
        th = atanf(sqrtf(-logf(1.0f - u1) / (c * c / (m->ax * m->ax) + s * s / (m->ay * m->ay))));
        st = sinf(th);
        h = appear_vec3_make(st * c, st * s, cosf(th));
        *wi = appear_sub(appear_scale(h, 2.0f * appear_dot(wo, h)), wo);
    } else {
        float r = sqrtf(u1), phi = 2.0f * (float)BW_PI * u2;
        *wi = appear_vec3_make(r * cosf(phi), r * sinf(phi), sqrtf(1.0f - u1));
    }
    if (!(wi->z > 0)) return 0;
    f = plain_eval(m, wo, *wi);
    p = plain_pdf(m, wo, *wi);
    *w = f * wi->z / p;
    return 1;
}

/* ---- double reference for the error column ---- */
static double ref_eval_d(const plain_ward *m, appear_vec3 wo, appear_vec3 wi)
{
    double hx = (double)wo.x + wi.x, hy = (double)wo.y + wi.y, hz = (double)wo.z + wi.z, ci = wi.z, co = wo.z;
    double e = ((hx / hz) * (hx / hz) / ((double)m->ax * m->ax) + (hy / hz) * (hy / hz) / ((double)m->ay * m->ay));
    double l;
    if (m->variant == APPEAR_WARD_ORIGINAL) l = exp(-e) / (4 * BW_PI * m->ax * m->ay * sqrt(ci * co));
    else if (m->variant == APPEAR_WARD_DUER) l = exp(-e) / (4 * BW_PI * m->ax * m->ay * ci * co);
    else l = (hx * hx + hy * hy + hz * hz) / (BW_PI * m->ax * m->ay * hz * hz * hz * hz) * exp(-e);
    return m->rd / BW_PI + m->rs * l;
}

/* ---- timing loops ---- */
typedef struct {
    appear_ward m; plain_ward p;
    appear_vec3 *wo, *wi; float *u; long n;
} bw_ctx;

static void run_eval(void *c)
{ bw_ctx *x = (bw_ctx *)c; float acc = 0; long i; for (i = 0; i < x->n; ++i) acc += appear_ward_eval(&x->m, x->wo[i], x->wi[i]).v[0]; b_sink = acc; }
static void run_eval_plain(void *c)
{ bw_ctx *x = (bw_ctx *)c; float acc = 0; long i; for (i = 0; i < x->n; ++i) acc += plain_eval(&x->p, x->wo[i], x->wi[i]); b_sink = acc; }
static void run_pdf(void *c)
{ bw_ctx *x = (bw_ctx *)c; float acc = 0; long i; for (i = 0; i < x->n; ++i) acc += appear_ward_pdf(&x->m, x->wo[i], x->wi[i]); b_sink = acc; }
static void run_pdf_plain(void *c)
{ bw_ctx *x = (bw_ctx *)c; float acc = 0; long i; for (i = 0; i < x->n; ++i) acc += plain_pdf(&x->p, x->wo[i], x->wi[i]); b_sink = acc; }
static void run_sample(void *c)
{
    bw_ctx *x = (bw_ctx *)c; float acc = 0; long i;
    for (i = 0; i < x->n; ++i) {
        appear_bsdf_record s;
        appear_ward_sample(&x->m, x->wo[i], x->u[3 * i], x->u[3 * i + 1], x->u[3 * i + 2], &s);
        acc += s.weight.v[0] + s.wi.x;
    }
    b_sink = acc;
}
static void run_sample_plain(void *c)
{
    bw_ctx *x = (bw_ctx *)c; float acc = 0; long i;
    for (i = 0; i < x->n; ++i) {
        appear_vec3 wi = appear_vec3_make(0, 0, 0); float w = 0;
        if (plain_sample(&x->p, x->wo[i], x->u[3 * i], x->u[3 * i + 1], x->u[3 * i + 2], &wi, &w)) acc += w + wi.x;
    }
    b_sink = acc;
}
static void run_sample_h(void *c)
{
    bw_ctx *x = (bw_ctx *)c; float acc = 0; long i;
    for (i = 0; i < x->n; ++i) {
        appear_vec3 h = appear_ward_specular_sample_h(x->p.ax, x->p.ay, x->u[3 * i + 1], x->u[3 * i + 2]);
        acc += h.x + h.z;
    }
    b_sink = acc;
}

static void run_spec_eval(void *c)
{
    bw_ctx *x = (bw_ctx *)c; float acc = 0; long i;
    for (i = 0; i < x->n; ++i) acc += appear_ward_specular_eval((appear_ward_variant)x->p.variant, x->p.ax, x->p.ay, x->wo[i], x->wi[i]);
    b_sink = acc;
}
static void run_spec_pdf(void *c)
{
    bw_ctx *x = (bw_ctx *)c; float acc = 0; long i;
    for (i = 0; i < x->n; ++i) acc += appear_ward_specular_pdf(x->p.ax, x->p.ay, x->wo[i], x->wi[i]);
    b_sink = acc;
}
static void run_spec_pdf_h(void *c)
{
    bw_ctx *x = (bw_ctx *)c; float acc = 0; long i;
    for (i = 0; i < x->n; ++i) acc += appear_ward_specular_pdf_h(x->p.ax, x->p.ay, x->wi[i]);
    b_sink = acc;
}

void bench_ward(void)
{
    static const int variants[] = { APPEAR_WARD_ORIGINAL, APPEAR_WARD_BALANCED };
    long n = b_quick() ? 20000 : 200000, i;
    bw_ctx c;
    b_rng r = b_rng_make(4);
    int vi;
    c.n = n;
    c.wo = (appear_vec3 *)malloc(sizeof(appear_vec3) * n);
    c.wi = (appear_vec3 *)malloc(sizeof(appear_vec3) * n);
    c.u = (float *)malloc(sizeof(float) * 3 * n);
    for (i = 0; i < n; ++i) {
        c.wo[i] = b_rand_hemi(&r);
        c.wi[i] = b_rand_hemi(&r);
        c.u[3 * i] = b_randf(&r); c.u[3 * i + 1] = b_randf(&r); c.u[3 * i + 2] = b_randf(&r);
    }
    b_note("ward: alpha 0.1/0.2, rho_d 0.3, rho_s 0.6, %ld upper-hemisphere pairs; plain = Eq. 17.1 with acos/atan2/tan and Walter's atan(tan) sampling", n);
    for (vi = 0; vi < 2; ++vi) {
        char name[96];
        double e_ours = 0, e_plain = 0, ns;
        static const char *const vn[3] = { "original", "duer", "balanced" };
        c.m = appear_ward_make(appear_spectrum_splat(0.3f), appear_spectrum_splat(0.6f), 0.1f, 0.2f, (appear_ward_variant)variants[vi]);
        c.p.variant = variants[vi]; c.p.ax = 0.1f; c.p.ay = 0.2f; c.p.rd = 0.3f; c.p.rs = 0.6f; c.p.ps = c.m.p_spec;
        for (i = 0; i < n; i += 7) {
            double ref = ref_eval_d(&c.p, c.wo[i], c.wi[i]);
            double a = appear_ward_eval(&c.m, c.wo[i], c.wi[i]).v[0], b = plain_eval(&c.p, c.wo[i], c.wi[i]);
            if (c.wo[i].z < 1e-3f || c.wi[i].z < 1e-3f) continue;
            e_ours = fmax(e_ours, fabs(a - ref) / ref);
            e_plain = fmax(e_plain, fabs(b - ref) / ref);
        }
        /* interleaved: ours, plain, ours, plain */
        snprintf(name, sizeof name, "%s eval", vn[variants[vi]]);
        ns = b_time(run_eval, &c, n); b_row("ward", name, ns, e_ours, "half-vector form");
        snprintf(name, sizeof name, "%s eval (plain Eq. 17.1)", vn[variants[vi]]);
        ns = b_time(run_eval_plain, &c, n); b_row("ward", name, ns, e_plain, "acos/atan2/tan");
        snprintf(name, sizeof name, "%s pdf", vn[variants[vi]]);
        ns = b_time(run_pdf, &c, n); b_row("ward", name, ns, -1, "mixture");
        snprintf(name, sizeof name, "%s pdf (plain)", vn[variants[vi]]);
        ns = b_time(run_pdf_plain, &c, n); b_row("ward", name, ns, -1, "");
        snprintf(name, sizeof name, "%s sample", vn[variants[vi]]);
        ns = b_time(run_sample, &c, n); b_row("ward", name, ns, -1, "Box-Muller half vector + eval + pdf");
        snprintf(name, sizeof name, "%s sample (plain Walter)", vn[variants[vi]]);
        ns = b_time(run_sample_plain, &c, n); b_row("ward", name, ns, -1, "atan(tan) + libm");
    }
    b_row("ward", "specular_sample_h", b_time(run_sample_h, &c, n), -1, "half vector only");
    b_row("ward", "specular_eval (balanced lobe)", b_time(run_spec_eval, &c, n), -1, "");
    b_row("ward", "specular_pdf", b_time(run_spec_pdf, &c, n), -1, "");
    b_row("ward", "specular_pdf_h", b_time(run_spec_pdf_h, &c, n), -1, "half-vector density");
    free(c.wo); free(c.wi); free(c.u);
}
