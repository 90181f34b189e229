/* tests/gpu/kernels.cu - one CUDA kernel per model family, for the GPU
 * footprint check (tests/gpu/footprint.sh, run by `make check-compile`
 * when nvcc is installed). Each kernel is compiled alone (-DFAMILY_<NAME>)
 * and ptxas reports its registers, stack frame, spills, global and user
 * constant memory; the PTX is searched for f64 instructions. Models are
 * kernel parameters made on the host (make() is set-up, not per-sample
 * work), so the kernel holds exactly the per-sample code: eval, pdf and
 * sample of the family, one call each per thread. */
#if defined(FAMILY_GENERIC) /* a renderer with three models compiles the other parts out */
#define APPEAR_NO_WARD
#define APPEAR_NO_MULTISCATTER
#define APPEAR_NO_THINFILM
#define APPEAR_NO_SHEEN
#define APPEAR_NO_MATERIALS /* (its dispersive dielectric's 120-byte stack would join the switch) */
#endif
#include "../../appear.h"

#define IDX (blockIdx.x * blockDim.x + threadIdx.x)
#define DIRS                                                                     \
    appear_vec3 wo = appear_vec3_make(in[6 * IDX], in[6 * IDX + 1], in[6 * IDX + 2]);     \
    appear_vec3 wi = appear_vec3_make(in[6 * IDX + 3], in[6 * IDX + 4], in[6 * IDX + 5]); \
    float u = u_in[IDX]
#define BSDF(model, m)                                                                       \
    {                                                                                        \
        appear_bsdf_record s;                                                                \
        float acc = appear_##model##_eval(&m, wo, wi).v[0] + appear_##model##_pdf(&m, wo, wi); \
        acc += (float)appear_##model##_sample(&m, wo, u, 1.0f - u, 0.5f * u, &s) + s.pdf + s.weight.v[1]; \
        out[IDX] = acc + s.wi.z;                                                             \
    }
#define PHASE(prefix, m)                                                                     \
    {                                                                                        \
        appear_phase_record s;                                                               \
        float acc = prefix##_eval(m, wo, wi);                                                \
        acc += (float)prefix##_sample(m, wo, u, 1.0f - u, &s) + s.pdf + s.weight;            \
        out[IDX] = acc + s.wi.z;                                                             \
    }

#if defined(FAMILY_LAMBERT)
__global__ void k_lambert(appear_lambert m, const float *in, const float *u_in, float *out) { DIRS; BSDF(lambert, m) }
#elif defined(FAMILY_EON)
__global__ void k_eon(appear_eon m, const float *in, const float *u_in, float *out) { DIRS; BSDF(eon, m) }
#elif defined(FAMILY_SHEEN) /* the LTC sheen: its table in global memory, read through the accessor */
__global__ void k_sheen(appear_sheen m, const float *in, const float *u_in, float *out)
{
    DIRS;
    BSDF(sheen, m)
    out[IDX] += appear_sheen_base_weight(&m, wo, wi, APPEAR_SHEEN_LAYER_RECIPROCAL);
}
#elif defined(FAMILY_HG)
__global__ void k_hg(appear_hg m, const float *in, const float *u_in, float *out) { DIRS; PHASE(appear_hg, &m) }
#elif defined(FAMILY_WARD)
__global__ void k_ward(appear_ward m, const float *in, const float *u_in, float *out) { DIRS; BSDF(ward, m) }
#elif defined(FAMILY_CONDUCTOR)
__global__ void k_conductor(appear_conductor m, const float *in, const float *u_in, float *out) { DIRS; BSDF(conductor, m) }
#elif defined(FAMILY_DIELECTRIC)
__global__ void k_dielectric(appear_dielectric m, const float *in, const float *u_in, float *out) { DIRS; BSDF(dielectric, m) }
#elif defined(FAMILY_THIN_DIELECTRIC)
__global__ void k_thin(appear_thin_dielectric m, const float *in, const float *u_in, float *out)
{
    DIRS;
    appear_bsdf_record s;
    out[IDX] = appear_thin_dielectric_eval(&m, wo, wi).v[0] + (float)appear_thin_dielectric_sample(&m, wo, u, u, u, &s) + s.pdf;
}
#elif defined(FAMILY_MATERIALS) /* a named metal looked up per thread, its conductor; the dielectrics */
__global__ void k_materials(appear_microfacet d, int metal, const float *in, const float *u_in, float *out)
{
    DIRS;
    float lam[APPEAR_SPECTRUM_SAMPLES], e, k;
    int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) lam[i] = 360.0f + 470.0f * u * (float)(i + 1) / 4.0f;
    appear_conductor m = appear_conductor_make_metal(d, metal, lam);
    BSDF(conductor, m)
    (void)appear_metal_eta_k(metal, 360.0f + 470.0f * u, &e, &k);
    out[IDX] += e + k + appear_dielectric_ior(metal, lam[0]) + appear_ior_cauchy_abbe(1.5f, 40.0f, lam[0]) +
                appear_metal_to_rgb(metal).f0[0];
    {
        appear_dielectric_dispersive g = appear_dielectric_make_dispersive(d, appear_dielectric_ior_spectrum(metal, lam));
        appear_bsdf_record s;
        out[IDX] += appear_dielectric_dispersive_eval(&g, wo, wi).v[1] + appear_dielectric_dispersive_pdf(&g, wo, wi) +
                    (float)appear_dielectric_dispersive_sample(&g, wo, u, 0.5f, u, &s) + s.weight.v[1];
    }
}
#elif defined(FAMILY_COMPENSATED)
__global__ void k_comp(appear_conductor c, appear_dielectric d, const float *in, const float *u_in, float *out)
{ DIRS; BSDF(conductor_comp, c) BSDF(dielectric_comp, d) }
#elif defined(FAMILY_COAT_ALBEDO) /* the reflection-only albedo lookups a coat calls: 124 KB of tables */
__global__ void k_coat_albedo(int type, float alpha, float eta, const float *in, const float *u_in, float *out)
{
    DIRS;
    out[IDX] = appear_dielectric_reflect_albedo(type, alpha * u, eta, wo.z) +
               appear_dielectric_reflect_albedo_avg(type, alpha * u, eta) + wi.z;
}
#elif defined(FAMILY_OPENPBR) /* OpenPBR Surface: every lobe, made on the host (2616 bytes) */
/* in global memory, as a renderer keeps its materials (a kernel parameter of this size whose
   address the calls take would be copied to the stack: 2616 bytes that are the harness's) */
__global__ void k_openpbr(const appear_openpbr *mp, const float *in, const float *u_in, float *out)
{
    const appear_openpbr &m = *mp;
    DIRS;
    BSDF(openpbr, m)
    out[IDX] += appear_openpbr_emission(&m, wo).v[0];
}
#elif defined(FAMILY_THINFILM)
__global__ void k_thinfilm(appear_thinfilm_conductor m, const float *in, const float *u_in, float *out)
{ DIRS; BSDF(thinfilm_conductor, m) }
#elif defined(FAMILY_RANDOM_WALK)
__global__ void k_walk(appear_conductor c, const float *in, const float *u_in, float *out)
{
    DIRS;
    appear_rng rng = appear_rng_make((unsigned)IDX);
    appear_bsdf_record s;
    out[IDX] = appear_conductor_ms_eval(&c, wo, wi, &rng).v[0] + appear_conductor_ms_pdf(&c, wo, wi) +
               (float)appear_conductor_ms_sample(&c, wo, &rng, &s) + s.pdf + u;
}
#elif defined(FAMILY_HOMOGENEOUS)
__global__ void k_homog(appear_spectrum sigma, const float *in, const float *u_in, float *out)
{
    appear_medium_sample s;
    float u = u_in[IDX];
    out[IDX] = (float)appear_homogeneous_sample(sigma, in[IDX], u, 1.0f - u, &s) + s.pdf + s.weight.v[2] +
               appear_homogeneous_pdf(sigma, in[IDX], s.t, s.scattered);
}
#elif defined(FAMILY_TRACKER)
__global__ void k_tracker(float smaj, const float *in, const float *u_in, float *out)
{
    appear_majorant_segment seg = appear_majorant_make_constant(smaj);
    appear_tracker tr;
    float t;
    int i = 0;
    appear_tracker_init(&tr, APPEAR_TRACK_RATIO, in[IDX], &seg, 1, 0);
    while (appear_tracker_next(&tr, u_in[(IDX + i) & 255], u_in[(IDX + 7 * i) & 255], &t) && i < 1000)
        appear_tracker_feed(&tr, smaj * 0.5f * (1.0f + __sinf(t))), ++i;
    out[IDX] = tr.T;
}
#elif defined(FAMILY_SGGX)
__global__ void k_sggx(appear_sggx m, const float *in, const float *u_in, float *out)
{
    DIRS;
    appear_phase_record s;
    out[IDX] = appear_sggx_specular_eval(&m, wo, wi) + appear_sggx_sigma(&m, wo) +
               (float)appear_sggx_specular_sample(&m, wo, u, u, &s) + s.pdf +
               (float)appear_sggx_diffuse_sample(&m, wo, u, u, u, u, &s) + s.pdf;
}
#elif defined(FAMILY_SGGX_MAKE) /* a heterogeneous volume's per-lookup make(): the float Jacobi on the device */
__global__ void k_sggx_make(const float *in, const float *u_in, float *out)
{
    DIRS;
    appear_sggx m = appear_sggx_make(in[0], in[1], in[2], in[3], in[4], in[5]);
    out[IDX] = appear_sggx_sigma(&m, wo) + appear_sggx_specular_eval(&m, wo, wi) + u;
}
#elif defined(FAMILY_FIBER)
__global__ void k_fiber(appear_fiber m, const float *in, const float *u_in, float *out)
{ DIRS; PHASE(appear_fiber, &m) }
#elif defined(FAMILY_MORE_PHASE)
__global__ void k_more(appear_dhg dh, const float *in, const float *u_in, float *out)
{
    DIRS;
    {
        appear_phase_record s;
        float acc = appear_rayleigh_eval(wo, wi) + (float)appear_rayleigh_sample(wo, u, u, &s) + s.pdf;
        out[IDX] = acc;
    }
    PHASE(appear_dhg, &dh)
}
#elif defined(FAMILY_DRAINE_MIE)
__global__ void k_draine(appear_draine dr, appear_mie mi, const float *in, const float *u_in, float *out)
{
    DIRS;
    PHASE(appear_draine, &dr)
    PHASE(appear_mie, &mi)
}
#elif defined(FAMILY_GENERIC) || defined(FAMILY_GENERIC_ALL)
/* the generic interface: each thread's material (Lambert, GGX conductor or GGX dielectric,
   made on the host) from an array, through appear_bsdf_eval / _pdf / _sample. FAMILY_GENERIC
   compiles the header with the parts the kernel does not use switched off (what a renderer
   with these three models does), FAMILY_GENERIC_ALL with every part, so the switch holds every
   kind, the random walks included. */
__global__ void k_generic(const appear_bsdf *mats, const float *in, const float *u_in, float *out)
{
    DIRS;
    appear_bsdf m = mats[IDX % 3u];
    BSDF(bsdf, m)
}
#else
#error "define one FAMILY_<NAME> (see tests/gpu/footprint.sh)"
#endif
