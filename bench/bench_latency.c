/* bench/bench_latency.c - group `latency`: the figure a path tracer feels.
 *
 * Every public eval / pdf / sample function (and the building blocks a
 * renderer calls per vertex: Fresnel, D, Lambda, SGGX sigma / D) is called
 * one at a time in a dependent chain: the index of the next pre-drawn input
 * is the top bits of h = (h ^ bits(result)) * 0x9e3779b1, an address
 * dependency the compiler cannot remove, so consecutive calls cannot
 * overlap. The 32-bit state makes the order of the inputs pseudo-random
 * with no short cycle: branch predictors cannot learn the inputs' branch
 * outcomes, as they cannot in a renderer (the earlier index k + 1 + (bits &
 * 1) went round the 512 inputs in a cycle of about 340 calls, which a
 * modern predictor learns, flattering code that branches on data). Every
 * run starts the hash from its own seed: a run that repeated the previous
 * run's 32,768 indices let the predictor learn part of them across runs
 * (Fresnel dielectric 0.81 -> 0.87, Lambert eval 2.00 -> 2.15 once
 * reseeded, issue 36). Every input of a call (directions, random numbers)
 * comes from the row the chain picks, so all of them wait for the previous
 * result, as in a renderer where a ray cast sits between two calls. Each
 * function sits behind an __attribute__((noinline)) wrapper
 * `float w(const lat_in *in)` that returns a float summary of its output;
 * appear and the baseline have wrappers of the same shape and are called
 * by the same loop. Inputs are drawn before timing (the RNG is not timed).
 *
 * Block 1: appear's function against a plain baseline from tests/listings.h
 * (pbrt-v4 / Mitsuba 3 style, libm), timed in alternation
 * (b_time_latency_pair, median of per-pair ratios). Before timing, each pair
 * is run on the same LAT_N inputs and compared (the note's `check`):
 *   value   the two summaries, max relative difference;
 *   pdf/f   samplers whose mapping of (u1, u2) differs: appear's pdf (and
 *           eval) at the baseline's sampled direction against the baseline's
 *           pdf (and f), max relative difference;
 * `bad` counts inputs with relative difference > 1e-3; absolute differences
 * below 1e-12 count as equal (the far tails, where the cut-offs differ).
 * CSV rows: "<name>" (appear, note "ratio=R ...") and "<name> [baseline]".
 * Block 2: every other public _eval/_pdf/_sample, no baseline ("ratio=-").
 *
 * One row or a few:  ./build/bench_O2 latency hg       (substring of the row name)
 *                    ./build/bench_O2 latency "hg_sample g=0.9"
 *                    APPEAR_BENCH_FILTER=dielectric ./build/bench_O3native latency
 *                    ./build/bench_O2 latency --filter=ward   (ward is also a group name)
 * APPEAR_BENCH_QUICK=1 runs fewer and shorter repetitions.
 */
#include "bench.h"
#include "../tests/listings.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

/* Every wrapper starts on its own 64-byte line: where the linker happened to put a short one
   moved it by 0.3 ns (pbrt-v4's Lambert eval 1.65 or 1.95 ns in two builds of the same code). */
#if defined(__GNUC__) || defined(__clang__)
#define LAT_NOINLINE __attribute__((noinline, aligned(64)))
#else
#define LAT_NOINLINE
#endif

enum { LAT_LOG2N = 9, LAT_N = 1 << LAT_LOG2N }; /* inputs: 512 x 64 bytes = 32 KiB, L1-resident */
typedef struct {
    appear_vec3 wo, wi, m;
    float u1, u2, uc, x, t, d;
    float pad[3];
} lat_in;
static lat_in g_in[LAT_N];
static long g_calls;
static unsigned g_run; /* runs so far: each run starts the hash from its own seed */

typedef float (*lat_fn)(const lat_in *in);
typedef struct { lat_fn fn; } lat_job;

static unsigned lat_bits(float r) { unsigned b; memcpy(&b, &r, sizeof b); return b; }
static void lat_run(void *ctx)
{
    lat_fn fn = ((const lat_job *)ctx)->fn;
    unsigned h = (0x9e3779b9u ^ ++g_run) * 0x85ebca6bu, k = h >> (32 - LAT_LOG2N);
    long i;
    for (i = 0; i < g_calls; ++i) {
        float r = fn(&g_in[k]);
        h = (h ^ lat_bits(r)) * 0x9e3779b1u;  /* a 32-bit state: no short cycle to learn */
        k = h >> (32 - LAT_LOG2N);
    }
    b_sink = (float)k;
}

/* ---- models (appear's, and the same parameters for the baselines) ---- */
static lst_sampled g_R4; /* pbrt-v4's R: NSpectrumSamples = 4, the fourth 0 */
static appear_spectrum g_R, g_eta3, g_k3, g_sig3, g_sig1;
static appear_lambert g_lam;
static appear_eon g_eon, g_eon_cos;
static lst_eon g_leon;
static appear_sheen g_sheen;
static float g_g, g_ax, g_ay;
static appear_conductor g_cond;
static lst_conductor g_lcond;
static appear_dielectric g_diel;
static lst_dielectric g_ldiel;
static appear_ward g_ward;
static lst_ward06 g_lward;
static appear_sggx g_sggx;
static float g_S[6] = { 1.0f, 0.35f, 0.32f, 0.52f, 0.44f, 0.2f };        /* lambda_max / lambda_min 33 */
static float g_S2[6] = { 1.0f, 0.8f, 0.6f, 0.1f, 0.15f, 0.05f };         /* well conditioned */
static appear_sggx g_sggx2;
static float g_S3[6]; /* lambda_max / lambda_min 1e4: nearly singular, the eigenbasis form */
static appear_sggx g_sggx3;
static appear_thin_dielectric g_thin;
static appear_thinfilm_conductor g_tfc;
static appear_fiber g_fiber;
static appear_dhg g_dhg;
static appear_draine g_draine;
static appear_mie g_mie;
static appear_phase_table g_tab;
static appear_rng g_rng;
static appear_layered g_layered;

static float s3(appear_spectrum s) { float a = 0; int i; for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) a += s.v[i]; return a; }
static float bs_sum(const appear_bsdf_record *s) { return s->wi.x + s->wi.y + s->wi.z + s->pdf + s3(s->weight); }
static float ps_sum(const appear_phase_record *s) { return s->wi.x + s->wi.y + s->wi.z + s->pdf; }
static float ms_sum(const appear_medium_sample *s) { return s->t + s->pdf + s3(s->weight); }

/* ---- wrappers: A_ = appear, B_ = baseline; one line each, same shape ---- */
#define W(name, expr) static LAT_NOINLINE float name(const lat_in *in) { return (expr); }
#define WS(name, T, call, sum) static LAT_NOINLINE float name(const lat_in *in) { T s; (void)(call); return sum(&s); }

W(A_lambert_eval, s3(appear_lambert_eval(&g_lam, in->wo, in->wi)))
/* summed as s3 sums (from 0: the same adds on both sides of the chain) */
static float s4(lst_sampled s) { float a = 0; int i; for (i = 0; i < 4; ++i) a += s.v[i]; return a; }
W(B_lambert_eval, s4(lst_lambert_eval(g_R4, in->wo, in->wi)))
W(A_lambert_pdf, appear_lambert_pdf(&g_lam, in->wo, in->wi))
W(B_lambert_pdf, lst_lambert_pdf(in->wo, in->wi))
WS(A_lambert_sample, appear_bsdf_record, appear_lambert_sample(&g_lam, in->wo, in->uc, in->u1, in->u2, &s), bs_sum)
WS(B_lambert_sample, appear_bsdf_record, lst_lambert_sample(g_R, in->wo, in->u1, in->u2, &s), bs_sum)
W(A_eon_eval, s3(appear_eon_eval(&g_eon, in->wo, in->wi)))
W(B_eon_eval, s3(lst_eon_eval(&g_leon, in->wo, in->wi)))
W(B_fon_eval, s3(lst_fon_eval(&g_leon, in->wo, in->wi)))
W(A_eon_pdf, appear_eon_pdf(&g_eon, in->wo, in->wi))
W(B_eon_pdf, lst_eon_pdf(&g_leon, in->wo, in->wi))
WS(A_eon_sample, appear_bsdf_record, appear_eon_sample(&g_eon, in->wo, in->uc, in->u1, in->u2, &s), bs_sum)
WS(A_eon_sample_cos, appear_bsdf_record, appear_eon_sample(&g_eon_cos, in->wo, in->uc, in->u1, in->u2, &s), bs_sum)
WS(B_eon_sample, appear_bsdf_record, lst_eon_sample(&g_leon, in->wo, in->u1, in->u2, &s), bs_sum)
W(A_sheen_eval, s3(appear_sheen_eval(&g_sheen, in->wo, in->wi)))
W(A_sheen_pdf, appear_sheen_pdf(&g_sheen, in->wo, in->wi))
WS(A_sheen_sample, appear_bsdf_record, appear_sheen_sample(&g_sheen, in->wo, in->uc, in->u1, in->u2, &s), bs_sum)
W(A_layered_eval, s3(appear_layered_eval(&g_layered, in->wo, in->wi, &g_rng)))
W(A_layered_pdf, appear_layered_pdf(&g_layered, in->wo, in->wi, &g_rng))
WS(A_layered_sample, appear_bsdf_record, appear_layered_sample(&g_layered, in->wo, &g_rng, &s), bs_sum)
WS(A_iso_sample, appear_phase_record, appear_isotropic_sample(in->wo, in->u1, in->u2, &s), ps_sum)
WS(B_iso_sample, appear_phase_record, lst_isotropic_sample(in->wo, in->u1, in->u2, &s), ps_sum)
W(A_hg_eval, appear_hg_eval_g(g_g, in->wo, in->wi))
W(B_hg_eval, lst_hg_eval(g_g, in->wo, in->wi))
WS(A_hg_sample, appear_phase_record, appear_hg_sample_g(g_g, in->wo, in->u1, in->u2, &s), ps_sum)
WS(B_hg_sample, appear_phase_record, lst_hg_sample(g_g, in->wo, in->u1, in->u2, &s), ps_sum)
W(A_fr_diel, appear_fresnel_dielectric(in->x, 1.5f))
W(B_fr_diel, lst_fresnel_dielectric(in->x, 1.5f))
W(A_fr_cond, appear_fresnel_conductor(in->wo.z, 0.143f, 3.983f))
W(B_fr_cond, lst_fresnel_complex(in->wo.z, 0.143f, 3.983f))
W(B_fr_cond_mi3, lst_fresnel_conductor_mi3(in->wo.z, 0.143f, 3.983f))
W(A_fr_cond3, s3(appear_fresnel_conductor_spectrum(in->wo.z, g_eta3, g_k3)))
W(B_fr_cond3, s3(lst_fresnel_complex_spectrum(in->wo.z, g_eta3, g_k3)))
W(A_fr_schlick, appear_fresnel_schlick(in->wo.z, 0.04f))
W(B_fr_schlick, lst_fresnel_schlick(in->wo.z, 0.04f))
W(A_ggx_D, appear_ggx_D(g_ax, g_ay, in->m))
W(B_ggx_D, lst_ggx_D(g_ax, g_ay, in->m))
W(A_ggx_lambda, appear_ggx_lambda(g_ax, g_ay, in->wo))
W(B_ggx_lambda, lst_ggx_lambda(g_ax, g_ay, in->wo))
static LAT_NOINLINE float A_ggx_vis(const lat_in *in) { appear_vec3 m = appear_ggx_sample_visible(g_ax, g_ay, in->wo, in->u1, in->u2); return m.x + m.y + m.z; }
static LAT_NOINLINE float B_ggx_vis(const lat_in *in) { appear_vec3 m = lst_ggx_sample_wm(g_ax, g_ay, in->wo, in->u1, in->u2); return m.x + m.y + m.z; }
W(A_ggx_pdfv, appear_ggx_pdf_visible(g_ax, g_ay, in->wo, in->m))
W(B_ggx_pdfv, lst_ggx_pdf_visible(g_ax, g_ay, in->wo, in->m))
W(A_beck_D, appear_beckmann_D(g_ax, g_ay, in->m))
W(B_beck_D, lst_beckmann_D(g_ax, g_ay, in->m))
static LAT_NOINLINE float A_beck_vis(const lat_in *in) { appear_vec3 m = appear_beckmann_sample_visible(g_ax, g_ay, in->wo, in->u1, in->u2); return m.x + m.y + m.z; }
static LAT_NOINLINE float B_beck_vis(const lat_in *in) { appear_vec3 m = lst_beckmann_sample_visible(g_ax, g_ay, in->wo, in->u1, in->u2); return m.x + m.y + m.z; }
W(A_cond_eval, s3(appear_conductor_eval(&g_cond, in->wo, in->wi)))
W(B_cond_eval, s3(lst_conductor_eval(&g_lcond, in->wo, in->wi)))
W(A_cond_pdf, appear_conductor_pdf(&g_cond, in->wo, in->wi))
W(B_cond_pdf, lst_conductor_pdf(&g_lcond, in->wo, in->wi))
WS(A_cond_sample, appear_bsdf_record, appear_conductor_sample(&g_cond, in->wo, in->uc, in->u1, in->u2, &s), bs_sum)
WS(B_cond_sample, appear_bsdf_record, lst_conductor_sample(&g_lcond, in->wo, in->u1, in->u2, &s), bs_sum)
W(A_diel_eval, s3(appear_dielectric_eval(&g_diel, in->wo, in->wi)))
W(B_diel_eval, lst_dielectric_eval(&g_ldiel, in->wo, in->wi) * (float)APPEAR_SPECTRUM_SAMPLES)
W(A_diel_pdf, appear_dielectric_pdf(&g_diel, in->wo, in->wi))
W(B_diel_pdf, lst_dielectric_pdf(&g_ldiel, in->wo, in->wi))
WS(A_diel_sample, appear_bsdf_record, appear_dielectric_sample(&g_diel, in->wo, in->uc, in->u1, in->u2, &s), bs_sum)
WS(B_diel_sample, appear_bsdf_record, lst_dielectric_sample(&g_ldiel, in->wo, in->uc, in->u1, in->u2, &s), bs_sum)
/* Mitsuba 0.6's eval returns f cos(wi): appear's side multiplies, as its caller would */
W(A_ward_eval, s3(appear_ward_eval(&g_ward, in->wo, in->wi)) * in->wi.z)
W(B_ward_eval, s3(lst_ward06_eval(&g_lward, in->wo, in->wi)))
W(A_ward_pdf, appear_ward_pdf(&g_ward, in->wo, in->wi))
W(B_ward_pdf, lst_ward06_pdf(&g_lward, in->wo, in->wi))
WS(A_ward_sample, appear_bsdf_record, appear_ward_sample(&g_ward, in->wo, in->uc, in->u1, in->u2, &s), bs_sum)
WS(B_ward_sample, appear_bsdf_record, lst_ward06_sample(&g_lward, in->wo, in->u1, in->u2, &s), bs_sum)
W(A_sggx_sigma, appear_sggx_sigma(&g_sggx, in->wo))
W(B_sggx_sigma, lst_sggx_sigma(g_S, in->wo))
W(A_sggx_sigma2, appear_sggx_sigma(&g_sggx2, in->wo))
W(B_sggx_sigma2, lst_sggx_sigma(g_S2, in->wo))
W(A_sggx_sigma3, appear_sggx_sigma(&g_sggx3, in->wo))
W(B_sggx_sigma3, lst_sggx_sigma(g_S3, in->wo))
W(A_sggx_D3, appear_sggx_D(&g_sggx3, in->wo))
W(B_sggx_D3, lst_sggx_D(g_S3, in->wo))
W(A_sggx_D, appear_sggx_D(&g_sggx, in->wo))
W(A_sggx_D2, appear_sggx_D(&g_sggx2, in->wo))
W(B_sggx_D2, lst_sggx_D(g_S2, in->wo))
W(B_sggx_D, lst_sggx_D(g_S, in->wo))
WS(A_homog3, appear_medium_sample, appear_homogeneous_sample(g_sig3, in->d, in->uc, in->u1, &s), ms_sum)
WS(B_homog3, appear_medium_sample, lst_homogeneous_sample(g_sig3, in->d, in->uc, in->u1, &s), ms_sum)
WS(A_homog1, appear_medium_sample, appear_homogeneous_sample(g_sig1, in->d, in->uc, in->u1, &s), ms_sum)
WS(B_homog1, appear_medium_sample, lst_homogeneous_sample1(g_sig1.v[0], in->d, in->u1, &s), ms_sum)
/* block 1b: the samplers with the chain through what the next call waits for; the other outputs
   are still consumed (added into g_side, off the chain), so an inlined baseline cannot drop them */
static float g_side;
static float ps_wi(const appear_phase_record *s) { g_side += s->pdf; return s->wi.x + s->wi.y + s->wi.z; }
static float ms_t(const appear_medium_sample *s) { g_side += s->pdf + s3(s->weight); return s->t; }
WS(A_hg_sample_wi, appear_phase_record, appear_hg_sample_g(g_g, in->wo, in->u1, in->u2, &s), ps_wi)
WS(B_hg_sample_wi, appear_phase_record, lst_hg_sample(g_g, in->wo, in->u1, in->u2, &s), ps_wi)
static float bs_wi(const appear_bsdf_record *s) { g_side += s->pdf + s3(s->f) + s3(s->weight); return s->wi.x + s->wi.y + s->wi.z; }
WS(A_cond_sample_wi, appear_bsdf_record, appear_conductor_sample(&g_cond, in->wo, in->uc, in->u1, in->u2, &s), bs_wi)
WS(B_cond_sample_wi, appear_bsdf_record, lst_conductor_sample(&g_lcond, in->wo, in->u1, in->u2, &s), bs_wi)
WS(A_diel_sample_wi, appear_bsdf_record, appear_dielectric_sample(&g_diel, in->wo, in->uc, in->u1, in->u2, &s), bs_wi)
WS(B_diel_sample_wi, appear_bsdf_record, lst_dielectric_sample(&g_ldiel, in->wo, in->uc, in->u1, in->u2, &s), bs_wi)
/* the floor of a validated Lambert eval: appear's side test on the bits alone, without the two
   unit-length checks the robustness contract adds (not a public function) */
W(A_lambert_eval_side, s3(appear__same_side(in->wo.z, in->wi.z) ? appear_spectrum_scale(g_lam.albedo, APPEAR_INV_PI)
                                                                : appear_spectrum_splat(0.0f)))
WS(A_homog3_t, appear_medium_sample, appear_homogeneous_sample(g_sig3, in->d, in->uc, in->u1, &s), ms_t)
WS(B_homog3_t, appear_medium_sample, lst_homogeneous_sample(g_sig3, in->d, in->uc, in->u1, &s), ms_t)
W(A_homog_pdf_s, appear_homogeneous_pdf(g_sig3, in->d, in->t, 1))
W(B_homog_pdf_s, lst_homogeneous_pdf(g_sig3, in->d, in->t, 1))
W(A_homog_pdf_p, appear_homogeneous_pdf(g_sig3, in->d, in->t, 0))
W(B_homog_pdf_p, lst_homogeneous_pdf(g_sig3, in->d, in->t, 0))

/* block 2 (no baseline) */
W(A_iso_eval, appear_isotropic_eval(in->wo, in->wi))
W(A_iso_pdf, appear_isotropic_pdf(in->wo, in->wi))
W(A_hg_pdf, appear_hg_pdf_g(g_g, in->wo, in->wi))
W(A_wards_eval, appear_ward_specular_eval(APPEAR_WARD_BALANCED, g_ax, g_ay, in->wo, in->wi))
W(A_wards_pdf, appear_ward_specular_pdf(g_ax, g_ay, in->wo, in->wi))
W(A_thin_eval, s3(appear_thin_dielectric_eval(&g_thin, in->wo, in->wi)))
W(A_thin_pdf, appear_thin_dielectric_pdf(&g_thin, in->wo, in->wi))
WS(A_thin_sample, appear_bsdf_record, appear_thin_dielectric_sample(&g_thin, in->wo, in->uc, in->u1, in->u2, &s), bs_sum)
W(A_tfc_eval, s3(appear_thinfilm_conductor_eval(&g_tfc, in->wo, in->wi)))
W(A_tfc_pdf, appear_thinfilm_conductor_pdf(&g_tfc, in->wo, in->wi))
WS(A_tfc_sample, appear_bsdf_record, appear_thinfilm_conductor_sample(&g_tfc, in->wo, in->uc, in->u1, in->u2, &s), bs_sum)
W(A_ccomp_eval, s3(appear_conductor_comp_eval(&g_cond, in->wo, in->wi)))
W(A_ccomp_pdf, appear_conductor_comp_pdf(&g_cond, in->wo, in->wi))
WS(A_ccomp_sample, appear_bsdf_record, appear_conductor_comp_sample(&g_cond, in->wo, in->uc, in->u1, in->u2, &s), bs_sum)
W(A_dcomp_eval, s3(appear_dielectric_comp_eval(&g_diel, in->wo, in->wi)))
W(A_dcomp_pdf, appear_dielectric_comp_pdf(&g_diel, in->wo, in->wi))
WS(A_dcomp_sample, appear_bsdf_record, appear_dielectric_comp_sample(&g_diel, in->wo, in->uc, in->u1, in->u2, &s), bs_sum)
W(A_cms_eval, s3(appear_conductor_ms_eval(&g_cond, in->wo, in->wi, &g_rng)))
W(A_cms_pdf, appear_conductor_ms_pdf(&g_cond, in->wo, in->wi))
WS(A_cms_sample, appear_bsdf_record, appear_conductor_ms_sample(&g_cond, in->wo, &g_rng, &s), bs_sum)
W(A_dms_eval, s3(appear_dielectric_ms_eval(&g_diel, in->wo, in->wi, &g_rng)))
W(A_dms_pdf, appear_dielectric_ms_pdf(&g_diel, in->wo, in->wi))
WS(A_dms_sample, appear_bsdf_record, appear_dielectric_ms_sample(&g_diel, in->wo, &g_rng, &s), bs_sum)
W(A_sggxs_eval, appear_sggx_specular_eval(&g_sggx, in->wo, in->wi))
W(A_sggxs_pdf, appear_sggx_specular_pdf(&g_sggx, in->wo, in->wi))
WS(A_sggxs_sample, appear_phase_record, appear_sggx_specular_sample(&g_sggx, in->wo, in->u1, in->u2, &s), ps_sum)
W(A_sggxd_eval, appear_sggx_diffuse_eval(&g_sggx, in->wo, in->wi, in->u1, in->u2))
WS(A_sggxd_sample, appear_phase_record, appear_sggx_diffuse_sample(&g_sggx, in->wo, in->u1, in->u2, in->uc, in->x * 0.5f + 0.5f, &s), ps_sum)
W(A_fiber_eval, appear_fiber_eval(&g_fiber, in->wo, in->wi))
W(A_fiber_pdf, appear_fiber_pdf(&g_fiber, in->wo, in->wi))
WS(A_fiber_sample, appear_phase_record, appear_fiber_sample(&g_fiber, in->wo, in->u1, in->u2, &s), ps_sum)
W(A_dhg_eval, appear_dhg_eval(&g_dhg, in->wo, in->wi))
W(A_dhg_pdf, appear_dhg_pdf(&g_dhg, in->wo, in->wi))
WS(A_dhg_sample, appear_phase_record, appear_dhg_sample(&g_dhg, in->wo, in->u1, in->u2, &s), ps_sum)
W(A_ray_eval, appear_rayleigh_eval(in->wo, in->wi))
W(A_ray_pdf, appear_rayleigh_pdf(in->wo, in->wi))
WS(A_ray_sample, appear_phase_record, appear_rayleigh_sample(in->wo, in->u1, in->u2, &s), ps_sum)
W(A_draine_eval, appear_draine_eval(&g_draine, in->wo, in->wi))
W(A_draine_pdf, appear_draine_pdf(&g_draine, in->wo, in->wi))
WS(A_draine_sample, appear_phase_record, appear_draine_sample(&g_draine, in->wo, in->u1, in->u2, &s), ps_sum)
W(A_mie_eval, appear_mie_eval(&g_mie, in->wo, in->wi))
W(A_mie_pdf, appear_mie_pdf(&g_mie, in->wo, in->wi))
WS(A_mie_sample, appear_phase_record, appear_mie_sample(&g_mie, in->wo, in->u1, in->u2, &s), ps_sum)
W(A_tab_eval, appear_phase_table_eval(&g_tab, in->wo, in->wi))
W(A_tab_pdf, appear_phase_table_pdf(&g_tab, in->wo, in->wi))
WS(A_tab_sample, appear_phase_record, appear_phase_table_sample(&g_tab, in->wo, in->u1, in->u2, &s), ps_sum)

/* ---- inputs ---- */
enum { IN_HEMI = 0, IN_SPHERE = 1, IN_DIEL = 2, IN_DIEL_INSIDE = 3 };
/* IN_HEMI: wo, wi uniform on the upper hemisphere; IN_SPHERE: both on the
   sphere (phase functions); IN_DIEL: wo upper, wi on the sphere (R and T);
   IN_DIEL_INSIDE: wo lower (inside the dielectric), wi on the sphere.
   Always: m = normalize(wo + wi) flipped up (a half vector, for D and the
   visible pdfs), u1, u2, uc uniform, x uniform in [-1, 1] (signed cosine),
   d = 2 u (segment length), t uniform in [0, d). */
static void lat_inputs(int kind, uint64_t seed)
{
    b_rng r = b_rng_make(seed);
    int i;
    for (i = 0; i < LAT_N; ++i) {
        lat_in *p = &g_in[i];
        appear_vec3 h;
        p->wo = kind == IN_SPHERE ? b_rand_dir(&r) : b_rand_hemi(&r);
        if (kind == IN_DIEL_INSIDE) p->wo.z = -p->wo.z;
        p->wi = kind == IN_HEMI ? b_rand_hemi(&r) : b_rand_dir(&r);
        h = appear_add(p->wo, p->wi);
        h = appear_dot(h, h) > 1e-12f ? appear_normalize(h) : appear_vec3_make(0, 0, 1);
        if (h.z < 0) h = appear_neg(h);
        p->m = h;
        p->u1 = b_randf(&r); p->u2 = b_randf(&r); p->uc = b_randf(&r);
        p->x = (float)(2.0 * b_rand(&r) - 1.0);
        p->d = 2.0f * b_randf(&r);
        p->t = p->d * b_randf(&r);
    }
}

/* ---- correctness checks ---- */
static double rel(double a, double b)
{
    double m = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
    if (a != a || b != b) return (a != a && b != b) ? 0.0 : 1.0;
    if (fabs(a - b) <= 1e-12) return 0.0; /* tails: Mitsuba cuts D below 1e-20, appear at exp(-88) */
    return m > 0 ? fabs(a - b) / m : 0.0;
}
static double g_bad_tol = 1e-3;
typedef double (*lat_check)(lat_fn a, lat_fn b, int *bad);
static double chk_value(lat_fn a, lat_fn b, int *bad)
{
    double worst = 0; int i;
    *bad = 0;
    for (i = 0; i < LAT_N; ++i) {
        double e = rel(a(&g_in[i]), b(&g_in[i]));
        *bad += e > g_bad_tol;
        if (e > worst) worst = e;
    }
    return worst;
}
#define CHK_ACC(e) do { double e_ = (e); *bad += e_ > g_bad_tol; if (e_ > worst) worst = e_; } while (0)
/* samplers whose (u1, u2) mapping differs: appear's pdf/eval at the
   baseline's sample against the baseline's pdf/f */
static double chk_hg_sample(lat_fn a, lat_fn b, int *bad)
{
    double worst = 0; int i; (void)a; (void)b; *bad = 0;
    for (i = 0; i < LAT_N; ++i) {
        appear_phase_record s;
        lst_hg_sample(g_g, g_in[i].wo, g_in[i].u1, g_in[i].u2, &s);
        CHK_ACC(rel(appear_hg_pdf_g(g_g, g_in[i].wo, s.wi), s.pdf));
    }
    return worst;
}
static double chk_eon_sample(lat_fn a, lat_fn b, int *bad)
{
    double worst = 0; int i; (void)a; (void)b; *bad = 0;
    for (i = 0; i < LAT_N; ++i) {
        appear_bsdf_record s;
        if (!lst_eon_sample(&g_leon, g_in[i].wo, g_in[i].u1, g_in[i].u2, &s)) continue;
        CHK_ACC(rel(appear_eon_pdf(&g_eon, g_in[i].wo, s.wi), s.pdf));
        CHK_ACC(rel(s3(appear_eon_eval(&g_eon, g_in[i].wo, s.wi)), s3(s.f)));
    }
    return worst;
}
/* FON alone against appear's full EON: the value differs by f_ms (no check) */
static double chk_none(lat_fn a, lat_fn b, int *bad) { (void)a; (void)b; *bad = 0; return 0.0; }
static double chk_ggx_vis(lat_fn a, lat_fn b, int *bad)
{
    double worst = 0; int i; (void)a; (void)b; *bad = 0;
    for (i = 0; i < LAT_N; ++i) {
        appear_vec3 m = lst_ggx_sample_wm(g_ax, g_ay, g_in[i].wo, g_in[i].u1, g_in[i].u2);
        CHK_ACC(rel(appear_ggx_pdf_visible(g_ax, g_ay, g_in[i].wo, m), lst_ggx_pdf_visible(g_ax, g_ay, g_in[i].wo, m)));
    }
    return worst;
}
static double chk_cond_sample(lat_fn a, lat_fn b, int *bad)
{
    double worst = 0; int i; (void)a; (void)b; *bad = 0;
    for (i = 0; i < LAT_N; ++i) {
        appear_bsdf_record s;
        if (!lst_conductor_sample(&g_lcond, g_in[i].wo, g_in[i].u1, g_in[i].u2, &s)) continue;
        CHK_ACC(rel(appear_conductor_pdf(&g_cond, g_in[i].wo, s.wi), s.pdf));
        CHK_ACC(rel(s3(appear_conductor_eval(&g_cond, g_in[i].wo, s.wi)), s3(s.f)));
    }
    return worst;
}
static double chk_diel_sample(lat_fn a, lat_fn b, int *bad)
{
    double worst = 0; int i; (void)a; (void)b; *bad = 0;
    for (i = 0; i < LAT_N; ++i) {
        appear_bsdf_record s;
        if (!lst_dielectric_sample(&g_ldiel, g_in[i].wo, g_in[i].uc, g_in[i].u1, g_in[i].u2, &s)) continue;
        CHK_ACC(rel(appear_dielectric_pdf(&g_diel, g_in[i].wo, s.wi), s.pdf));
        CHK_ACC(rel(appear_dielectric_eval(&g_diel, g_in[i].wo, s.wi).v[0], s.f.v[0]));
    }
    return worst;
}

static double chk_ward_sample(lat_fn a, lat_fn b, int *bad)
{
    double worst = 0; int i; (void)a; (void)b; *bad = 0;
    for (i = 0; i < LAT_N; ++i) {
        appear_bsdf_record s;
        float p;
        if (!lst_ward06_sample(&g_lward, g_in[i].wo, g_in[i].u1, g_in[i].u2, &s)) continue;
        p = appear_ward_pdf(&g_ward, g_in[i].wo, s.wi);
        CHK_ACC(rel(p, s.pdf));
        CHK_ACC(rel(s3(appear_ward_eval(&g_ward, g_in[i].wo, s.wi)) * s.wi.z / p, s3(s.weight)));
    }
    return worst;
}
/* HG sample's pdf against the density at the returned direction in double: appear's (the pdf
   at wi) and the sampled cosine's (pbrt-v4's form, without its clamp of g to 0.99, which makes
   g = 0.999 another function), max relative errors */
static double hg_density(double g, appear_vec3 wo, appear_vec3 wi)
{
    double lo = sqrt((double)wo.x * wo.x + (double)wo.y * wo.y + (double)wo.z * wo.z);
    double li = sqrt((double)wi.x * wi.x + (double)wi.y * wi.y + (double)wi.z * wi.z);
    double mu = -((double)wo.x * wi.x + (double)wo.y * wi.y + (double)wo.z * wi.z) / (lo * li);
    double d = 1.0 + g * g - 2.0 * g * mu;
    return (1.0 - g * g) / (4.0 * 3.14159265358979323846 * d * sqrt(d));
}
static void hg_pdf_errors(float g, double *err_appear, double *err_base)
{
    int i;
    *err_appear = *err_base = 0;
    for (i = 0; i < LAT_N; ++i) {
        appear_phase_record a, b;
        double ea, eb;
        if (appear_hg_sample_g(g, g_in[i].wo, g_in[i].u1, g_in[i].u2, &a)) {
            ea = fabs(a.pdf - hg_density(g, g_in[i].wo, a.wi)) / hg_density(g, g_in[i].wo, a.wi);
            if (ea > *err_appear) *err_appear = ea;
        }
        if (lst_hg_sample_unclamped(g, g_in[i].wo, g_in[i].u1, g_in[i].u2, &b)) {
            eb = fabs(b.pdf - hg_density(g, g_in[i].wo, b.wi)) / hg_density(g, g_in[i].wo, b.wi);
            if (eb > *err_base) *err_base = eb;
        }
    }
}

/* The Ward lobe alone (rho_d = 0, rho_s = 1, ORIGINAL) against double from the same float
   directions: appear's and Mitsuba 0.6's max relative errors where the lobe is >= floor. Its
   float exponent E's rounding is amplified by E itself (E up to 87: ~2.5e-5 at the far tail);
   Mitsuba cuts values below 1e-10 to 0. */
static void ward_lobe_errors(float ax, float ay, double floor_v, double *err_appear, double *err_base)
{
    appear_ward w = appear_ward_make(appear_spectrum_splat(0.0f), appear_spectrum_splat(1.0f), ax, ay,
                                     APPEAR_WARD_ORIGINAL);
    lst_ward06 l = lst_ward06_make(appear_spectrum_splat(0.0f), appear_spectrum_splat(1.0f), ax, ay, LST_WARD06_WARD);
    int i;
    *err_appear = *err_base = 0;
    for (i = 0; i < LAT_N; ++i) {
        appear_vec3 o = g_in[i].wo, v = g_in[i].wi;
        double hx = (double)o.x + v.x, hy = (double)o.y + v.y, hz = (double)o.z + v.z;
        double e = (hx * hx / ((double)ax * ax) + hy * hy / ((double)ay * ay)) / (hz * hz);
        double ref = exp(-e) / (4.0 * 3.14159265358979323846 * ax * ay * sqrt((double)o.z * v.z));
        double a = appear_ward_eval(&w, o, v).v[0], b = lst_ward06_eval(&l, o, v).v[0] / v.z;
        if (!(ref >= floor_v)) continue;
        if (fabs(a - ref) / ref > *err_appear) *err_appear = fabs(a - ref) / ref;
        if (fabs(b - ref) / ref > *err_base) *err_base = fabs(b - ref) / ref;
    }
}

/* the rough conductor of both sides: appear's model and the baseline's parameters */
/* The generic interface (appear_bsdf) over a mix of 4 families (Lambert, Ward, GGX conductor,
   GGX dielectric), the material chosen by the input's index (so by the chain: unpredictable),
   against the direct calls behind the caller's own switch on its material's kind, read from
   memory as appear_bsdf's kind is: what a renderer without the interface writes. */
static appear_bsdf g_mix[4];
static int g_mix_kind[4] = { 0, 1, 2, 3 }; /* the caller's material records: their kinds */
static int lat_family(const lat_in *in) { return (int)(in - g_in) & 3; }
WS(A_mix_sample, appear_bsdf_record,
   appear_bsdf_sample(&g_mix[lat_family(in)], in->wo, in->uc, in->u1, in->u2, &s), bs_sum)
W(A_mix_eval, s3(appear_bsdf_eval(&g_mix[lat_family(in)], in->wo, in->wi)))
static LAT_NOINLINE float B_mix_sample(const lat_in *in)
{
    appear_bsdf_record s;
    switch (g_mix_kind[lat_family(in)]) {
    case 0: (void)appear_lambert_sample(&g_lam, in->wo, in->uc, in->u1, in->u2, &s); break;
    case 1: (void)appear_ward_sample(&g_ward, in->wo, in->uc, in->u1, in->u2, &s); break;
    case 2: (void)appear_conductor_sample(&g_cond, in->wo, in->uc, in->u1, in->u2, &s); break;
    default: (void)appear_dielectric_sample(&g_diel, in->wo, in->uc, in->u1, in->u2, &s); break;
    }
    return bs_sum(&s);
}
static LAT_NOINLINE float B_mix_eval(const lat_in *in)
{
    switch (g_mix_kind[lat_family(in)]) {
    case 0: return s3(appear_lambert_eval(&g_lam, in->wo, in->wi));
    case 1: return s3(appear_ward_eval(&g_ward, in->wo, in->wi));
    case 2: return s3(appear_conductor_eval(&g_cond, in->wo, in->wi));
    default: return s3(appear_dielectric_eval(&g_diel, in->wo, in->wi));
    }
}

static void lat_set_conductor(int type, float ax, float ay)
{
    g_ax = ax; g_ay = ay;
    g_cond = appear_conductor_make(appear_microfacet_make(type, ax, ay, APPEAR_SAMPLE_VISIBLE), g_eta3, g_k3);
    g_lcond.beckmann = type == APPEAR_BECKMANN; g_lcond.ax = ax; g_lcond.ay = ay; g_lcond.eta = g_eta3; g_lcond.k = g_k3;
}

/* ---- rows ---- */
static int g_nrows, g_nloses;
static void lat_pair_in(const char *group, const char *name, lat_fn fa, lat_fn fb, lat_check chk,
                        const char *base)
{
    lat_job ja, jb;
    double ta, tb, q, err;
    int bad = 0;
    char note[256], bname[160];
    if (!b_filter_match(name)) return;
    ja.fn = fa; jb.fn = fb;
    err = chk ? chk(fa, fb, &bad) : chk_value(fa, fb, &bad);
    q = b_time_latency_pair(lat_run, &ja, lat_run, &jb, g_calls, &ta, &tb);
    snprintf(note, sizeof note, "ratio=%.3f vs %s (median of paired runs); check %s maxrel=%.1e bad=%d/%d", q, base,
             chk ? "pdf/f" : "value", err, bad, LAT_N);
    b_row(group, name, ta, err, note);
    snprintf(bname, sizeof bname, "%s [baseline]", name);
    snprintf(note, sizeof note, "baseline: %s", base);
    b_row(group, bname, tb, -1, note);
    if (!strcmp(group, "latency")) { ++g_nrows; g_nloses += q > 1.0; }
}
static void lat_pair(const char *name, lat_fn fa, lat_fn fb, lat_check chk, const char *base)
{ lat_pair_in("latency", name, fa, fb, chk, base); }
static void lat_single(const char *name, lat_fn fa)
{
    lat_job ja;
    if (!b_filter_match(name)) return;
    ja.fn = fa;
    b_row("latency", name, b_time(lat_run, &ja, g_calls), -1, "ratio=- (no baseline)");
}

void bench_latency(void)
{
    static const float gs[2] = { 0.3f, 0.9f };
    char name[128];
    int k;
    float vals[256];
    g_calls = b_quick() ? 1L << 12 : 1L << 15;
    b_note("latency: dependent chain of %ld calls over %d pre-drawn inputs, noinline wrappers; ratio = appear / baseline", g_calls, LAT_N);

    g_R = appear_spectrum_rgb(0.8f, 0.5f, 0.2f);
    for (k = 0; k < 4; ++k) g_R4.v[k] = k < APPEAR_SPECTRUM_SAMPLES ? g_R.v[k] : 0.0f;
    g_lam = appear_lambert_make(g_R);
    g_eta3 = appear_spectrum_rgb(0.143f, 0.374f, 1.442f); g_k3 = appear_spectrum_rgb(3.983f, 2.386f, 1.603f);
    g_sggx = appear_sggx_make(g_S[0], g_S[1], g_S[2], g_S[3], g_S[4], g_S[5]);
    g_sig3 = appear_spectrum_rgb(0.5f, 1.0f, 2.0f); g_sig1 = appear_spectrum_splat(1.0f);
    g_ward = appear_ward_make(appear_spectrum_splat(0.3f), appear_spectrum_splat(0.5f), 0.2f, 0.2f, APPEAR_WARD_ORIGINAL);

    lat_inputs(IN_HEMI, 101);
    lat_pair("lambert_eval", A_lambert_eval, B_lambert_eval, 0, "pbrt-v4 DiffuseBxDF::f (4 wavelengths)");
    lat_pair("lambert_pdf", A_lambert_pdf, B_lambert_pdf, 0, "pbrt-v4 DiffuseBxDF::PDF");
    lat_pair("lambert_sample", A_lambert_sample, B_lambert_sample, 0, "pbrt-v4 DiffuseBxDF::Sample_f (polar map, libm)");
    g_eon = appear_eon_make(g_R, 0.7f);
    g_eon_cos = appear_eon_make_sampled(g_R, 0.7f, APPEAR_EON_SAMPLE_COSINE);
    g_leon.rho = g_R; g_leon.r = 0.7f;
    lat_pair("eon_eval sigma 0.7", A_eon_eval, B_eon_eval, 0, "EON listing f_EON, E_FON_exact (acosf)");
    /* not the same function (appear's full EON against FON alone): group latency_info, not counted */
    lat_pair_in("latency_info", "eon_eval sigma 0.7 vs FON alone", A_eon_eval, B_fon_eval, chk_none,
                "FON single scattering only (listing's f_ss)");
    lat_pair("eon_pdf sigma 0.7", A_eon_pdf, B_eon_pdf, 0, "EON listing pdf_EON (CLTC mixture, powf)");
    lat_pair("eon_sample sigma 0.7", A_eon_sample, B_eon_sample, chk_eon_sample,
             "EON listing sample_EON + f_EON");
    lat_pair("eon_sample sigma 0.7, cosine sampling", A_eon_sample_cos, B_eon_sample,
             chk_none, "EON listing sample_EON + f_EON (CLTC: a different sampler)");
    /* the LTC sheen [Zeltner22] at roughness 0.5 (no baseline: compare with the Lambert rows) */
    g_sheen = appear_sheen_make(g_R, 0.5f);
    lat_single("sheen_eval r=0.5", A_sheen_eval);
    lat_single("sheen_pdf r=0.5", A_sheen_pdf);
    lat_single("sheen_sample r=0.5", A_sheen_sample);
    /* the layered reference [Guo18] (SECTION layered): a GGX 0.3 coat eta 1.5 over the Lambert
       base, no slab, 1 walk per call, at most 10 events; eval and pdf each run one walk (and
       the exit's connection), sample one walk and one more for its pdf estimate (no baseline:
       compare with the lambert and dielectric rows it calls) */
    {
        appear_bsdf top = appear_bsdf_dielectric(
            appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE), 1.5f));
        appear_bsdf base = appear_bsdf_lambert(g_lam);
        g_layered = appear_layered_make(&top, &base, appear_slab_none(), 1, 10);
        g_rng = appear_rng_make(11);
    }
    lat_single("layered_eval ggx a=0.3 eta=1.5 over lambert", A_layered_eval);
    lat_single("layered_pdf ggx a=0.3 eta=1.5 over lambert", A_layered_pdf);
    lat_single("layered_sample ggx a=0.3 eta=1.5 over lambert", A_layered_sample);
    lat_pair("fresnel_conductor", A_fr_cond, B_fr_cond, 0, "pbrt-v4 FrComplex");
    lat_pair("fresnel_conductor vs Mitsuba 3", A_fr_cond, B_fr_cond_mi3, 0, "Mitsuba 3 fresnel_conductor");
    lat_pair("fresnel_conductor_spectrum", A_fr_cond3, B_fr_cond3, 0, "pbrt-v4 FrComplex (3 channels)");
    lat_pair("fresnel_schlick", A_fr_schlick, B_fr_schlick, 0, "Schlick 1994 (pbrt-v3 FrSchlick)");
    lat_inputs(IN_SPHERE, 102);
    lat_pair("isotropic_sample", A_iso_sample, B_iso_sample, 0, "pbrt-v4 SampleUniformSphere");
    for (k = 0; k < 2; ++k) {
        g_g = gs[k];
        snprintf(name, sizeof name, "hg_eval g=%g", gs[k]);
        lat_pair(name, A_hg_eval, B_hg_eval, 0, "pbrt-v4 HenyeyGreenstein");
        snprintf(name, sizeof name, "hg_sample g=%g", gs[k]);
        lat_pair(name, A_hg_sample, B_hg_sample, chk_hg_sample, "pbrt-v4 SampleHenyeyGreenstein");
    }
    /* the trade of decision 2 (issue 36): appear's pdf is the density at the returned wi, pbrt-v4's
       that of the sampled cosine; near |g| = 1 the direction's rounding moves the density */
    {
        static const float gh[3] = { 0.9f, 0.999f, 0.9999f };
        for (k = 0; k < 3; ++k) {
            double ea, eb;
            hg_pdf_errors(gh[k], &ea, &eb);
            b_note("latency: hg_sample g=%g pdf vs the double density at the returned wi: appear %.1e, "
                   "the sampled cosine's (pbrt-v4's form, g unclamped) %.1e (max rel., %d inputs)", gh[k], ea, eb, LAT_N);
        }
    }
    lat_inputs(IN_SPHERE, 103);
    lat_pair("fresnel_dielectric eta=1.5 (both sides)", A_fr_diel, B_fr_diel, 0, "pbrt-v4 FrDielectric");

    lat_inputs(IN_HEMI, 104);
    for (k = 0; k < 2; ++k) {
        const char *tag = k ? "a=0.1/0.4" : "a=0.3";
        g_ax = k ? 0.1f : 0.3f; g_ay = k ? 0.4f : 0.3f;
        snprintf(name, sizeof name, "ggx_D %s", tag);
        lat_pair(name, A_ggx_D, B_ggx_D, 0, "pbrt-v4 TrowbridgeReitz D");
        snprintf(name, sizeof name, "ggx_lambda %s", tag);
        lat_pair(name, A_ggx_lambda, B_ggx_lambda, 0, "pbrt-v4 TrowbridgeReitz Lambda");
        snprintf(name, sizeof name, "ggx_sample_visible %s", tag);
        lat_pair(name, A_ggx_vis, B_ggx_vis, chk_ggx_vis, "pbrt-v4 Sample_wm (Heitz 2018)");
        snprintf(name, sizeof name, "ggx_pdf_visible %s", tag);
        lat_pair(name, A_ggx_pdfv, B_ggx_pdfv, 0, "pbrt-v4 TrowbridgeReitz PDF(w, wm)");
        snprintf(name, sizeof name, "beckmann_D %s", tag);
        lat_pair(name, A_beck_D, B_beck_D, 0, "Mitsuba 3 MicrofacetDistribution::eval");
        snprintf(name, sizeof name, "beckmann_sample_visible %s", tag);
        lat_pair(name, A_beck_vis, B_beck_vis, 0, "Mitsuba 3 sample_visible_11 (3 Newton steps, erff, Giles erfinv)");
    }
    for (k = 0; k < 3; ++k) {
        static const char *tags[3] = { "ggx a=0.3", "ggx a=0.1/0.4", "beckmann a=0.3" };
        static const char *bases[3][3] = {
            { "pbrt-v4 ConductorBxDF::f (RGB)", "pbrt-v4 ConductorBxDF::PDF", "pbrt-v4 ConductorBxDF::Sample_f + weight" },
            { "pbrt-v4 ConductorBxDF::f (RGB)", "pbrt-v4 ConductorBxDF::PDF", "pbrt-v4 ConductorBxDF::Sample_f + weight" },
            { "pbrt-v4 ConductorBxDF, Beckmann (Mitsuba 3 D/sampler, exact Lambda)", "same, PDF", "same, Sample_f + weight" } };
        int type = k == 2 ? APPEAR_BECKMANN : APPEAR_GGX;
        lat_set_conductor(type, k == 1 ? 0.1f : 0.3f, k == 1 ? 0.4f : 0.3f);
        snprintf(name, sizeof name, "conductor_eval %s", tags[k]);
        lat_pair(name, A_cond_eval, B_cond_eval, 0, bases[k][0]);
        snprintf(name, sizeof name, "conductor_pdf %s", tags[k]);
        lat_pair(name, A_cond_pdf, B_cond_pdf, 0, bases[k][1]);
        snprintf(name, sizeof name, "conductor_sample %s", tags[k]);
        lat_pair(name, A_cond_sample, B_cond_sample, chk_cond_sample, bases[k][2]);
    }
    g_diel = appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE), 1.5f);
    g_ldiel.ax = g_ldiel.ay = 0.3f; g_ldiel.eta = 1.5f;
    for (k = 0; k < 2; ++k) {
        const char *tag = k ? "wo inside" : "wo outside";
        lat_inputs(k ? IN_DIEL_INSIDE : IN_DIEL, 105 + k);
        snprintf(name, sizeof name, "dielectric_eval ggx a=0.3 eta=1.5 %s", tag);
        lat_pair(name, A_diel_eval, B_diel_eval, 0, "pbrt-v4 DielectricBxDF::f (Radiance)");
        snprintf(name, sizeof name, "dielectric_pdf ggx a=0.3 eta=1.5 %s", tag);
        lat_pair(name, A_diel_pdf, B_diel_pdf, 0, "pbrt-v4 DielectricBxDF::PDF");
        snprintf(name, sizeof name, "dielectric_sample ggx a=0.3 eta=1.5 %s", tag);
        lat_pair(name, A_diel_sample, B_diel_sample, chk_diel_sample, "pbrt-v4 DielectricBxDF::Sample_f + weight");
    }
    lat_inputs(IN_HEMI, 107);
    for (k = 0; k < 2; ++k) {
        const char *tag = k ? "a=0.1/0.4" : "a=0.2";
        float ax = k ? 0.1f : 0.2f, ay = k ? 0.4f : 0.2f;
        g_ward = appear_ward_make(appear_spectrum_splat(0.3f), appear_spectrum_splat(0.5f), ax, ay, APPEAR_WARD_ORIGINAL);
        g_lward = lst_ward06_make(appear_spectrum_splat(0.3f), appear_spectrum_splat(0.5f), ax, ay, LST_WARD06_WARD);
        snprintf(name, sizeof name, "ward_eval original %s (x cos)", tag);
        lat_pair(name, A_ward_eval, B_ward_eval, 0, "Mitsuba 0.6 Ward::eval (f cos)");
        snprintf(name, sizeof name, "ward_pdf original %s", tag);
        lat_pair(name, A_ward_pdf, B_ward_pdf, 0, "Mitsuba 0.6 Ward::pdf");
        snprintf(name, sizeof name, "ward_sample original %s", tag);
        lat_pair(name, A_ward_sample, B_ward_sample, chk_ward_sample, "Mitsuba 0.6 Ward::sample (weight)");
        {
            double ea, eb, fa, fb;
            ward_lobe_errors(ax, ay, 1e-6, &ea, &eb);
            ward_lobe_errors(ax, ay, 1e-30, &fa, &fb);
            b_note("latency: ward lobe %s vs double: appear %.1e, Mitsuba 0.6 %.1e where >= 1e-6; "
                   "appear %.1e, Mitsuba 0.6 %.1e where >= 1e-30 (its cut at 1e-10: 1)", tag, ea, eb, fa, fb);
        }
    }
    lat_inputs(IN_SPHERE, 108);
    lat_pair("sggx_sigma kappa 33 (triangular form)", A_sggx_sigma, B_sggx_sigma, 0, "Mitsuba 3 sggx_projected_area");
    g_sggx2 = appear_sggx_make(g_S2[0], g_S2[1], g_S2[2], g_S2[3], g_S2[4], g_S2[5]);
    snprintf(name, sizeof name, "sggx_sigma kappa %.2g (triangular form)",
             1.0 / fmin(g_sggx2.lam[0], fmin(g_sggx2.lam[1], g_sggx2.lam[2])));
    lat_pair(name, A_sggx_sigma2, B_sggx_sigma2, 0, "Mitsuba 3 sggx_projected_area");
    { /* a fiber-like S of condition 1e4, rotated: its entries, and the model made from them */
        appear_sggx f = appear_sggx_make_fiber(appear_normalize(appear_vec3_make(0.3f, -0.5f, 0.81f)), 0.01f);
        appear_sggx_matrix(&f, g_S3);
        g_sggx3 = appear_sggx_make(g_S3[0], g_S3[1], g_S3[2], g_S3[3], g_S3[4], g_S3[5]);
    }
    snprintf(name, sizeof name, "sggx_sigma kappa %.2g (eigenbasis form)",
             1.0 / fmin(g_sggx3.lam[0], fmin(g_sggx3.lam[1], g_sggx3.lam[2])));
    lat_pair(name, A_sggx_sigma3, B_sggx_sigma3, 0, "Mitsuba 3 sggx_projected_area");
    lat_pair("sggx_D kappa 33 (triangular form)", A_sggx_D, B_sggx_D, 0, "Mitsuba 3 sggx_pdf");
    snprintf(name, sizeof name, "sggx_D kappa %.2g (triangular form)",
             1.0 / fmin(g_sggx2.lam[0], fmin(g_sggx2.lam[1], g_sggx2.lam[2])));
    lat_pair(name, A_sggx_D2, B_sggx_D2, 0, "Mitsuba 3 sggx_pdf");
    snprintf(name, sizeof name, "sggx_D kappa %.2g (eigenbasis form)",
             1.0 / fmin(g_sggx3.lam[0], fmin(g_sggx3.lam[1], g_sggx3.lam[2])));
    lat_pair(name, A_sggx_D3, B_sggx_D3, 0, "Mitsuba 3 sggx_pdf");
    lat_inputs(IN_HEMI, 109);
    lat_pair("homogeneous_sample rgb sigma=(0.5,1,2)", A_homog3, B_homog3, 0,
             "pbrt-v4 SampleT_maj (FastExp), spectral MIS pdf");
    lat_pair("homogeneous_sample grey sigma=1", A_homog1, B_homog1, 0, "pbrt-v4 SampleExponential + FastExp T_maj, pdf");
    lat_pair("homogeneous_pdf scattered", A_homog_pdf_s, B_homog_pdf_s, 0, "spectral MIS average, expf");
    lat_pair("homogeneous_pdf passed", A_homog_pdf_p, B_homog_pdf_p, 0, "spectral MIS average, expf");
    if (g_nrows) b_note("latency: %d pairs, appear slower than its baseline in %d", g_nrows, g_nloses);

    /* block 1b (group latency_chain, not in the count above): a floor (appear's Lambert eval
       without the unit-length checks), then the same samplers with the next index taken from the
       direction (phase, BSDF) or the distance (medium) alone. That is what a path tracer's next
       call waits for (the ray); the pdf and weight go into the throughput beside it. The
       difference from the block-1 row is the part of the chain spent after the direction:
       appear's HG pdf is evaluated at the returned wi (sample().pdf == pdf(wo, wi), bit for bit),
       the baseline's from the sampled cosine. */
    lat_inputs(IN_SPHERE, 102);
    for (k = 0; k < 2; ++k) {
        g_g = gs[k];
        snprintf(name, sizeof name, "hg_sample g=%g (chain: wi)", gs[k]);
        lat_pair_in("latency_chain", name, A_hg_sample_wi, B_hg_sample_wi, chk_hg_sample,
                    "pbrt-v4 SampleHenyeyGreenstein");
    }
    lat_inputs(IN_HEMI, 101);
    lat_pair_in("latency_chain", "lambert_eval, side test only (floor: no unit-length checks)", A_lambert_eval_side,
                B_lambert_eval, 0, "pbrt-v4 DiffuseBxDF::f");
    lat_inputs(IN_HEMI, 104);
    lat_set_conductor(APPEAR_GGX, 0.3f, 0.3f);
    lat_pair_in("latency_chain", "conductor_sample ggx a=0.3 (chain: wi)", A_cond_sample_wi, B_cond_sample_wi,
                chk_cond_sample, "pbrt-v4 ConductorBxDF::Sample_f + weight");
    lat_inputs(IN_DIEL, 105);
    lat_pair_in("latency_chain", "dielectric_sample ggx a=0.3 eta=1.5 wo outside (chain: wi)", A_diel_sample_wi,
                B_diel_sample_wi, chk_diel_sample, "pbrt-v4 DielectricBxDF::Sample_f + weight");
    lat_inputs(IN_HEMI, 109);
    lat_pair_in("latency_chain", "homogeneous_sample rgb sigma=(0.5,1,2) (chain: t)", A_homog3_t, B_homog3_t,
                0, "pbrt-v4 SampleT_maj (FastExp), spectral MIS pdf");
    lat_inputs(IN_HEMI, 111);
    lat_set_conductor(APPEAR_GGX, 0.3f, 0.3f);
    g_diel = appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE), 1.5f);
    g_mix[0] = appear_bsdf_lambert(g_lam);
    g_mix[1] = appear_bsdf_ward(g_ward);
    g_mix[2] = appear_bsdf_conductor(g_cond);
    g_mix[3] = appear_bsdf_dielectric(g_diel);
    lat_pair_in("latency_chain", "bsdf_sample mix of 4 (lambert, ward, conductor, dielectric; generic)",
                A_mix_sample, B_mix_sample, 0, "the direct calls behind the caller's switch");
    lat_pair_in("latency_chain", "bsdf_eval mix of 4 (lambert, ward, conductor, dielectric; generic)",
                A_mix_eval, B_mix_eval, 0, "the direct calls behind the caller's switch");
    b_sink += g_side;

    /* block 2: every other public eval/pdf/sample, no baseline */
    g_g = 0.7f;
    lat_set_conductor(APPEAR_GGX, 0.3f, 0.3f);
    g_thin = appear_thin_dielectric_make(1.5f);
    g_tfc = appear_thinfilm_conductor_make(appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE),
                                           appear_thinfilm_make_rgb(1.33f, 300.0f, appear_spectrum_splat(0.2f), appear_spectrum_splat(3.0f)));
    g_fiber = appear_fiber_make(appear_normalize(appear_vec3_make(0.3f, 0.5f, 0.8f)), 20.0f);
    g_dhg = appear_dhg_make(0.8f, -0.4f, 0.7f);
    g_draine = appear_draine_make(0.5f, 1.0f);
    g_mie = appear_mie_make(10.0f);
    for (k = 0; k < 256; ++k) {
        double mu = -1.0 + 2.0 * k / 255.0, d = 1.0 + 0.49 - 1.4 * mu;
        vals[k] = (float)((1 - 0.49) / (4 * 3.14159265358979 * d * sqrt(d)));
    }
    appear_phase_table_make(&g_tab, vals, NULL, 256);
    g_rng = appear_rng_make(7);
    lat_inputs(IN_HEMI, 110);
    lat_single("ward_specular_eval balanced a=0.3", A_wards_eval);
    lat_single("ward_specular_pdf a=0.3", A_wards_pdf);
    lat_single("thin_dielectric_eval", A_thin_eval);
    lat_single("thin_dielectric_pdf", A_thin_pdf);
    lat_single("thin_dielectric_sample", A_thin_sample);
    lat_single("thinfilm_conductor_eval", A_tfc_eval);
    lat_single("thinfilm_conductor_pdf", A_tfc_pdf);
    lat_single("thinfilm_conductor_sample", A_tfc_sample);
    lat_single("conductor_comp_eval ggx a=0.3", A_ccomp_eval);
    lat_single("conductor_comp_pdf ggx a=0.3", A_ccomp_pdf);
    lat_single("conductor_comp_sample ggx a=0.3", A_ccomp_sample);
    lat_single("conductor_ms_eval ggx a=0.3", A_cms_eval);
    lat_single("conductor_ms_pdf ggx a=0.3", A_cms_pdf);
    lat_single("conductor_ms_sample ggx a=0.3", A_cms_sample);
    lat_inputs(IN_DIEL, 111);
    lat_single("dielectric_comp_eval ggx a=0.3", A_dcomp_eval);
    lat_single("dielectric_comp_pdf ggx a=0.3", A_dcomp_pdf);
    lat_single("dielectric_comp_sample ggx a=0.3", A_dcomp_sample);
    lat_single("dielectric_ms_eval ggx a=0.3", A_dms_eval);
    lat_single("dielectric_ms_pdf ggx a=0.3", A_dms_pdf);
    lat_single("dielectric_ms_sample ggx a=0.3", A_dms_sample);
    lat_inputs(IN_SPHERE, 112);
    lat_single("isotropic_eval", A_iso_eval);
    lat_single("isotropic_pdf", A_iso_pdf);
    lat_single("hg_pdf g=0.7", A_hg_pdf);
    lat_single("sggx_specular_eval", A_sggxs_eval);
    lat_single("sggx_specular_pdf", A_sggxs_pdf);
    lat_single("sggx_specular_sample", A_sggxs_sample);
    lat_single("sggx_diffuse_eval", A_sggxd_eval);
    lat_single("sggx_diffuse_sample", A_sggxd_sample);
    lat_single("fiber_eval p=20", A_fiber_eval);
    lat_single("fiber_pdf p=20", A_fiber_pdf);
    lat_single("fiber_sample p=20", A_fiber_sample);
    lat_single("dhg_eval", A_dhg_eval);
    lat_single("dhg_pdf", A_dhg_pdf);
    lat_single("dhg_sample", A_dhg_sample);
    lat_single("rayleigh_eval", A_ray_eval);
    lat_single("rayleigh_pdf", A_ray_pdf);
    lat_single("rayleigh_sample", A_ray_sample);
    lat_single("draine_eval", A_draine_eval);
    lat_single("draine_pdf", A_draine_pdf);
    lat_single("draine_sample", A_draine_sample);
    lat_single("mie_eval d=10", A_mie_eval);
    lat_single("mie_pdf d=10", A_mie_pdf);
    lat_single("mie_sample d=10", A_mie_sample);
    lat_single("phase_table_eval n=256", A_tab_eval);
    lat_single("phase_table_pdf n=256", A_tab_pdf);
    lat_single("phase_table_sample n=256", A_tab_sample);
}
