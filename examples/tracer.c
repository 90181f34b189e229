/* examples/tracer.c - see tracer.h. A volumetric path tracer in one file:
   random numbers, geometry, materials (dispatch to appear.h), media, lights,
   the path integrator with NEE + MIS, spectral colour, the threaded renderer,
   output. */
#define _POSIX_C_SOURCE 200809L
#include "tracer.h"
#include "image_io.h"
#include "cie_data.h"
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define EPS_T 1e-4f      /* smallest hit distance */
#define EPS_OFF 2e-4f    /* origin offset along the normal when leaving a surface */
#define INF_T 1e30f

/* ======================================================================== */
/* Random numbers: PCG32 (O'Neill 2014), one stream per pixel               */
/* ======================================================================== */
typedef struct { uint64_t state, inc; } rng;
static uint32_t rng_u32(rng *r)
{
    uint64_t old = r->state;
    uint32_t x, rot;
    r->state = old * 6364136223846793005ull + r->inc;
    x = (uint32_t)(((old >> 18u) ^ old) >> 27u);
    rot = (uint32_t)(old >> 59u);
    return (x >> rot) | (x << ((32u - rot) & 31u));
}
/* uniform in [0, 1) */
static float rng_f(rng *r) { return (float)(rng_u32(r) >> 8) * (1.0f / 16777216.0f); }
static rng rng_make(uint64_t seed, uint64_t stream)
{
    rng r;
    r.state = 0; r.inc = (stream << 1u) | 1u;
    rng_u32(&r); r.state += seed; rng_u32(&r);
    return r;
}

/* ======================================================================== */
/* Small vector / spectrum helpers                                          */
/* ======================================================================== */
static appear_vec3 v3(float x, float y, float z) { return appear_vec3_make(x, y, z); }
static appear_vec3 madd(appear_vec3 o, appear_vec3 d, float t) { return appear_add(o, appear_scale(d, t)); }
static float comp(appear_vec3 v, int i) { return i == 0 ? v.x : (i == 1 ? v.y : v.z); }
static appear_spectrum sp(float s) { return appear_spectrum_splat(s); }
static appear_spectrum sp_mul(appear_spectrum a, appear_spectrum b) { return appear_spectrum_mul(a, b); }
static appear_spectrum sp_scale(appear_spectrum a, float s) { return appear_spectrum_scale(a, s); }
static appear_spectrum sp_add(appear_spectrum a, appear_spectrum b) { return appear_spectrum_add(a, b); }
static int sp_is_zero(appear_spectrum a) { return appear_spectrum_max(a) <= 0.0f; }

/* ======================================================================== */
/* Scene building                                                           */
/* ======================================================================== */
void tracer_scene_init(tracer_scene *sc, const char *name)
{
    memset(sc, 0, sizeof *sc);
    sc->name = name;
    sc->env_top = sc->env_bottom = sp(1.0f);
    sc->eye = v3(0, 0, 5); sc->look = v3(0, 0, 0); sc->up = v3(0, 1, 0); sc->fov = 0.7f;
    sc->light = -1;
}
int tracer_add_material(tracer_scene *sc, tracer_material m)
{
    if (sc->n_mats >= TRACER_MAX_MATERIALS) return -1;
    sc->mats[sc->n_mats] = m;
    return sc->n_mats++;
}
int tracer_add_medium(tracer_scene *sc, tracer_medium m)
{
    if (sc->n_media >= TRACER_MAX_MEDIA) return -1;
    sc->media[sc->n_media] = m;
    return sc->n_media++;
}
static int add_shape(tracer_scene *sc, tracer_shape s)
{
    if (sc->n_shapes >= TRACER_MAX_SHAPES) return -1;
    sc->shapes[sc->n_shapes] = s;
    return sc->n_shapes++;
}
int tracer_add_sphere(tracer_scene *sc, appear_vec3 c, float r, int material, int medium)
{
    tracer_shape s;
    memset(&s, 0, sizeof s);
    s.kind = SHAPE_SPHERE; s.c = c; s.r = r; s.material = material; s.medium = medium;
    return add_shape(sc, s);
}
int tracer_add_box(tracer_scene *sc, appear_vec3 lo, appear_vec3 hi, int material, int medium)
{
    tracer_shape s;
    memset(&s, 0, sizeof s);
    s.kind = SHAPE_BOX; s.lo = lo; s.hi = hi; s.material = material; s.medium = medium;
    return add_shape(sc, s);
}
int tracer_add_convex(tracer_scene *sc, const float (*planes)[4], int n, int material, int medium)
{
    tracer_shape s;
    int i;
    if (n < 1 || n > TRACER_MAX_PLANES) return -1;
    memset(&s, 0, sizeof s);
    s.kind = SHAPE_CONVEX; s.material = material; s.medium = medium; s.n_planes = n;
    for (i = 0; i < n; ++i) { /* unit normals: the distances below are lengths */
        float l = sqrtf(planes[i][0] * planes[i][0] + planes[i][1] * planes[i][1] +
                        planes[i][2] * planes[i][2]);
        if (!(l > 0.0f)) return -1;
        s.plane[i][0] = planes[i][0] / l; s.plane[i][1] = planes[i][1] / l;
        s.plane[i][2] = planes[i][2] / l; s.plane[i][3] = planes[i][3] / l;
    }
    return add_shape(sc, s);
}
/* a material of this kind, every other field zero */
static tracer_material mat_of_kind(int kind)
{
    tracer_material m;
    memset(&m, 0, sizeof m);
    m.kind = kind;
    return m;
}
int tracer_add_sphere_light(tracer_scene *sc, appear_vec3 c, float r, appear_spectrum radiance)
{
    tracer_material m = mat_of_kind(MAT_EMITTER);
    int i;
    m.emission = radiance;
    i = tracer_add_sphere(sc, c, r, tracer_add_material(sc, m), -1);
    sc->light = i;
    return i;
}
tracer_material tracer_mat_bsdf(appear_bsdf bsdf)
{
    tracer_material m = mat_of_kind(MAT_BSDF);
    m.bsdf = bsdf;
    return m;
}
tracer_material tracer_mat_lambert(appear_spectrum albedo)
{
    return tracer_mat_bsdf(appear_bsdf_lambert(appear_lambert_make(albedo)));
}
#if TRACER_HAS_SHEEN
tracer_material tracer_mat_sheen_over(appear_sheen sheen, appear_bsdf base, int mode)
{
    tracer_material m = tracer_mat_bsdf(base);
    m.has_sheen = 1; m.sheen = sheen; m.sheen_mode = mode;
    return m;
}
#endif
#if TRACER_HAS_LAYERED
tracer_material tracer_mat_coated(appear_coated c)
{
    tracer_material m = mat_of_kind(MAT_COATED);
    m.coated = c;
    return m;
}
tracer_material tracer_mat_layered(tracer_layered l)
{
    tracer_material m = mat_of_kind(MAT_LAYERED);
    m.layered = l;
    return m;
}
appear_layered tracer_layered_make(const tracer_layered *l, appear_rng *rng)
{
    appear_bsdf top;
    (void)rng; /* the _ms top's, when the header has it */
    memset(&top, 0, sizeof top); /* an unknown top kind: invalid (flags 0), make() rejects it */
    if (l->top == TRACER_TOP_SINGLE) top = appear_bsdf_dielectric(l->coat);
    else if (l->top == TRACER_TOP_COMP) top = appear_bsdf_dielectric_comp(l->coat);
#if TRACER_HAS_MULTISCATTER
    else if (l->top == TRACER_TOP_MS) top = appear_bsdf_dielectric_ms(l->coat, rng);
#endif
    return appear_layered_make(&top, &l->base, l->slab, l->samples, l->max_depth);
}
#endif
tracer_material tracer_mat_none(void) { return mat_of_kind(MAT_NONE); }
#if TRACER_HAS_OPENPBR
tracer_material tracer_mat_openpbr(const appear_openpbr_params *p)
{
    tracer_material m = mat_of_kind(MAT_OPENPBR);
    m.openpbr = appear_openpbr_make(p);
    /* toward the normal: spectral mode's grey check, and whether to add emission at all */
    m.emission = appear_openpbr_emission(&m.openpbr, v3(0.0f, 0.0f, 1.0f));
    return m;
}
int tracer_add_openpbr_sphere(tracer_scene *sc, appear_vec3 c, float r,
                              const appear_openpbr_params *p)
{
    tracer_material m = tracer_mat_openpbr(p);
    tracer_medium med;
    float g;
    int mi = tracer_add_material(sc, m), me = -1;
    if (mi < 0) return -1;
    memset(&med, 0, sizeof med);
    med.kind = MED_HOMOGENEOUS;
    if (appear_openpbr_medium(&sc->mats[mi].openpbr, &med.sigma_t, &med.albedo, &g)) {
        med.phase = appear_phase_hg(appear_hg_make(g));
        if ((me = tracer_add_medium(sc, med)) < 0) return -1;
    }
    return tracer_add_sphere(sc, c, r, mi, me);
}
#endif
#if TRACER_HAS_MATERIALS
tracer_material tracer_mat_metal(appear_microfacet d, int metal)
{
    tracer_material m = mat_of_kind(MAT_METAL);
    m.d = d; m.named = metal; m.metal_form = TRACER_METAL_ETA_K;
    return m;
}
tracer_material tracer_mat_glass(appear_microfacet d, int dielectric)
{
    tracer_material m = mat_of_kind(MAT_GLASS);
    m.d = d; m.named = dielectric;
    return m;
}
#endif

/* ======================================================================== */
/* Geometry                                                                 */
/* ======================================================================== */
typedef struct { float t; int shape; appear_vec3 n; /* outward unit normal */ } hit;

/* nearest t in (tmin, tmax) of the ray o + t d (d unit) with the sphere */
static float hit_sphere(const tracer_shape *s, appear_vec3 o, appear_vec3 d, float tmin, float tmax)
{
    appear_vec3 oc = appear_sub(o, s->c);
    float b = appear_dot(oc, d), c = appear_dot(oc, oc) - s->r * s->r, q, t0, t1;
    /* discriminant as r^2 - |oc - b d|^2 (Haines et al., Precision
       improvements for ray/sphere intersection, Ray Tracing Gems 2019, ch. 7):
       b^2 - c cancels for distant spheres */
    appear_vec3 perp = appear_sub(oc, appear_scale(d, b));
    float disc = s->r * s->r - appear_dot(perp, perp);
    if (disc < 0.0f) return -1.0f;
    q = sqrtf(disc);
    /* t0 = -b - q without cancellation for far-away origins: c / (-b + q) */
    t0 = b < 0.0f ? c / (-b + q) : -b - q;
    t1 = b < 0.0f ? -b + q : c / (-b - q);
    if (t0 > t1) { float x = t0; t0 = t1; t1 = x; }
    if (t0 > tmin && t0 < tmax) return t0;
    if (t1 > tmin && t1 < tmax) return t1;
    return -1.0f;
}

/* slab test (Kay & Kajiya 1986) */
static float hit_box(const tracer_shape *s, appear_vec3 o, appear_vec3 d, float tmin, float tmax)
{
    float t0 = -INF_T, t1 = INF_T;
    int i;
    for (i = 0; i < 3; ++i) {
        float inv = 1.0f / comp(d, i);
        float a = (comp(s->lo, i) - comp(o, i)) * inv, b = (comp(s->hi, i) - comp(o, i)) * inv;
        if (a > b) { float x = a; a = b; b = x; }
        if (a != a || b != b) { /* d_i = 0 and o_i on a face: treat as inside the slab iff between */
            if (comp(o, i) < comp(s->lo, i) || comp(o, i) > comp(s->hi, i)) return -1.0f;
            continue;
        }
        t0 = a > t0 ? a : t0;
        t1 = b < t1 ? b : t1;
    }
    if (t0 > t1) return -1.0f;
    if (t0 > tmin && t0 < tmax) return t0;
    if (t1 > tmin && t1 < tmax) return t1;
    return -1.0f;
}

/* A convex polyhedron: the slab test with one slab per plane [Haines 1991, Fast Ray-Convex
   Polyhedron Intersection, Graphics Gems II]: entering planes raise t0, leaving ones lower t1. */
static float hit_convex(const tracer_shape *s, appear_vec3 o, appear_vec3 d, float tmin, float tmax)
{
    float t0 = -INF_T, t1 = INF_T;
    int i;
    for (i = 0; i < s->n_planes; ++i) {
        const float *pl = s->plane[i];
        float dn = pl[0] * d.x + pl[1] * d.y + pl[2] * d.z;
        float gap = pl[3] - (pl[0] * o.x + pl[1] * o.y + pl[2] * o.z); /* > 0: o is inside */
        float t;
        if (dn == 0.0f) { /* parallel to the plane: wholly inside or wholly outside */
            if (gap < 0.0f) return -1.0f;
            continue;
        }
        t = gap / dn;
        if (dn > 0.0f) t1 = t < t1 ? t : t1;
        else t0 = t > t0 ? t : t0;
    }
    if (t0 > t1) return -1.0f;
    if (t0 > tmin && t0 < tmax) return t0;
    if (t1 > tmin && t1 < tmax) return t1;
    return -1.0f;
}

static appear_vec3 shape_normal(const tracer_shape *s, appear_vec3 p)
{
    if (s->kind == SHAPE_SPHERE) return appear_normalize(appear_sub(p, s->c));
    if (s->kind == SHAPE_CONVEX) { /* the plane p lies on: the largest n . p - c */
        int i, best = 0;
        float bv = -INF_T;
        for (i = 0; i < s->n_planes; ++i) {
            const float *pl = s->plane[i];
            float v = pl[0] * p.x + pl[1] * p.y + pl[2] * p.z - pl[3];
            if (v > bv) { bv = v; best = i; }
        }
        return v3(s->plane[best][0], s->plane[best][1], s->plane[best][2]);
    }
    {
        /* the face whose relative distance from the centre is largest */
        int i, best = 0;
        float bv = -1.0f, n[3] = { 0, 0, 0 };
        for (i = 0; i < 3; ++i) {
            float c = 0.5f * (comp(s->lo, i) + comp(s->hi, i)), hsz = 0.5f * (comp(s->hi, i) - comp(s->lo, i));
            float rel = fabsf(comp(p, i) - c) / hsz;
            if (rel > bv) { bv = rel; best = i; }
        }
        n[best] = comp(p, best) > 0.5f * (comp(s->lo, best) + comp(s->hi, best)) ? 1.0f : -1.0f;
        return v3(n[0], n[1], n[2]);
    }
}

/* only >= 0: that shape alone (isolated furnace objects); skip >= 0: all
   but that one (shadow rays ignore the light they aim at) */
static int intersect_only(const tracer_scene *sc, appear_vec3 o, appear_vec3 d, float tmax, int only, int skip, hit *h)
{
    int i;
    h->t = tmax; h->shape = -1;
    for (i = 0; i < sc->n_shapes; ++i) {
        const tracer_shape *s = &sc->shapes[i];
        if ((only >= 0 && i != only) || i == skip) continue;
        float t = s->kind == SHAPE_SPHERE ? hit_sphere(s, o, d, EPS_T, h->t)
                : s->kind == SHAPE_BOX    ? hit_box(s, o, d, EPS_T, h->t)
                                          : hit_convex(s, o, d, EPS_T, h->t);
        if (t > 0.0f) { h->t = t; h->shape = i; }
    }
    if (h->shape < 0) return 0;
    h->n = shape_normal(&sc->shapes[h->shape], madd(o, d, h->t));
    return 1;
}
static int intersect(const tracer_scene *sc, appear_vec3 o, appear_vec3 d, float tmax, hit *h)
{ return intersect_only(sc, o, d, tmax, -1, -1, h); }

/* origin for a ray leaving the surface point p (normal n) in direction d */
static appear_vec3 spawn(appear_vec3 p, appear_vec3 n, appear_vec3 d)
{
    return madd(p, n, appear_dot(d, n) > 0.0f ? EPS_OFF : -EPS_OFF);
}

static appear_frame shape_frame(const tracer_shape *s, appear_vec3 n)
{
    if (s->tangent_mode == 1) /* tangent along the latitude circles about y */
        return appear_frame_from_normal_tangent(n, appear_cross(v3(0, 1, 0), n));
    return appear_frame_from_normal(n);
}

/* ======================================================================== */
/* Materials: appear.h's generic interface                                  */
/* ======================================================================== */
/* A material at one shading point: its appear_bsdf value and what that value refers to. A
   composite by reference points into the material (appear_coated) or into this struct (the
   appear_layered made here and the appear_rng its walks draw from, seeded from the path's
   generator: one per shading point, never shared between threads), so the struct stays in place
   while bsdf is used. */
typedef struct shade_point {
    const tracer_material *m;
    appear_bsdf bsdf;
    int stochastic; /* APPEAR_MODEL_STOCHASTIC: eval and pdf are estimates (no MIS, see tracer.h) */
#if TRACER_HAS_MATERIALS
    /* MAT_GLASS: the dispersive dielectric, which the generic interface does not hold; bsdf is
       then its hero's appear_dielectric, for the flags */
    int dispersive;
    appear_dielectric_dispersive glass;
#endif
#if TRACER_HAS_LAYERED
    appear_rng arng;
    appear_layered layered;
#endif
} shade_point;

#if TRACER_HAS_MATERIALS
/* an appear_spectrum from an RGB triple (channels past the third repeat blue, as
   appear_spectrum_rgb's) */
static appear_spectrum sp_rgb3(const float c[3]) { return appear_spectrum_rgb(c[0], c[1], c[2]); }

/* The named metal or glass at the path's wavelengths lambda (spectral mode), or its RGB form
   (lambda NULL). */
static void shade_bind_named(shade_point *sh, const tracer_material *m, const float *lambda)
{
    if (m->kind == MAT_METAL) {
        appear_conductor c;
        if (lambda) {
            c = appear_conductor_make_metal(m->d, m->named, lambda);
        } else { /* appear_conductor_make_metal(d, metal, NULL) in any build width */
            appear_metal_rgb r = appear_metal_to_rgb(m->named);
            c = m->metal_form == TRACER_METAL_F82
                    ? appear_conductor_make_f82(m->d, sp_rgb3(r.f0), sp_rgb3(r.f82_tint))
                    : appear_conductor_make(m->d, sp_rgb3(r.eta), sp_rgb3(r.k));
        }
        sh->bsdf = appear_bsdf_conductor(c);
    } else { /* MAT_GLASS: in RGB mode n_d everywhere, which the dispersive form passes through */
        appear_spectrum eta = lambda ? appear_dielectric_ior_spectrum(m->named, lambda)
                                     : sp(appear_dielectric_ior(m->named, APPEAR_LAMBDA_D));
        sh->glass = appear_dielectric_make_dispersive(m->d, eta);
        sh->bsdf = appear_bsdf_dielectric(sh->glass.hero);
        sh->dispersive = 1;
    }
}
#endif

/* Draws from the path's generator only for a stochastic composite: the other scenes' random
   sequences are those of a tracer without it. lambda: the path's wavelengths (spectral mode) or
   NULL (RGB). */
static void shade_bind(shade_point *sh, const tracer_material *m, rng *r, const float *lambda)
{
    sh->m = m;
    sh->bsdf = m->bsdf;
#if TRACER_HAS_MATERIALS
    sh->dispersive = 0;
    if (m->kind == MAT_METAL || m->kind == MAT_GLASS) shade_bind_named(sh, m, lambda);
#else
    (void)lambda;
#endif
#if TRACER_HAS_OPENPBR
    if (m->kind == MAT_OPENPBR) sh->bsdf = appear_bsdf_openpbr(&m->openpbr);
#endif
#if TRACER_HAS_LAYERED
    if (m->kind == MAT_COATED) sh->bsdf = appear_bsdf_coated(&m->coated);
    if (m->kind == MAT_LAYERED) {
        sh->arng = appear_rng_make(rng_u32(r));
        sh->layered = tracer_layered_make(&m->layered, &sh->arng);
        sh->bsdf = appear_bsdf_layered(&sh->layered, &sh->arng);
    }
#else
    (void)r;
#endif
    sh->stochastic = (appear_bsdf_flags(&sh->bsdf) & APPEAR_MODEL_STOCHASTIC) != 0;
}

/* The share of light a surface lets pass unscattered: an OpenPBR cutout's 1 - geometry_opacity;
   0 for every other surface (MAT_NONE is a boundary, not a surface). */
static float mat_pass(const tracer_material *m)
{
#if TRACER_HAS_OPENPBR
    if (m->kind == MAT_OPENPBR) return 1.0f - appear_openpbr_opacity(&m->openpbr);
#endif
    (void)m;
    return 0.0f;
}

/* every lobe a delta: no light sampling */
static int mat_delta_only(const shade_point *sh)
{
    return !(appear_bsdf_flags(&sh->bsdf) & APPEAR_LOBE_NONDELTA);
}

#if TRACER_HAS_SHEEN
/* the sheen's share of the samples: its energy E(mu_o) mean(C) against the base's 1 - E */
static float mat_sheen_prob(const tracer_material *m, appear_vec3 wo)
{
    float e = appear_sheen_albedo(&m->sheen, wo.z), c = 0.0f;
    int i;
    for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) c += m->sheen.color.v[i];
    c = e * c / APPEAR_SPECTRUM_SAMPLES;
    return c > 0.0f ? c / (c + 1.0f - e) : 0.0f;
}
#endif

/* f(wo, wi) and, for MIS, the sampler's density *pdf (0 for a stochastic model: not joined; the
   sheen's mixture needs its base's density, so no scene puts the sheen over a stochastic base) */
static appear_spectrum mat_eval(const shade_point *sh, appear_vec3 wo, appear_vec3 wi, float *pdf)
{
    const tracer_material *m = sh->m;
#if TRACER_HAS_MATERIALS
    if (sh->dispersive) {
        *pdf = appear_dielectric_dispersive_pdf(&sh->glass, wo, wi);
        return appear_dielectric_dispersive_eval(&sh->glass, wo, wi);
    }
#endif
    *pdf = sh->stochastic ? 0.0f : appear_bsdf_pdf(&sh->bsdf, wo, wi);
#if TRACER_HAS_SHEEN
    if (m->has_sheen) {
        float p = mat_sheen_prob(m, wo);
        *pdf = p * appear_sheen_pdf(&m->sheen, wo, wi) + (1.0f - p) * *pdf;
        return appear_sheen_layer_eval(&m->sheen, wo, wi, appear_bsdf_eval(&sh->bsdf, wo, wi),
                                       m->sheen_mode);
    }
#else
    (void)m;
#endif
    return appear_bsdf_eval(&sh->bsdf, wo, wi);
}

static int mat_sample(const shade_point *sh, appear_vec3 wo, rng *r, appear_bsdf_record *s)
{
    const tracer_material *m = sh->m;
    float uc = rng_f(r), u1 = rng_f(r), u2 = rng_f(r);
#if TRACER_HAS_MATERIALS
    if (sh->dispersive) return appear_dielectric_dispersive_sample(&sh->glass, wo, uc, u1, u2, s);
#endif
#if TRACER_HAS_SHEEN
    if (m->has_sheen) { /* one lobe by uc, then the mixture's f and pdf at the sampled wi */
        float p = mat_sheen_prob(m, wo), c;
        float ub = p < 1.0f ? (uc - p) / (1.0f - p) : 0.0f;
        int ok = uc < p ? appear_sheen_sample(&m->sheen, wo, 0.5f, u1, u2, s)
                        : appear_bsdf_sample(&sh->bsdf, wo, ub, u1, u2, s);
        int i;
        if (!ok) return 0;
        s->f = mat_eval(sh, wo, s->wi, &s->pdf);
        c = APPEAR_FABSF(s->wi.z);
        if (!(s->pdf > 0.0f)) return 0;
        for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) s->weight.v[i] = s->f.v[i] * c / s->pdf;
        return 1;
    }
#else
    (void)m;
#endif
    return appear_bsdf_sample(&sh->bsdf, wo, uc, u1, u2, s);
}

/* ======================================================================== */
/* Media                                                                    */
/* ======================================================================== */

/* value noise on the integer lattice, smoothstep-interpolated, in [0, 1] */
static float lattice(int x, int y, int z)
{
    uint32_t h = (uint32_t)x * 73856093u ^ (uint32_t)y * 19349663u ^ (uint32_t)z * 83492791u;
    h ^= h >> 13; h *= 0x5bd1e995u; h ^= h >> 15;
    return (float)(h & 0xffffu) * (1.0f / 65535.0f);
}
static float value_noise(appear_vec3 p)
{
    float fx = floorf(p.x), fy = floorf(p.y), fz = floorf(p.z);
    int x = (int)fx, y = (int)fy, z = (int)fz;
    float tx = p.x - fx, ty = p.y - fy, tz = p.z - fz;
    float a, b, c, d, e, f, g, k;
    tx = tx * tx * (3 - 2 * tx); ty = ty * ty * (3 - 2 * ty); tz = tz * tz * (3 - 2 * tz);
    a = lattice(x, y, z);     b = lattice(x + 1, y, z);
    c = lattice(x, y + 1, z); d = lattice(x + 1, y + 1, z);
    e = lattice(x, y, z + 1); f = lattice(x + 1, y, z + 1);
    g = lattice(x, y + 1, z + 1); k = lattice(x + 1, y + 1, z + 1);
    a += (b - a) * tx; c += (d - c) * tx; e += (f - e) * tx; g += (k - g) * tx;
    a += (c - a) * ty; e += (g - e) * ty;
    return a + (e - a) * tz;
}

float tracer_cloud_density(const tracer_medium *m, appear_vec3 p)
{
    /* box-relative coordinates q in [-1, 1]^3 */
    float qx = 2.0f * (p.x - m->lo.x) / (m->hi.x - m->lo.x) - 1.0f;
    float qy = 2.0f * (p.y - m->lo.y) / (m->hi.y - m->lo.y) - 1.0f;
    float qz = 2.0f * (p.z - m->lo.z) / (m->hi.z - m->lo.z) - 1.0f;
    float r2 = qx * qx + 1.6f * qy * qy + qz * qz; /* a flattened blob */
    float n = 0.0f, amp = 0.5f, fr = 2.5f, d;
    int o;
    for (o = 0; o < 4; ++o) {
        n += amp * value_noise(v3(qx * fr + 11.3f, qy * fr + 5.1f, qz * fr + 7.7f));
        amp *= 0.5f; fr *= 2.0f;
    }
    n /= 0.9375f;                               /* fBm in [0, 1] */
    d = 2.2f * n - 0.55f - 1.1f * r2;           /* dense core, wispy edges, holes */
    return d < 0.0f ? 0.0f : (d > 1.0f ? 1.0f : d);
}

/* scalar extinction at p along direction d (d matters for SGGX only) */
static float medium_sigma_scalar(const tracer_medium *m, appear_vec3 p, appear_vec3 d)
{
    (void)d;
    if (m->kind == MED_CLOUD) return m->sigma_max * tracer_cloud_density(m, p);
#if TRACER_HAS_SGGX
    if (m->kind == MED_SGGX) return appear_sggx_sigma_t(&m->sggx, m->sigma_max, d); /* rho sigma(d) [Heitz15] */
#endif
    return m->sigma_max;
}

/* Free flight from o along d over [0, tmax]. Returns 1 with *t the real
   collision, or 0 when the segment was passed.
   Chromatic homogeneous media use path-level spectral MIS (one-sample
   balance heuristic over the channels, as in pbrt-v4's r_u): the whole path
   samples distances with the channel `hero` (picked once per path), beta
   holds f / p_hero and ru the ratios p_i / p_hero; a contribution is
   beta L / avg(ru). appear_homogeneous_sample draws t with the channel that
   uc selects and reports every channel's transmittance, from which the
   per-channel pdfs follow: sigma_i T_i(t) at a collision, T_i(d) on a pass.
   (Its own per-event MIS weight is unbiased too, but in a long random walk
   its product over many events has a heavy tail.) */
static int medium_flight(const tracer_medium *m, appear_vec3 o, appear_vec3 d, float tmax, rng *r,
                         int hero, float *t, appear_spectrum *beta, appear_spectrum *ru)
{
    if (m->kind == MED_HOMOGENEOUS || m->kind == MED_SGGX) {
        appear_medium_sample ms;
        float u = rng_f(r), ph;
        int i;
        /* SGGX: homogeneous flake density, extinction depends on the ray
           direction only, so the flight is homogeneous along the ray */
        appear_spectrum sig = m->kind == MED_SGGX ? sp(medium_sigma_scalar(m, o, d)) : m->sigma_t;
        if (!appear_homogeneous_sample(sig, tmax, ((float)hero + 0.5f) / (float)APPEAR_SPECTRUM_SAMPLES, u, &ms)) {
            *beta = sp(0.0f); return 0;
        }
        ph = ms.scattered ? sig.v[hero] * ms.tr.v[hero] : ms.tr.v[hero];
        if (!(ph > 0.0f)) { *beta = sp(0.0f); return 0; }
        for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) {
            float pi = ms.scattered ? sig.v[i] * ms.tr.v[i] : ms.tr.v[i];
            /* a collision scores sigma_s = albedo sigma_t; a pass scores T */
            beta->v[i] *= (ms.scattered ? m->albedo.v[i] * pi : pi) / ph;
            ru->v[i] *= pi / ph;
        }
        *t = ms.t;
        return ms.scattered;
    }
#if TRACER_HAS_CTRACKER
    if (m->kind == MED_CLOUD_CHROMATIC) {
        /* chromatic delta tracking with the path's hero channel (the walk
           steps with sigma_t[hero]); beta and r_u take the path-level
           ratios F_i / p_hero and p_i / p_hero (appear.h, "Chromatic
           heterogeneous media"); a collision scores sigma_s,i(t) */
        appear_ctracker tr;
        appear_cmajorant_segment seg = appear_cmajorant_make_constant(m->sigma_t);
        float tt, dens = 0.0f;
        int i;
        appear_ctracker_init(&tr, APPEAR_TRACK_DELTA, tmax, &seg, 1,
                             ((float)hero + 0.5f) / (float)APPEAR_SPECTRUM_SAMPLES, NULL);
        while (appear_ctracker_next(&tr, rng_f(r), rng_f(r), &tt)) {
            dens = tracer_cloud_density(m, madd(o, d, tt));
            appear_ctracker_feed(&tr, sp_scale(m->sigma_t, dens));
        }
        if (tr.flags & (APPEAR_TRACK_BAD_INPUT | APPEAR_TRACK_BAD_DENSITY |
                        APPEAR_TRACK_TRUNCATED)) {
            *beta = sp(0.0f); return 0;
        }
        for (i = 0; i < APPEAR_SPECTRUM_SAMPLES; ++i) {
            float ss = m->albedo.v[i] * m->sigma_t.v[i] * dens; /* sigma_s,i(t) */
            float f = tr.collided ? tr.beta.v[i] * ss : tr.beta.v[i];
            beta->v[i] *= f;
            ru->v[i] *= tr.r_u.v[i];
        }
        *t = tr.t;
        return tr.collided;
    }
#endif
#if TRACER_HAS_TRACKERS
    {
        /* delta tracking against a constant majorant: a real collision has
           pdf sigma_t(t) T(t), so the weight is sigma_s / sigma_t = albedo */
        appear_tracker tr;
        appear_majorant_segment seg = appear_majorant_make_constant(m->kind == MED_CLOUD ? m->sigma_max : medium_sigma_scalar(m, o, d));
        float tt;
        appear_tracker_init(&tr, APPEAR_TRACK_DELTA, tmax, &seg, 1, NULL);
        while (appear_tracker_next(&tr, rng_f(r), rng_f(r), &tt))
            appear_tracker_feed(&tr, medium_sigma_scalar(m, madd(o, d, tt), d));
        if (tr.flags & (APPEAR_TRACK_BAD_INPUT | APPEAR_TRACK_BAD_DENSITY | APPEAR_TRACK_TRUNCATED)) { *beta = sp(0.0f); return 0; }
        if (tr.collided) { *beta = sp_mul(*beta, m->albedo); *t = tr.t; return 1; }
        return 0;
    }
#else
    (void)o; (void)d; (void)t; (void)r; (void)tmax;
    *beta = sp(0.0f);
    return 0;
#endif
}

/* Transmittance over [0, dist] along a shadow ray: closed form or ratio
   tracking (an unbiased estimate). */
static appear_spectrum medium_transmittance(const tracer_medium *m, appear_vec3 o, appear_vec3 d, float dist, rng *r)
{
    if (m->kind == MED_HOMOGENEOUS) return appear_homogeneous_transmittance(m->sigma_t, dist);
    if (m->kind == MED_SGGX) return appear_homogeneous_transmittance(sp(medium_sigma_scalar(m, o, d)), dist);
#if TRACER_HAS_CTRACKER
    if (m->kind == MED_CLOUD_CHROMATIC) {
        /* chromatic ratio tracking on the common majorant (the largest
           channel's): plain ratio tracking per channel, one walk */
        appear_ctracker tr;
        appear_cmajorant_segment seg =
            appear_cmajorant_make_constant(sp(appear_spectrum_max(m->sigma_t)));
        float tt;
        appear_ctracker_init(&tr, APPEAR_TRACK_RATIO, dist, &seg, 1, rng_f(r), NULL);
        while (appear_ctracker_next(&tr, rng_f(r), rng_f(r), &tt)) {
            float dens = tracer_cloud_density(m, madd(o, d, tt));
            appear_ctracker_feed(&tr, sp_scale(m->sigma_t, dens));
        }
        return tr.T;
    }
#endif
#if TRACER_HAS_TRACKERS
    {
        appear_tracker tr;
        appear_majorant_segment seg = appear_majorant_make_constant(m->sigma_max);
        float tt;
        appear_tracker_init(&tr, APPEAR_TRACK_RATIO, dist, &seg, 1, NULL);
        while (appear_tracker_next(&tr, rng_f(r), rng_f(r), &tt))
            appear_tracker_feed(&tr, medium_sigma_scalar(m, madd(o, d, tt), d));
        return sp(tr.T);
    }
#else
    (void)o; (void)d; (void)dist; (void)r;
    return sp(0.0f);
#endif
}

static float phase_eval(const tracer_medium *m, appear_vec3 wo, appear_vec3 wi)
{
    return appear_phase_eval(&m->phase, wo, wi);
}
/* returns 0 on failure; *w = f / pdf, *pdf, *delta */
static int phase_sample(const tracer_medium *m, appear_vec3 wo, rng *r, appear_vec3 *wi, float *w, float *pdf, int *delta)
{
    appear_phase_record ps;
    float uc = rng_f(r), u1 = rng_f(r), u2 = rng_f(r);
    int ok = appear_phase_sample(&m->phase, wo, uc, u1, u2, &ps);
    *wi = ps.wi; *w = ps.weight; *pdf = ps.pdf; *delta = (ps.flags & APPEAR_LOBE_SPECULAR) != 0;
    return ok;
}

/* ======================================================================== */
/* Lights                                                                   */
/* ======================================================================== */
static appear_spectrum env_radiance(const tracer_scene *sc, appear_vec3 d)
{
    float a = 0.5f * (d.y + 1.0f);
    return sp_add(sp_scale(sc->env_top, a), sp_scale(sc->env_bottom, 1.0f - a));
}

/* 1 - cos(theta_max) of the cone that the sphere light subtends from p,
   without cancellation for distant lights; 0 when p is inside */
static float cone_one_minus_cos(const tracer_shape *l, appear_vec3 p)
{
    appear_vec3 pc = appear_sub(l->c, p);
    float d2 = appear_dot(pc, pc), s2 = l->r * l->r / d2;
    if (!(s2 < 1.0f)) return 0.0f;
    return s2 / (1.0f + sqrtf(1.0f - s2));
}
/* solid-angle pdf of uniform cone sampling of the light from p */
static float light_pdf(const tracer_scene *sc, appear_vec3 p)
{
    float omc = cone_one_minus_cos(&sc->shapes[sc->light], p);
    return omc > 0.0f ? 1.0f / (6.28318531f * omc) : 0.0f;
}
static float power_heuristic(float a, float b) { return a * a / (a * a + b * b); }

/* Transmittance from p along d over [0, dist], starting in medium med:
   opaque surfaces block, MAT_NONE boundaries switch the medium. */
static appear_spectrum shadow_T(const tracer_scene *sc, appear_vec3 p, appear_vec3 d, float dist, int med, rng *r)
{
    appear_spectrum T = sp(1.0f);
    int k;
    for (k = 0; k < 32; ++k) {
        hit h;
        int got = intersect_only(sc, p, d, dist, -1, sc->light, &h);
        float seg = got ? h.t : dist;
        if (med >= 0) T = sp_mul(T, medium_transmittance(&sc->media[med], p, d, seg, r));
        if (!got) return T;
        {
            const tracer_material *bm = &sc->mats[sc->shapes[h.shape].material];
            if (bm->kind != MAT_NONE) { /* a surface: blocks, or (a cutout) passes a share */
                float pass = mat_pass(bm);
                if (!(pass > 0.0f)) return sp(0.0f);
                T = sp_scale(T, pass);
            }
            if (sp_is_zero(T)) return sp(0.0f);
        }
        med = appear_dot(d, h.n) < 0.0f ? sc->shapes[h.shape].medium : -1;
        {
            appear_vec3 q = madd(p, d, h.t);
            appear_vec3 o = spawn(q, h.n, d);
            dist -= appear_dot(appear_sub(o, p), d);
            p = o;
        }
        if (dist <= 0.0f) return T;
    }
    return sp(0.0f);
}

/* Samples a direction to the light from p: *wi, its solid-angle pdf, the
   distance to the light surface and its radiance. Returns 0 on failure. */
static int light_sample(const tracer_scene *sc, appear_vec3 p, rng *r, appear_vec3 *wi, float *pdf, float *dist, appear_spectrum *Le)
{
    const tracer_shape *l = &sc->shapes[sc->light];
    appear_vec3 pc = appear_sub(l->c, p);
    float dc = sqrtf(appear_dot(pc, pc));
    float omc = cone_one_minus_cos(l, p), u1 = rng_f(r), u2 = rng_f(r);
    float one_minus_ct, st, s, c, t;
    appear_frame f;
    if (!(omc > 0.0f)) return 0;
    one_minus_ct = u1 * omc;                      /* uniform in cos over the cone */
    st = sqrtf(one_minus_ct * (2.0f - one_minus_ct));
    appear_sincos_2pi(u2, &s, &c);
    f = appear_frame_from_normal(appear_scale(pc, 1.0f / dc));
    *wi = appear_normalize(appear_frame_to_world(f, v3(st * c, st * s, 1.0f - one_minus_ct)));
    t = hit_sphere(l, p, *wi, 0.0f, INF_T);
    if (!(t > 0.0f)) t = dc - l->r;              /* grazing the silhouette: rounding */
    *dist = t;
    *pdf = 1.0f / (6.28318531f * omc);
    *Le = sc->mats[l->material].emission;
    return 1;
}

/* ======================================================================== */
/* The path integrator                                                      */
/* ======================================================================== */
/* lambda: the path's wavelengths (spectral mode: the lights count as grey, the caller applies
   their spectrum) or NULL (RGB) */
static appear_spectrum radiance(const tracer_scene *sc, appear_vec3 o, appear_vec3 d, rng *r,
                                int nee, const float *lambda)
{
    appear_spectrum L = sp(0.0f), beta = sp(1.0f), ru = sp(1.0f);
    appear_vec3 prev_p = o;
    /* the channel that media sample distances with; spectral mode: channel 0, the hero
       wavelength (the wavelengths are already a random rotation), which the dispersive glass's
       sampler follows too */
    int hero = lambda ? 0 : (int)(rng_f(r) * (float)APPEAR_SPECTRUM_SAMPLES);
    float prev_pdf = 0.0f;
    /* prev_stoch: the last event was a non-delta one of a stochastic model (no MIS, tracer.h) */
    int med = -1, specular = 1, prev_stoch = 0, depth = 0, iter, only = -1;
    for (iter = 0; iter < 4 * TRACER_MAX_DEPTH; ++iter) {
        hit h;
        int got = intersect_only(sc, o, d, INF_T, only, -1, &h);
        if (got && sc->isolate) only = h.shape;
        if (med >= 0 && got) {
            const tracer_medium *m = &sc->media[med];
            float t;
            if (medium_flight(m, o, d, h.t, r, hero, &t, &beta, &ru)) {
                /* a real scattering event in the medium */
                appear_vec3 p = madd(o, d, t), wo = appear_neg(d), wi;
                float w, pdf;
                int delta;
                if (++depth > TRACER_MAX_DEPTH) break;
                if (nee) { /* next-event estimation, MIS with phase sampling */
                    appear_vec3 wl; float lpdf, dist; appear_spectrum Le;
                    if (light_sample(sc, p, r, &wl, &lpdf, &dist, &Le)) {
                        float ph = phase_eval(m, wo, wl);
                        if (ph > 0.0f) {
                            appear_spectrum T = shadow_T(sc, p, wl, dist * (1.0f - 1e-4f), med, r);
                            L = sp_add(L, sp_mul(sp_mul(beta, T), sp_scale(Le, ph * power_heuristic(lpdf, ph) / (lpdf * appear_spectrum_avg(ru)))));
                        }
                    }
                }
                if (!phase_sample(m, wo, r, &wi, &w, &pdf, &delta)) break;
                beta = sp_scale(beta, w);
                specular = delta; prev_pdf = pdf; prev_p = p; prev_stoch = 0;
                o = p; d = wi;
                goto roulette;
            }
            if (sp_is_zero(beta)) break;
        }
        if (!got) { L = sp_add(L, sp_mul(beta, sp_scale(env_radiance(sc, d), 1.0f / appear_spectrum_avg(ru)))); break; }
        {
            const tracer_shape *s = &sc->shapes[h.shape];
            const tracer_material *mt = &sc->mats[s->material];
            appear_vec3 p = madd(o, d, h.t);
            if (mt->kind == MAT_EMITTER) {
                float w = 1.0f;
                if (nee && !specular && h.shape == sc->light)
                    w = prev_stoch ? 0.0f : power_heuristic(prev_pdf, light_pdf(sc, prev_p));
                L = sp_add(L, sp_mul(beta, sp_scale(mt->emission, w / appear_spectrum_avg(ru))));
                break;
            }
            /* a medium boundary, or a cutout surface (an OpenPBR geometry_opacity below 1, a
               draw only then): pass through */
            if (mt->kind == MAT_NONE || (mat_pass(mt) > 0.0f && rng_f(r) < mat_pass(mt))) {
                med = appear_dot(d, h.n) < 0.0f ? s->medium : -1;
                o = spawn(p, h.n, d);
                continue;
            }
            {
                appear_frame f = shape_frame(s, h.n);
                appear_vec3 wo = appear_frame_to_local(f, appear_neg(d)), wi;
                appear_bsdf_record bs;
                shade_point sh;
                if (++depth > TRACER_MAX_DEPTH) break;
                shade_bind(&sh, mt, r, lambda);
#if TRACER_HAS_OPENPBR
                if (mt->kind == MAT_OPENPBR && !sp_is_zero(mt->emission)) /* found by the path */
                    L = sp_add(L, sp_mul(beta, sp_scale(appear_openpbr_emission(&mt->openpbr, wo),
                                                        1.0f / appear_spectrum_avg(ru))));
#endif
                /* NEE, MIS with BSDF sampling (a stochastic model: bpdf = 0, weight 1) */
                if (nee && !mat_delta_only(&sh)) {
                    appear_vec3 wl; float lpdf, dist, bpdf; appear_spectrum Le;
                    if (light_sample(sc, p, r, &wl, &lpdf, &dist, &Le)) {
                        appear_vec3 wll = appear_frame_to_local(f, wl);
                        appear_spectrum fv = mat_eval(&sh, wo, wll, &bpdf);
                        if (!sp_is_zero(fv)) {
                            appear_vec3 po = spawn(p, h.n, wl);
                            /* into the shape: its medium, if it has one (a transmitting surface) */
                            int lmed = appear_dot(wl, h.n) < 0.0f ? s->medium : -1;
                            appear_spectrum T =
                                shadow_T(sc, po, wl, dist * (1.0f - 1e-4f), lmed, r);
                            float c = fabsf(wll.z) * power_heuristic(lpdf, bpdf) / (lpdf * appear_spectrum_avg(ru));
                            L = sp_add(L, sp_mul(sp_mul(beta, T), sp_mul(fv, sp_scale(Le, c))));
                        }
                    }
                }
                if (!mat_sample(&sh, wo, r, &bs)) break;
                beta = sp_mul(beta, bs.weight);
                if (bs.flags & APPEAR_SAMPLE_TERMINATE_SECONDARY) {
                    /* a dispersive refraction: the hero (channel 0) alone carries on. Its
                       direction has density 0 for the other wavelengths, so their r_u become 0
                       and avg(r_u) = r_u0 / n multiplies the hero's later light by n, as
                       pbrt-v4's SampledWavelengths::TerminateSecondary does with the pdf */
                    int i;
                    for (i = 1; i < APPEAR_SPECTRUM_SAMPLES; ++i) beta.v[i] = ru.v[i] = 0.0f;
                }
                wi = appear_frame_to_world(f, bs.wi);
                if ((bs.flags & APPEAR_LOBE_TRANSMISSION) && s->medium >= 0) /* into or out of */
                    med = appear_dot(wi, h.n) < 0.0f ? s->medium : -1;
                specular = (bs.flags & APPEAR_LOBE_SPECULAR) != 0;
                prev_pdf = bs.pdf; prev_p = p; prev_stoch = sh.stochastic;
                o = spawn(p, h.n, wi); d = appear_normalize(wi);
            }
        }
    roulette:
        if (depth > 3) { /* Russian roulette only once the throughput has dropped */
            float q = appear_spectrum_max(beta) / appear_spectrum_avg(ru);
            if (q < 1.0f) {
                if (!(rng_f(r) < q)) break;
                beta = sp_scale(beta, 1.0f / q);
            }
        }
        if (sp_is_zero(beta)) break;
    }
    return L;
}

/* ======================================================================== */
/* Spectral colour: CIE 1931 x D65 to linear sRGB                           */
/* ======================================================================== */
/* The XYZ -> linear sRGB matrix and D65's luminance, for the tables as the tracer reads them
   (linear between their 5 nm rows, examples/cie_data.h). */
typedef struct spectral_colour {
    float M[3][3]; /* XYZ -> linear sRGB (IEC 61966-2-1 primaries, the integrated D65 white) */
    float inv_y;   /* 1 / integral of D65 ybar */
} spectral_colour;

/* the tables at lambda_nm, linear between rows, clamped to 360-830 nm */
static void cie_lookup(float lambda_nm, float xyz[3], float *d65)
{
    float t = (lambda_nm - CIE_LAMBDA_MIN) / CIE_LAMBDA_STEP, f;
    int i, c;
    t = t > 0.0f ? (t < (float)(CIE_N - 1) ? t : (float)(CIE_N - 1)) : 0.0f; /* NaN: 360 */
    i = (int)t;
    i = i < CIE_N - 2 ? i : CIE_N - 2;
    f = t - (float)i;
    for (c = 0; c < 3; ++c)
        xyz[c] = cie_cmf_5nm[i][c] + f * (cie_cmf_5nm[i + 1][c] - cie_cmf_5nm[i][c]);
    *d65 = cie_d65_5nm[i] + f * (cie_d65_5nm[i + 1] - cie_d65_5nm[i]);
}

/* the inverse of a 3x3 matrix, by cofactors */
static void inverse3(double m[3][3], double o[3][3]) /* m is only read */
{
    double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                 m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                 m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            int a = (j + 1) % 3, b = (j + 2) % 3, c = (i + 1) % 3, e = (i + 2) % 3;
            o[i][j] = (m[a][c] * m[b][e] - m[a][e] * m[b][c]) / det;
        }
}

/* As tests/gen/gen_materials.c builds appear_metal_to_rgb's matrix: the sRGB primaries' XYZ
   scaled so that they sum to the white, here the D65 x CIE integral of the tables as read above
   (each 5 nm step a product of two linear functions, which Simpson's rule integrates exactly),
   so that a flat spectrum maps to exactly equal RGB. */
static spectral_colour spectral_colour_make(void)
{
    static const double xy[3][2] = { { 0.64, 0.33 }, { 0.30, 0.60 }, { 0.15, 0.06 } };
    double W[3] = { 0, 0, 0 }, P[3][3], Pi[3][3], A[3][3], Mi[3][3], k[3];
    spectral_colour sc;
    int i, j, c;
    for (i = 0; i + 1 < CIE_N; ++i)
        for (c = 0; c < 3; ++c) {
            double d0 = cie_d65_5nm[i], d1 = cie_d65_5nm[i + 1];
            double x0 = cie_cmf_5nm[i][c], x1 = cie_cmf_5nm[i + 1][c];
            W[c] += (double)CIE_LAMBDA_STEP / 6.0 *
                    (2.0 * d0 * x0 + d0 * x1 + d1 * x0 + 2.0 * d1 * x1);
        }
    for (j = 0; j < 3; ++j) { /* columns: the primaries' XYZ at Y = 1 */
        P[0][j] = xy[j][0] / xy[j][1];
        P[1][j] = 1.0;
        P[2][j] = (1.0 - xy[j][0] - xy[j][1]) / xy[j][1];
    }
    inverse3(P, Pi);
    for (i = 0; i < 3; ++i) k[i] = (Pi[i][0] * W[0] + Pi[i][1] * W[1] + Pi[i][2] * W[2]) / W[1];
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) A[i][j] = P[i][j] * k[j]; /* linear sRGB -> XYZ */
    inverse3(A, Mi);
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) sc.M[i][j] = (float)Mi[i][j];
    sc.inv_y = (float)(1.0 / W[1]);
    return sc;
}

static void spectral_colour_at(const spectral_colour *sc, float lambda_nm, float *illum,
                               float rgb_bar[3])
{
    float xyz[3], d65;
    int c;
    cie_lookup(lambda_nm, xyz, &d65);
    *illum = d65 * sc->inv_y;
    for (c = 0; c < 3; ++c)
        rgb_bar[c] = sc->M[c][0] * xyz[0] + sc->M[c][1] * xyz[1] + sc->M[c][2] * xyz[2];
}

void tracer_spectral_colour(float lambda_nm, float *illum, float rgb_bar[3])
{
    spectral_colour sc = spectral_colour_make();
    spectral_colour_at(&sc, lambda_nm, illum, rgb_bar);
}

/* The path's wavelengths from one uniform u (Wilkie et al. 2014, tracer.h): the hero uniform in
   the range, the others 1/n of the range apart after it, wrapped around (each one uniform too). */
static void sample_wavelengths(float u, float lambda[APPEAR_SPECTRUM_SAMPLES])
{
    const float range = TRACER_LAMBDA_MAX - TRACER_LAMBDA_MIN;
    int j;
    for (j = 0; j < APPEAR_SPECTRUM_SAMPLES; ++j) {
        float x = u + (float)j / (float)APPEAR_SPECTRUM_SAMPLES;
        x = x < 1.0f ? x : x - 1.0f;
        lambda[j] = TRACER_LAMBDA_MIN + range * x;
        lambda[j] = lambda[j] < TRACER_LAMBDA_MAX ? lambda[j] : TRACER_LAMBDA_MAX;
    }
}

/* A spectral path's linear sRGB: the mean over its n wavelengths of L illum rgb_bar / p, p =
   1 / range the density of each wavelength. */
static void spectral_to_rgb(const spectral_colour *sc, appear_spectrum L,
                            const float lambda[APPEAR_SPECTRUM_SAMPLES], float rgb[3])
{
    const float w = (TRACER_LAMBDA_MAX - TRACER_LAMBDA_MIN) / (float)APPEAR_SPECTRUM_SAMPLES;
    int j, c;
    rgb[0] = rgb[1] = rgb[2] = 0.0f;
    for (j = 0; j < APPEAR_SPECTRUM_SAMPLES; ++j) {
        float illum, bar[3];
        spectral_colour_at(sc, lambda[j], &illum, bar);
        for (c = 0; c < 3; ++c) rgb[c] += w * L.v[j] * illum * bar[c];
    }
}

/* ======================================================================== */
/* Threaded renderer with a progress bar                                    */
/* ======================================================================== */
typedef struct {
    const tracer_scene *sc; const tracer_options *opt; tracer_image *img;
    spectral_colour colour; /* spectral mode */
    appear_vec3 fw, rt, upv; float tx, ty;
    int next_row, rows_done; long nonfinite;
    pthread_mutex_t lock; double t0;
} job;

static double now_s(void) { struct timespec ts; clock_gettime(CLOCK_MONOTONIC, &ts); return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec; }

static appear_vec3 camera_dir(const job *jb, float x, float y)
{
    float sx = (2.0f * x / (float)jb->img->w - 1.0f) * jb->tx, sy = (1.0f - 2.0f * y / (float)jb->img->h) * jb->ty;
    return appear_normalize(appear_add(jb->fw, appear_add(appear_scale(jb->rt, sx), appear_scale(jb->upv, sy))));
}

static void *worker(void *arg)
{
    job *jb = (job *)arg;
    const tracer_scene *sc = jb->sc;
    int w = jb->img->w, hgt = jb->img->h, spp = jb->opt->spp;
    for (;;) {
        int y, x, k;
        long bad = 0;
        pthread_mutex_lock(&jb->lock);
        y = jb->next_row++;
        pthread_mutex_unlock(&jb->lock);
        if (y >= hgt) break;
        for (x = 0; x < w; ++x) {
            rng r = rng_make(jb->opt->seed, (uint64_t)y * (uint64_t)w + (uint64_t)x);
            double sum[3] = { 0, 0, 0 }, s2[3] = { 0, 0, 0 };
            size_t i = (size_t)y * w + x;
            hit h;
            for (k = 0; k < spp; ++k) {
                float jx = rng_f(&r), jy = rng_f(&r), lambda[APPEAR_SPECTRUM_SAMPLES], rgb[3];
                appear_vec3 dir = jb->opt->pixel_centre ? camera_dir(jb, x + 0.5f, y + 0.5f) : camera_dir(jb, (float)x + jx, (float)y + jy);
                appear_spectrum L;
                int c;
                /* the hero stratified over the pixel's samples: less colour noise (the
                   per-sample variance below then overstates the mean's, a safe bound) */
                if (jb->opt->spectral)
                    sample_wavelengths(((float)k + rng_f(&r)) / (float)spp, lambda);
                L = radiance(sc, sc->eye, dir, &r, sc->light >= 0 && !jb->opt->no_nee,
                             jb->opt->spectral ? lambda : NULL);
                if (jb->opt->spectral) spectral_to_rgb(&jb->colour, L, lambda, rgb);
                else for (c = 0; c < 3; ++c) rgb[c] = L.v[c];
                if (!(isfinite(rgb[0]) && isfinite(rgb[1]) && isfinite(rgb[2]))) {
                    ++bad;
                    continue;
                }
                for (c = 0; c < 3; ++c) { sum[c] += rgb[c]; s2[c] += (double)rgb[c] * rgb[c]; }
            }
            for (k = 0; k < 3; ++k) {
                double v = spp > 1 ? (s2[k] - sum[k] * sum[k] / spp) / (spp - 1) : 0.0;
                jb->img->rgb[3 * i + k] = (float)(sum[k] / spp);
                jb->img->var[3 * i + k] = (float)(v > 0.0 ? v : 0.0);
            }
            jb->img->id[i] = intersect(sc, sc->eye, camera_dir(jb, x + 0.5f, y + 0.5f), INF_T, &h) ? h.shape : -1;
        }
        pthread_mutex_lock(&jb->lock);
        jb->nonfinite += bad;
        ++jb->rows_done;
        if (jb->opt->progress && isatty(2) && (100 * jb->rows_done / hgt) != (100 * (jb->rows_done - 1) / hgt)) {
            double el = now_s() - jb->t0, eta = el / jb->rows_done * (hgt - jb->rows_done);
            int bar = 40 * jb->rows_done / hgt, i;
            fprintf(stderr, "\r  %-10s [", sc->name ? sc->name : "");
            for (i = 0; i < 40; ++i) fputc(i < bar ? '#' : '.', stderr);
            fprintf(stderr, "] %3d%%  %5.1fs elapsed, ~%5.1fs left ", 100 * jb->rows_done / hgt, el, eta);
        }
        pthread_mutex_unlock(&jb->lock);
    }
    return NULL;
}

/* every channel equal */
static int sp_is_grey(appear_spectrum a)
{
    int i, grey = 1;
    for (i = 1; i < APPEAR_SPECTRUM_SAMPLES; ++i) grey &= a.v[i] == a.v[0];
    return grey;
}

int tracer_render(const tracer_scene *sc, const tracer_options *opt, tracer_image *img)
{
    job jb;
    pthread_t tid[64];
    int i, nt = opt->threads < 1 ? 1 : (opt->threads > 64 ? 64 : opt->threads);
    size_t n = (size_t)opt->w * opt->h;
    memset(img, 0, sizeof *img);
    if (opt->w < 1 || opt->h < 1 || opt->spp < 1) return -1;
    if (!opt->spectral && APPEAR_SPECTRUM_SAMPLES < 3) return -1; /* RGB needs three channels */
    if (opt->spectral) { /* the lights' spectrum is D65 times their (grey) value */
        int grey = sp_is_grey(sc->env_top) && sp_is_grey(sc->env_bottom);
        for (i = 0; i < sc->n_shapes; ++i) {
            const tracer_material *m = &sc->mats[sc->shapes[i].material];
            if (m->kind == MAT_EMITTER || m->kind == MAT_OPENPBR) grey &= sp_is_grey(m->emission);
        }
        if (!grey) return -1;
    }
    img->w = opt->w; img->h = opt->h;
    img->rgb = (float *)calloc(n * 3, sizeof(float));
    img->var = (float *)calloc(n * 3, sizeof(float));
    img->id = (int *)calloc(n, sizeof(int));
    if (!img->rgb || !img->var || !img->id) { tracer_image_free(img); return -1; }
#if TRACER_HAS_LAYERED
    /* One eval of each appear_coated here, before the threads start: appear.h's rough coats (for
       now) fill a cache on first use, in static storage of a static inline function: one copy per
       translation unit, so appear_coated_make in scenes.c leaves this unit's copy empty, and
       threads filling it at once race (ThreadSanitizer; a nondeterministic image). */
    for (i = 0; i < sc->n_mats; ++i)
        if (sc->mats[i].kind == MAT_COATED) {
            appear_vec3 n = v3(0.0f, 0.0f, 1.0f);
            (void)appear_coated_eval(&sc->mats[i].coated, n, n);
        }
#endif
    memset(&jb, 0, sizeof jb);
    jb.sc = sc; jb.opt = opt; jb.img = img;
    jb.colour = spectral_colour_make();
    jb.fw = appear_normalize(appear_sub(sc->look, sc->eye));
    jb.rt = appear_normalize(appear_cross(jb.fw, sc->up));
    jb.upv = appear_cross(jb.rt, jb.fw);
    jb.ty = tanf(0.5f * sc->fov); jb.tx = jb.ty * (float)opt->w / (float)opt->h;
    pthread_mutex_init(&jb.lock, NULL);
    jb.t0 = now_s();
    for (i = 0; i < nt; ++i)
        if (pthread_create(&tid[i], NULL, worker, &jb)) { nt = i; break; }
    if (nt == 0) worker(&jb);
    for (i = 0; i < nt; ++i) pthread_join(tid[i], NULL);
    pthread_mutex_destroy(&jb.lock);
    if (opt->progress && isatty(2)) fprintf(stderr, "\n");
    img->nonfinite = jb.nonfinite;
    img->seconds = now_s() - jb.t0;
    return 0;
}

void tracer_image_free(tracer_image *img)
{
    free(img->rgb); free(img->var); free(img->id);
    img->rgb = img->var = NULL; img->id = NULL;
}

int tracer_write(const tracer_image *img, const char *dir, const char *name, float exposure)
{
    char path[1024];
    const char *names[4] = { "R", "G", "B", "var" }; /* var: of one sample, channel mean */
    size_t i, n = (size_t)img->w * img->h;
    float *buf = (float *)malloc(n * 4 * sizeof(float));
    int rv;
    if (!buf) return -1;
    mkdir(dir, 0777);
    for (i = 0; i < n; ++i) {
        buf[4 * i] = img->rgb[3 * i]; buf[4 * i + 1] = img->rgb[3 * i + 1]; buf[4 * i + 2] = img->rgb[3 * i + 2];
        buf[4 * i + 3] = (img->var[3 * i] + img->var[3 * i + 1] + img->var[3 * i + 2]) / 3.0f;
    }
    snprintf(path, sizeof path, "%s/%s.exr", dir, name);
    rv = img_write_exr(path, img->w, img->h, 4, names, buf);
    free(buf);
    if (rv) return rv;
    snprintf(path, sizeof path, "%s/%s.png", dir, name);
    return img_write_png(path, img->w, img->h, img->rgb, exposure);
}
