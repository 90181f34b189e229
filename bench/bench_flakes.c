/* bench/bench_flakes.c - micro-flake media (SGGX, Jakob fibers) and the
   wider phase-function family. Baselines written plainly from the papers:
   SGGX D and visible-normal sampling on the raw matrix entries (Heitz et al.
   2015, listings), the fiber sigma(w) by its closed form + quadrature per
   call (what the table replaces), HG sampling as the cost floor. */
#include "bench.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { N = 1 << 14 };
typedef struct {
    float u1[N], u2[N], u3[N], u4[N];
    appear_vec3 wo[N], wi[N];
} inputs;
static inputs *g_in;

typedef struct {
    int which;
    const void *m;
} bctx;

/* ---- plain SGGX reference from the matrix entries (baseline) ---- */
typedef struct { float s[6]; } ref_sggx; /* xx yy zz xy xz yz */
static float ref_quad(const float *s, appear_vec3 w)
{
    return s[0] * w.x * w.x + s[1] * w.y * w.y + s[2] * w.z * w.z + 2.0f * (s[3] * w.x * w.y + s[4] * w.x * w.z + s[5] * w.y * w.z);
}
static float ref_D(const ref_sggx *r, appear_vec3 m)
{
    const float *s = r->s;
    float det = s[0] * s[1] * s[2] - s[0] * s[5] * s[5] - s[1] * s[4] * s[4] - s[2] * s[3] * s[3] + 2.0f * s[3] * s[4] * s[5];
    float a[6];
    float q;
    a[0] = s[1] * s[2] - s[5] * s[5]; a[1] = s[0] * s[2] - s[4] * s[4]; a[2] = s[0] * s[1] - s[3] * s[3];
    a[3] = s[4] * s[5] - s[3] * s[2]; a[4] = s[3] * s[5] - s[4] * s[1]; a[5] = s[3] * s[4] - s[0] * s[5];
    q = ref_quad(a, m) / det;
    return 1.0f / (3.14159265f * sqrtf(det) * q * q);
}
/* Heitz 2015 listing: VNDF sample with the raw entries, libm sincos */
static appear_vec3 ref_vndf(const ref_sggx *r, appear_vec3 wi, float u1, float u2)
{
    const float *S = r->s;
    appear_frame f = appear_frame_from_normal(wi);
    appear_vec3 k = f.x, j = f.y, i = f.z;
    float Sm[3][3], skk, sjj, sii, skj, ski, sji, sdet, tmp, isii, ph = 6.2831853f * u2, uu, vv, ww;
    appear_vec3 Mk, Mj, Mi, m;
    Sm[0][0] = S[0]; Sm[1][1] = S[1]; Sm[2][2] = S[2];
    Sm[0][1] = Sm[1][0] = S[3]; Sm[0][2] = Sm[2][0] = S[4]; Sm[1][2] = Sm[2][1] = S[5];
#define Q(a, b) (a.x * (Sm[0][0] * b.x + Sm[0][1] * b.y + Sm[0][2] * b.z) + a.y * (Sm[1][0] * b.x + Sm[1][1] * b.y + Sm[1][2] * b.z) + a.z * (Sm[2][0] * b.x + Sm[2][1] * b.y + Sm[2][2] * b.z))
    skk = Q(k, k); sjj = Q(j, j); sii = Q(i, i); skj = Q(k, j); ski = Q(k, i); sji = Q(j, i);
#undef Q
    sdet = sqrtf(fabsf(skk * sjj * sii - skj * skj * sii - ski * ski * sjj - sji * sji * skk + 2.0f * skj * ski * sji));
    isii = 1.0f / sqrtf(sii);
    tmp = sqrtf(sjj * sii - sji * sji);
    Mk = appear_vec3_make(sdet / tmp, 0, 0);
    Mj = appear_vec3_make(-isii * (ski * sji - skj * sii) / tmp, isii * tmp, 0);
    Mi = appear_vec3_make(isii * ski, isii * sji, isii * sii);
    uu = sqrtf(u1) * cosf(ph); vv = sqrtf(u1) * sinf(ph); ww = sqrtf(1.0f - u1);
    m = appear_normalize(appear_add(appear_add(appear_scale(Mk, uu), appear_scale(Mj, vv)), appear_scale(Mi, ww)));
    return appear_add(appear_add(appear_scale(k, m.x), appear_scale(j, m.y)), appear_scale(i, m.z));
}

enum { W_SGGX_D, W_SGGX_D_REF, W_SGGX_SIGMA, W_SGGX_SPEC_EVAL, W_SGGX_VNDF, W_SGGX_VNDF_REF, W_SGGX_SPEC_SAMPLE,
       W_SGGX_DIFF_SAMPLE, W_SGGX_DIFF_EVAL, W_FIBER_D, W_FIBER_SIGMA, W_FIBER_EVAL, W_FIBER_PDF, W_FIBER_SAMPLE,
       W_DHG_EVAL, W_DHG_SAMPLE, W_RAY_EVAL, W_RAY_SAMPLE, W_DRAINE_EVAL, W_DRAINE_SAMPLE, W_MIE_EVAL, W_MIE_SAMPLE,
       W_TAB_EVAL, W_TAB_SAMPLE, W_HG_SAMPLE, W_SGGX_SPEC_PDF, W_DHG_PDF, W_RAY_PDF, W_DRAINE_PDF, W_MIE_PDF, W_TAB_PDF };

static void run(void *c)
{
    const bctx *b = (const bctx *)c;
    float acc = 0.0f;
    int i;
    appear_phase_record s;
    for (i = 0; i < N; ++i) {
        appear_vec3 wo = g_in->wo[i], wi = g_in->wi[i];
        float u1 = g_in->u1[i], u2 = g_in->u2[i];
        switch (b->which) {
        case W_SGGX_D: acc += appear_sggx_D((const appear_sggx *)b->m, wi); break;
        case W_SGGX_D_REF: acc += ref_D((const ref_sggx *)b->m, wi); break;
        case W_SGGX_SIGMA: acc += appear_sggx_sigma((const appear_sggx *)b->m, wo); break;
        case W_SGGX_SPEC_EVAL: acc += appear_sggx_specular_eval((const appear_sggx *)b->m, wo, wi); break;
        case W_SGGX_VNDF: acc += appear_sggx_sample_visible((const appear_sggx *)b->m, wo, u1, u2).x; break;
        case W_SGGX_VNDF_REF: acc += ref_vndf((const ref_sggx *)b->m, wo, u1, u2).x; break;
        case W_SGGX_SPEC_SAMPLE: appear_sggx_specular_sample((const appear_sggx *)b->m, wo, u1, u2, &s); acc += s.wi.x + s.pdf; break;
        case W_SGGX_DIFF_SAMPLE: appear_sggx_diffuse_sample((const appear_sggx *)b->m, wo, u1, u2, g_in->u3[i], g_in->u4[i], &s); acc += s.wi.x; break;
        case W_SGGX_DIFF_EVAL: acc += appear_sggx_diffuse_eval((const appear_sggx *)b->m, wo, wi, u1, u2); break;
        case W_FIBER_D: acc += appear_fiber_D((const appear_fiber *)b->m, wi); break;
        case W_FIBER_SIGMA: acc += appear_fiber_sigma((const appear_fiber *)b->m, wo); break;
        case W_FIBER_EVAL: acc += appear_fiber_eval((const appear_fiber *)b->m, wo, wi); break;
        case W_FIBER_PDF: acc += appear_fiber_pdf((const appear_fiber *)b->m, wo, wi); break;
        case W_FIBER_SAMPLE: appear_fiber_sample((const appear_fiber *)b->m, wo, u1, u2, &s); acc += s.wi.x + s.weight; break;
        case W_DHG_EVAL: acc += appear_dhg_eval((const appear_dhg *)b->m, wo, wi); break;
        case W_DHG_SAMPLE: appear_dhg_sample((const appear_dhg *)b->m, wo, u1, u2, &s); acc += s.wi.x + s.pdf; break;
        case W_RAY_EVAL: acc += appear_rayleigh_eval(wo, wi); break;
        case W_RAY_SAMPLE: appear_rayleigh_sample(wo, u1, u2, &s); acc += s.wi.x + s.pdf; break;
        case W_DRAINE_EVAL: acc += appear_draine_eval((const appear_draine *)b->m, wo, wi); break;
        case W_DRAINE_SAMPLE: appear_draine_sample((const appear_draine *)b->m, wo, u1, u2, &s); acc += s.wi.x + s.pdf; break;
        case W_MIE_EVAL: acc += appear_mie_eval((const appear_mie *)b->m, wo, wi); break;
        case W_MIE_SAMPLE: appear_mie_sample((const appear_mie *)b->m, wo, u1, u2, &s); acc += s.wi.x + s.pdf; break;
        case W_SGGX_SPEC_PDF: acc += appear_sggx_specular_pdf((const appear_sggx *)b->m, wo, wi); break;
        case W_DHG_PDF: acc += appear_dhg_pdf((const appear_dhg *)b->m, wo, wi); break;
        case W_RAY_PDF: acc += appear_rayleigh_pdf(wo, wi); break;
        case W_DRAINE_PDF: acc += appear_draine_pdf((const appear_draine *)b->m, wo, wi); break;
        case W_MIE_PDF: acc += appear_mie_pdf((const appear_mie *)b->m, wo, wi); break;
        case W_TAB_PDF: acc += appear_phase_table_pdf((const appear_phase_table *)b->m, wo, wi); break;
        case W_TAB_EVAL: acc += appear_phase_table_eval((const appear_phase_table *)b->m, wo, wi); break;
        case W_TAB_SAMPLE: appear_phase_table_sample((const appear_phase_table *)b->m, wo, u1, u2, &s); acc += s.wi.x + s.pdf; break;
        default: appear_hg_sample_g(0.7f, wo, u1, u2, &s); acc += s.wi.x + s.pdf; break;
        }
    }
    b_sink = acc;
}

static double row(const char *group, const char *name, int which, const void *m, double err, const char *note)
{
    bctx c;
    double ns;
    c.which = which; c.m = m;
    ns = b_time(run, &c, N);
    b_row(group, name, ns, err, note);
    return ns;
}

/* the fiber sigma per call by the closed form + 48-point quadrature (what
   the table in appear_fiber_make replaces) */
typedef struct { const appear_fiber *m; float inv_b; } fexact;
static void run_fiber_exact(void *c)
{
    const fexact *f = (const fexact *)c;
    float acc = 0.0f;
    int i;
    for (i = 0; i < N / 16; ++i) {
        appear_vec3 l = appear_frame_to_local(f->m->f, g_in->wo[i]);
        acc += appear__fiber_sigma_exact(f->m->p, f->inv_b, fabsf(l.z), sqrtf(l.x * l.x + l.y * l.y));
    }
    b_sink = acc;
}
typedef struct { float p; } fmake;
static void run_fiber_make(void *c)
{
    const fmake *f = (const fmake *)c;
    float acc = 0.0f;
    int i;
    for (i = 0; i < 16; ++i) { appear_fiber m = appear_fiber_make(g_in->wo[i], f->p); acc += m.sigma_max; }
    b_sink = acc;
}

void bench_flakes(void)
{
    static appear_phase_table tab;
    b_rng r = b_rng_make(17);
    int i;
    char note[160];
    appear_sggx sg = appear_sggx_make(1.0f, 0.35f, 0.32f, 0.52f, 0.44f, 0.2f);
    ref_sggx rs = { { 1.0f, 0.35f, 0.32f, 0.52f, 0.44f, 0.2f } };
    appear_fiber fb = appear_fiber_make(appear_normalize(appear_vec3_make(0.3f, 0.5f, 0.8f)), 20.0f);
    appear_dhg dh = appear_dhg_make(0.8f, -0.4f, 0.7f);
    appear_draine dr = appear_draine_make(0.5f, 1.0f);
    appear_mie mi = appear_mie_make(10.0f);
    float vals[256];
    double ns, ns_ref, errD = 0, errV = 0;
    g_in = (inputs *)malloc(sizeof(inputs));
    for (i = 0; i < N; ++i) {
        g_in->u1[i] = b_randf(&r); g_in->u2[i] = b_randf(&r); g_in->u3[i] = b_randf(&r); g_in->u4[i] = b_randf(&r);
        g_in->wo[i] = b_rand_dir(&r); g_in->wi[i] = b_rand_dir(&r);
    }
    for (i = 0; i < 256; ++i) {
        double mu = -1.0 + 2.0 * i / 255.0, d = 1.0 + 0.49 - 1.4 * mu;
        vals[i] = (float)((1 - 0.49) / (4 * 3.14159265358979 * d * sqrt(d)));
    }
    appear_phase_table_make(&tab, vals, NULL, 256);
    /* errors of the eigen-form D and of the raw-entry baseline against a
       double evaluation of the same formula */
    for (i = 0; i < N; ++i) {
        appear_vec3 m = g_in->wi[i];
        const double s[6] = { 1.0, 0.35, 0.32, 0.52, 0.44, 0.2 };
        double a0 = s[1] * s[2] - s[5] * s[5], a1 = s[0] * s[2] - s[4] * s[4], a2 = s[0] * s[1] - s[3] * s[3];
        double a3 = s[4] * s[5] - s[3] * s[2], a4 = s[3] * s[5] - s[4] * s[1], a5 = s[3] * s[4] - s[0] * s[5];
        double det = s[0] * a0 + s[3] * a3 + s[4] * a4;
        double q = (a0 * m.x * m.x + a1 * m.y * m.y + a2 * m.z * m.z + 2 * (a3 * m.x * m.y + a4 * m.x * m.z + a5 * m.y * m.z)) / det;
        double ref = 1.0 / (3.14159265358979 * sqrt(det) * q * q);
        errD = fmax(errD, fabs(appear_sggx_D(&sg, m) - ref) / ref);
        errV = fmax(errV, fabs(ref_D(&rs, m) - ref) / ref);
        (void)a2;
    }
    b_note("flakes: SGGX on the Mitsuba 3 matrix [1,.35,.32,.52,.44,.2], fiber p = 20, Mie d = 10um; inputs drawn before timing");
    ns = row("sggx", "D (eigen form)", W_SGGX_D, &sg, errD, "rel err vs double");
    ns_ref = row("sggx", "D baseline (raw entries, S^-1)", W_SGGX_D_REF, &rs, errV, "rel err vs double");
    snprintf(note, sizeof note, "ratio D/baseline %.2f", ns / ns_ref); b_note("%s", note);
    row("sggx", "sigma(w)", W_SGGX_SIGMA, &sg, -1, "");
    row("sggx", "specular eval (= pdf)", W_SGGX_SPEC_EVAL, &sg, -1, "");
    row("sggx", "specular pdf", W_SGGX_SPEC_PDF, &sg, -1, "");
    ns = row("sggx", "sample_visible", W_SGGX_VNDF, &sg, -1, "");
    ns_ref = row("sggx", "sample_visible baseline (Heitz listing, libm)", W_SGGX_VNDF_REF, &rs, -1, "");
    b_note("ratio sample_visible/baseline %.2f", ns / ns_ref);
    row("sggx", "specular sample", W_SGGX_SPEC_SAMPLE, &sg, -1, "weight 1");
    row("sggx", "diffuse sample", W_SGGX_DIFF_SAMPLE, &sg, -1, "weight 1, + stochastic pdf");
    row("sggx", "diffuse eval (stochastic, 1 normal)", W_SGGX_DIFF_EVAL, &sg, -1, "");
    row("fiber", "D", W_FIBER_D, &fb, -1, "");
    ns = row("fiber", "sigma(w) (table)", W_FIBER_SIGMA, &fb, fb.sigma_err, "err: make's midpoint estimate");
    {
        fexact fe;
        fe.m = &fb; fe.inv_b = 1.0f / (1.77245385091f * appear__flakes_gamma_ratio(0.5f * fb.p + 1.0f));
        ns_ref = b_time(run_fiber_exact, &fe, N / 16);
        b_row("fiber", "sigma(w) baseline (closed form + quadrature)", ns_ref, 0.0, "exact to ~1e-6");
        b_note("ratio sigma table/quadrature %.3f", ns / ns_ref);
    }
    row("fiber", "eval", W_FIBER_EVAL, &fb, -1, "");
    row("fiber", "pdf", W_FIBER_PDF, &fb, -1, "");
    row("fiber", "sample", W_FIBER_SAMPLE, &fb, -1, "never loops");
    {
        fmake fm;
        fm.p = 20.0f;
        b_row("fiber", "make (p = 20)", b_time(run_fiber_make, &fm, 16), -1, "once per material");
    }
    row("phase", "HG sample (reference cost)", W_HG_SAMPLE, NULL, -1, "");
    row("phase", "double HG eval", W_DHG_EVAL, &dh, -1, "");
    row("phase", "double HG pdf", W_DHG_PDF, &dh, -1, "");
    row("phase", "double HG sample", W_DHG_SAMPLE, &dh, -1, "");
    row("phase", "Rayleigh eval", W_RAY_EVAL, NULL, -1, "");
    row("phase", "Rayleigh pdf", W_RAY_PDF, NULL, -1, "");
    row("phase", "Rayleigh sample", W_RAY_SAMPLE, NULL, -1, "closed form");
    row("phase", "Draine eval", W_DRAINE_EVAL, &dr, -1, "");
    row("phase", "Draine pdf", W_DRAINE_PDF, &dr, -1, "");
    row("phase", "Draine sample", W_DRAINE_SAMPLE, &dr, -1, "Newton in double");
    row("phase", "Mie (HG+Draine, d=10um) eval", W_MIE_EVAL, &mi, -1, "");
    row("phase", "Mie (HG+Draine, d=10um) pdf", W_MIE_PDF, &mi, -1, "");
    row("phase", "Mie (HG+Draine, d=10um) sample", W_MIE_SAMPLE, &mi, -1, "");
    row("phase", "table (256 nodes) eval", W_TAB_EVAL, &tab, -1, "");
    row("phase", "table (256 nodes) pdf", W_TAB_PDF, &tab, -1, "");
    row("phase", "table (256 nodes) sample", W_TAB_SAMPLE, &tab, -1, "");
    free(g_in);
}
