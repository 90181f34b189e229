/* examples/scenes.c - the validation scenes of the demo and the tests.
   Each scene states what it must show; tests/test_tracer.c checks it. */
#include "tracer.h"
#include "openpbr_presets.h"
#include <math.h>
#include <string.h>

const char *const tracer_scene_names[] = { "furnace", "gallery", "cloud",
#if TRACER_HAS_EON && TRACER_HAS_SHEEN
                                           "diffuse",
#endif
#if TRACER_HAS_SGGX
                                           "fibers",
#endif
#if TRACER_HAS_CTRACKER
                                           "chroma",
#endif
#if TRACER_HAS_LAYERED
                                           "layered", /* trace renders it with "layered_ref" */
#endif
#if TRACER_HAS_OPENPBR
                                           "openpbr", "openpbr_furnace",
#endif
#if TRACER_HAS_MATERIALS
                                           "metals", "prism", /* made for spectral mode */
#endif
                                           NULL };

int tracer_scene_is_spectral(const char *name)
{
    return !strcmp(name, "metals") || !strcmp(name, "prism");
}

const char *tracer_scene_expectation(const char *name)
{
    if (!strcmp(name, "furnace"))
        return "uniform white environment: lossless models (Lambert R=1, non-absorbing media, multiple-scattering "
               "microfacets) render 1.0 to noise; energy-losing ones (single-scattering microfacets, Ward) darker, never above 1";
    if (!strcmp(name, "gallery"))
        return "material gallery under a sky and a spherical area light (NEE + MIS)";
    if (!strcmp(name, "cloud"))
        return "heterogeneous procedural cloud (HG g = 0.6, albedo 0.95) in a box, delta tracking + ratio-tracked shadow rays";
    if (!strcmp(name, "chroma"))
        return "chromatic heterogeneous cloud: red scatters (albedo 0.97, sigma_t 12), blue is "
               "absorbed (albedo 0.2, sigma_t 3); appear_ctracker free flights with the path's "
               "hero + chromatic ratio-tracked shadow rays";
    if (!strcmp(name, "diffuse"))
        return "rough diffuse and sheen, lit from near the camera: Lambert, then EON at sigma 0 "
               "(= Lambert), 0.5 and 1 (flatter, brighter rims: retro-reflection, no energy lost); "
               "the LTC sheen over a dark base (bright rims), over EON sigma 1";
    if (!strcmp(name, "layered") || !strcmp(name, "layered_ref"))
        return "coats, left to right: plastic (smooth coat eta 1.5 over red Lambert), rough "
               "plastic (GGX 0.2 coat), coated gold (GGX 0.1 coat over GGX 0.15 gold), "
               "varnished diffuse (smooth absorbing amber coat over Lambert 0.7); \"layered\" "
               "is the fast form (appear_coated), \"layered_ref\" the same spheres through the "
               "reference random walk (appear_layered); trace renders both and their difference";
    if (!strcmp(name, "fibers"))
        return "isotropic (left) vs SGGX fiber (right) media, same density, lit from the side";
    if (!strcmp(name, "metals"))
        return "named metals as GGX alpha 0.25 spheres, left to right gold, copper, aluminium, "
               "silver, chromium, titanium (appear.h's measured n + ik), under a grey sky and a "
               "white light: spectral (their n, k at the path's wavelengths) against RGB "
               "(appear_metal_to_rgb's fitted eta, k; and its F82 form)";
    if (!strcmp(name, "openpbr"))
        return "OpenPBR presets from the spec's example materials (examples/openpbr_presets.c), "
               "front row car paint, brushed aluminium, glass, velvet, ceramic; back row rubber, "
               "skin, plastic, gold, honey (a glass around a scattering medium)";
    if (!strcmp(name, "openpbr_furnace"))
        return "OpenPBR's white-furnace configurations [OpenPBR11 \"White furnace testing\"] in a "
               "uniform white environment: every sphere renders 1 within its noise and the model's "
               "stated error, the coat and fuzz over glass darker (their light reflected back "
               "inside is lost)";
    if (!strcmp(name, "prism"))
        return "a smooth SF11 glass prism (appear_dielectric_make_dispersive) in front of a "
               "thin white light bar: seen through the prism the bar fans out into its "
               "spectrum (spectral mode); the RGB build's one index n_d shows it white";
    return "";
}

static tracer_medium medium_homogeneous(appear_spectrum sigma_t, appear_spectrum albedo, appear_phase phase)
{
    tracer_medium m;
    memset(&m, 0, sizeof m);
    m.kind = MED_HOMOGENEOUS; m.sigma_t = sigma_t; m.albedo = albedo; m.phase = phase;
    return m;
}
static tracer_medium medium_cloud(appear_vec3 lo, appear_vec3 hi, float sigma_max, appear_spectrum albedo, appear_phase phase)
{
    tracer_medium m;
    memset(&m, 0, sizeof m);
    m.kind = MED_CLOUD; m.lo = lo; m.hi = hi; m.sigma_max = sigma_max; m.albedo = albedo; m.phase = phase;
    return m;
}
/* Henyey-Greenstein with mean cosine g */
static appear_phase hg(float g) { return appear_phase_hg(appear_hg_make(g)); }

static void label(tracer_scene *sc, int shape, const char *l, int expect)
{
    if (shape < 0) return;
    sc->shapes[shape].label = l;
    sc->shapes[shape].expect = expect;
}

/* position of item i of n in a grid of `cols` columns, spacing s, centred */
static appear_vec3 grid_pos(int i, int n, int cols, float s, float y0)
{
    int rows = (n + cols - 1) / cols, row = i / cols, col = i % cols;
    int in_row = row == rows - 1 ? n - row * cols : cols;
    return appear_vec3_make(((float)col - 0.5f * (float)(in_row - 1)) * s, y0 + (0.5f * (float)(rows - 1) - (float)row) * s, 0.0f);
}

/* ---- white furnace ---------------------------------------------------- */
static void furnace(tracer_scene *sc)
{
    enum { MAXN = 16 };
    tracer_material mats[MAXN];
    tracer_medium meds[MAXN];
    const char *labels[MAXN];
    int expect[MAXN], is_box[MAXN], n = 0, i, none;
    memset(meds, 0, sizeof meds);
    tracer_scene_init(sc, "furnace");
    sc->env_top = sc->env_bottom = appear_spectrum_splat(1.0f);
    none = tracer_add_material(sc, tracer_mat_none());
    (void)none;

#define ITEM(mat, med, box, lab, exp) do { mats[n] = (mat); meds[n] = (med); is_box[n] = (box); labels[n] = (lab); expect[n] = (exp); ++n; } while (0)
    ITEM(tracer_mat_lambert(appear_spectrum_splat(1.0f)), meds[0], 0, "Lambert R=1", TRACER_EXPECT_ONE);
    ITEM(tracer_mat_none(), medium_homogeneous(appear_spectrum_splat(4.0f), appear_spectrum_splat(1.0f), hg(0.7f)), 0,
         "HG g=0.7 medium", TRACER_EXPECT_ONE);
    ITEM(tracer_mat_none(), medium_homogeneous(appear_spectrum_rgb(0.5f, 3.0f, 12.0f), appear_spectrum_splat(1.0f), hg(-0.5f)), 0,
         "chromatic medium, HG g=-0.5", TRACER_EXPECT_ONE);
#if TRACER_HAS_TRACKERS
    ITEM(tracer_mat_none(), medium_cloud(appear_vec3_make(0, 0, 0), appear_vec3_make(0, 0, 0), 12.0f, appear_spectrum_splat(1.0f), appear_phase_isotropic()), 1,
         "cloud box, isotropic", TRACER_EXPECT_ONE);
#endif
#if TRACER_HAS_WARD
    {
        ITEM(tracer_mat_bsdf(appear_bsdf_ward(appear_ward_make(appear_spectrum_splat(0.0f), appear_spectrum_splat(1.0f),
                                                               0.3f, 0.3f, APPEAR_WARD_BALANCED))),
             meds[0], 0, "Ward balanced a=0.3", TRACER_EXPECT_AT_MOST_ONE);
    }
#endif
#if TRACER_HAS_MICROFACET
    {
        appear_conductor c = appear_conductor_make_f82(appear_microfacet_make(APPEAR_GGX, 0.7f, 0.7f, APPEAR_SAMPLE_VISIBLE),
                                                       appear_spectrum_splat(1.0f), appear_spectrum_splat(1.0f));
        ITEM(tracer_mat_bsdf(appear_bsdf_conductor(c)), meds[0], 0, "GGX F=1 a=0.7 (single)", TRACER_EXPECT_AT_MOST_ONE);
        c = appear_conductor_make_f82(appear_microfacet_make(APPEAR_BECKMANN, 0.7f, 0.7f, APPEAR_SAMPLE_VISIBLE),
                                      appear_spectrum_splat(1.0f), appear_spectrum_splat(1.0f));
        ITEM(tracer_mat_bsdf(appear_bsdf_conductor(c)), meds[0], 0, "Beckmann F=1 a=0.7 (single)", TRACER_EXPECT_AT_MOST_ONE);
        ITEM(tracer_mat_bsdf(appear_bsdf_dielectric(
                 appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, 0.4f, 0.4f, APPEAR_SAMPLE_VISIBLE), 1.5f))),
             meds[0], 0, "GGX glass eta=1.5 a=0.4 (single)", TRACER_EXPECT_AT_MOST_ONE);
        ITEM(tracer_mat_bsdf(appear_bsdf_dielectric(
                 appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f, APPEAR_SAMPLE_VISIBLE), 1.5f))),
             meds[0], 0, "smooth glass eta=1.5", TRACER_EXPECT_ONE);
    }
#endif
#if TRACER_HAS_EON
    ITEM(tracer_mat_bsdf(appear_bsdf_eon(appear_eon_make(appear_spectrum_splat(1.0f), 1.0f))), meds[0], 0,
         "EON rho=1 sigma=1", TRACER_EXPECT_ONE);
#endif
#if TRACER_HAS_SHEEN
    ITEM(tracer_mat_sheen_over(appear_sheen_make(appear_spectrum_splat(1.0f), 0.4f),
                               appear_bsdf_lambert(appear_lambert_make(appear_spectrum_splat(1.0f))),
                               APPEAR_SHEEN_LAYER_RECIPROCAL),
         meds[0], 0, "sheen r=0.4 over Lambert R=1 (reciprocal)", TRACER_EXPECT_ONE);
#endif
#if TRACER_HAS_SGGX
    {
        tracer_medium m;
        memset(&m, 0, sizeof m);
        m.kind = MED_SGGX; m.sigma_max = 5.0f; m.albedo = appear_spectrum_splat(1.0f);
        m.sggx = appear_sggx_make_fiber(appear_normalize(appear_vec3_make(1, 1, 0)), 0.3f);
        m.phase = appear_phase_sggx_specular(m.sggx);
        ITEM(tracer_mat_none(), m, 0, "SGGX fiber medium a=0.3", TRACER_EXPECT_ONE);
    }
#endif
#undef ITEM
    for (i = 0; i < n; ++i) {
        appear_vec3 c = grid_pos(i, n, 4, 1.1f, 0.0f);
        int mi = tracer_add_material(sc, mats[i]), me = -1, s;
        if (mats[i].kind == MAT_NONE) {
            if (is_box[i]) {
                meds[i].lo = appear_vec3_make(c.x - 0.45f, c.y - 0.45f, c.z - 0.45f);
                meds[i].hi = appear_vec3_make(c.x + 0.45f, c.y + 0.45f, c.z + 0.45f);
            }
            me = tracer_add_medium(sc, meds[i]);
        }
        s = is_box[i] ? tracer_add_box(sc, meds[i].lo, meds[i].hi, mi, me) : tracer_add_sphere(sc, c, 0.48f, mi, me);
        label(sc, s, labels[i], expect[i]);
    }
    sc->isolate = 1; /* objects do not see each other: each faces the furnace alone */
    sc->eye = appear_vec3_make(0, 0, 7.5f); sc->look = appear_vec3_make(0, 0, 0); sc->fov = 0.5f;
}

/* ---- material gallery ------------------------------------------------- */
static void gallery(tracer_scene *sc)
{
    enum { MAXN = 16 };
    tracer_material mats[MAXN];
    const char *labels[MAXN];
    int tangent[MAXN], n = 0, i, floor_m;
    tracer_scene_init(sc, "gallery");
    sc->env_top = appear_spectrum_rgb(0.35f, 0.45f, 0.65f);
    sc->env_bottom = appear_spectrum_rgb(0.08f, 0.07f, 0.06f);
    floor_m = tracer_add_material(sc, tracer_mat_lambert(appear_spectrum_splat(0.5f)));
    tracer_add_box(sc, appear_vec3_make(-20, -1.5f, -20), appear_vec3_make(20, -0.5f, 20), floor_m, -1);
    tracer_add_sphere_light(sc, appear_vec3_make(-3.0f, 5.0f, 4.0f), 1.0f, appear_spectrum_splat(12.0f));

#define ITEM(mat, tan, lab) do { mats[n] = (mat); tangent[n] = (tan); labels[n] = (lab); ++n; } while (0)
    ITEM(tracer_mat_lambert(appear_spectrum_rgb(0.7f, 0.2f, 0.15f)), 0, "Lambert");
#if TRACER_HAS_WARD
    {
        appear_spectrum rd = appear_spectrum_rgb(0.1f, 0.15f, 0.3f), rs = appear_spectrum_splat(0.5f);
        ITEM(tracer_mat_bsdf(appear_bsdf_ward(appear_ward_make(rd, rs, 0.15f, 0.15f, APPEAR_WARD_BALANCED))), 0,
             "Ward isotropic a=0.15");
        ITEM(tracer_mat_bsdf(appear_bsdf_ward(appear_ward_make(rd, rs, 0.05f, 0.4f, APPEAR_WARD_BALANCED))), 1,
             "Ward anisotropic ax=0.05 ay=0.4");
    }
#endif
#if TRACER_HAS_MICROFACET
    {
        appear_spectrum silver = appear_spectrum_rgb(0.95f, 0.93f, 0.88f), one = appear_spectrum_splat(1.0f);
        /* silver-like F82 at the same alpha: GGX shows the longer tails */
        ITEM(tracer_mat_bsdf(appear_bsdf_conductor(appear_conductor_make_f82(
                 appear_microfacet_make(APPEAR_GGX, 0.15f, 0.15f, APPEAR_SAMPLE_VISIBLE), silver, one))), 0, "GGX a=0.15");
        ITEM(tracer_mat_bsdf(appear_bsdf_conductor(appear_conductor_make_f82(
                 appear_microfacet_make(APPEAR_BECKMANN, 0.15f, 0.15f, APPEAR_SAMPLE_VISIBLE), silver, one))), 0,
             "Beckmann a=0.15");
        /* gold, complex IOR at ~ (650, 550, 450) nm */
        ITEM(tracer_mat_bsdf(appear_bsdf_conductor(appear_conductor_make(
                 appear_microfacet_make(APPEAR_GGX, 0.3f, 0.3f, APPEAR_SAMPLE_VISIBLE),
                 appear_spectrum_rgb(0.143f, 0.374f, 1.442f), appear_spectrum_rgb(3.983f, 2.386f, 1.603f)))), 0,
             "rough gold a=0.3");
        ITEM(tracer_mat_bsdf(appear_bsdf_dielectric(
                 appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, 0.2f, 0.2f, APPEAR_SAMPLE_VISIBLE), 1.5f))), 0,
             "rough glass a=0.2");
        ITEM(tracer_mat_bsdf(appear_bsdf_conductor(appear_conductor_make_f82(
                 appear_microfacet_make(APPEAR_GGX, 1.0f, 1.0f, APPEAR_SAMPLE_VISIBLE), silver, one))), 0,
             "GGX a=1 single scattering");
    }
#endif
#if TRACER_HAS_MULTISCATTER
    {
        /* the same metal as the sphere before, energy-compensated */
        ITEM(tracer_mat_bsdf(appear_bsdf_conductor_comp(appear_conductor_make_f82(
                 appear_microfacet_make(APPEAR_GGX, 1.0f, 1.0f, APPEAR_SAMPLE_VISIBLE),
                 appear_spectrum_rgb(0.95f, 0.93f, 0.88f), appear_spectrum_splat(1.0f)))), 0,
             "GGX a=1 energy-compensated (multiple scattering on)");
    }
#endif
#if TRACER_HAS_THINFILM
    {
        /* 400 nm film of index 1.33 over a gold-like base */
        ITEM(tracer_mat_bsdf(appear_bsdf_thinfilm_conductor(appear_thinfilm_conductor_make(
                 appear_microfacet_make(APPEAR_GGX, 0.15f, 0.15f, APPEAR_SAMPLE_VISIBLE),
                 appear_thinfilm_make_rgb(1.33f, 400.0f, appear_spectrum_rgb(0.143f, 0.374f, 1.442f),
                                          appear_spectrum_rgb(3.983f, 2.386f, 1.603f))))),
             0, "iridescent coating (thin film 400 nm on gold)");
    }
#endif
#undef ITEM
    for (i = 0; i < n; ++i) {
        /* rows of 5 on the floor, later rows further back */
        int row = i / 5, col = i % 5, in_row = (n - row * 5) < 5 ? n - row * 5 : 5, s;
        float x = ((float)col - 0.5f * (float)(in_row - 1)) * 1.15f + (row & 1 ? 0.3f : 0.0f);
        s = tracer_add_sphere(sc, appear_vec3_make(x, 0.0f, -1.4f * (float)row), 0.5f, tracer_add_material(sc, mats[i]), -1);
        sc->shapes[s].tangent_mode = tangent[i];
        label(sc, s, labels[i], TRACER_EXPECT_NONE);
    }
    sc->eye = appear_vec3_make(0, 2.0f, 5.6f); sc->look = appear_vec3_make(0, -0.1f, -0.6f); sc->fov = 0.6f;
}

#if TRACER_HAS_EON && TRACER_HAS_SHEEN
/* ---- rough diffuse and sheen ------------------------------------------- */
static void diffuse(tracer_scene *sc)
{
    appear_spectrum clay = appear_spectrum_rgb(0.75f, 0.42f, 0.28f);
    tracer_material mats[6];
    const char *labels[6] = { "Lambert", "EON sigma 0", "EON sigma 0.5", "EON sigma 1",
                              "sheen r 0.35 over dark Lambert", "sheen r 0.6 over EON sigma 1" };
    int i, floor_m;
    tracer_scene_init(sc, "diffuse");
    sc->env_top = appear_spectrum_rgb(0.05f, 0.06f, 0.08f);
    sc->env_bottom = appear_spectrum_rgb(0.02f, 0.02f, 0.02f);
    floor_m = tracer_add_material(sc, tracer_mat_lambert(appear_spectrum_splat(0.3f)));
    tracer_add_box(sc, appear_vec3_make(-20, -1.5f, -20), appear_vec3_make(20, -0.55f, 20), floor_m, -1);
    /* the light a little above and beside the camera: EON's flattening shows, Lambert darkens
       toward its silhouette */
    tracer_add_sphere_light(sc, appear_vec3_make(1.0f, 2.0f, 8.0f), 0.8f, appear_spectrum_splat(40.0f));
    mats[0] = tracer_mat_lambert(clay);
    mats[1] = tracer_mat_bsdf(appear_bsdf_eon(appear_eon_make(clay, 0.0f)));
    mats[2] = tracer_mat_bsdf(appear_bsdf_eon(appear_eon_make(clay, 0.5f)));
    mats[3] = tracer_mat_bsdf(appear_bsdf_eon(appear_eon_make(clay, 1.0f)));
    mats[4] = tracer_mat_sheen_over(appear_sheen_make(appear_spectrum_rgb(0.9f, 0.55f, 0.7f), 0.35f),
                                    appear_bsdf_lambert(appear_lambert_make(appear_spectrum_rgb(0.05f, 0.02f, 0.04f))),
                                    APPEAR_SHEEN_LAYER_ALBEDO);
    mats[5] = tracer_mat_sheen_over(appear_sheen_make(appear_spectrum_splat(0.8f), 0.6f),
                                    appear_bsdf_eon(appear_eon_make(appear_spectrum_rgb(0.15f, 0.25f, 0.55f), 1.0f)),
                                    APPEAR_SHEEN_LAYER_ALBEDO);
    for (i = 0; i < 6; ++i) { /* one row */
        int s = tracer_add_sphere(sc, appear_vec3_make(((float)i - 2.5f) * 1.12f, 0.0f, 0.0f), 0.5f,
                                  tracer_add_material(sc, mats[i]), -1);
        label(sc, s, labels[i], TRACER_EXPECT_NONE);
    }
    sc->eye = appear_vec3_make(0, 0.7f, 7.5f); sc->look = appear_vec3_make(0, -0.02f, 0); sc->fov = 0.3f;
}
#endif

#if TRACER_HAS_LAYERED
/* ---- layered materials: the fast form, or the reference walk ---------- */
/* The same four spheres as appear_coated (ref 0) or as appear_layered (ref 1): the same coat, base
   and absorption. The reference's rough top is the energy-compensated dielectric (_comp), the
   walk tests/test_coated.c holds the fast form against: the walk's eval, which the tracer's light
   samples use, is consistent only with exact parts (SECTION layered). With the random-walk top
   (TRACER_TOP_MS) the rough plastic's eval integrated to 0.5151 +- 0.0007 against its sampler's
   0.5114 +- 0.0006 (mu_o 0.9, 400000 directions), and the spheres' fast - ref became rough
   plastic -0.14%, coated gold +0.89% (with _comp: -2.25%, +0.37%; trace --scene layered, 384
   spp). The walk's eval and pdf are estimates: the tracer joins no MIS at its vertices
   (tracer.h). */
static void layered(tracer_scene *sc, int ref)
{
    enum { N = 4 };
    const char *labels[N] = { "plastic", "rough plastic GGX 0.2", "coated gold",
                              "varnished diffuse" };
    appear_spectrum red = appear_spectrum_rgb(0.7f, 0.08f, 0.06f);
    appear_spectrum white = appear_spectrum_splat(1.0f), black = appear_spectrum_splat(0.0f);
    appear_spectrum amber = appear_spectrum_rgb(0.8f, 0.55f, 0.3f);
    appear_spectrum gold_eta = appear_spectrum_rgb(0.18f, 0.42f, 1.37f);
    appear_spectrum gold_k = appear_spectrum_rgb(3.42f, 2.35f, 1.77f);
    const int vis = APPEAR_SAMPLE_VISIBLE;
    appear_microfacet smooth = appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f, vis);
    appear_microfacet g02 = appear_microfacet_make(APPEAR_GGX, 0.2f, 0.2f, vis);
    appear_microfacet g01 = appear_microfacet_make(APPEAR_GGX, 0.1f, 0.1f, vis);
    appear_microfacet g015 = appear_microfacet_make(APPEAR_GGX, 0.15f, 0.15f, vis);
    appear_dielectric coat[N];
    appear_bsdf base[N];
    appear_spectrum color[N];
    int i, floor_m;
    tracer_scene_init(sc, ref ? "layered_ref" : "layered");
    coat[0] = appear_dielectric_make(smooth, 1.5f);
    coat[1] = appear_dielectric_make(g02, 1.5f);
    coat[2] = appear_dielectric_make(g01, 1.5f);
    coat[3] = appear_dielectric_make(smooth, 1.5f);
    base[0] = base[1] = appear_bsdf_lambert(appear_lambert_make(red));
    /* gold, complex IOR at ~ (650, 550, 450) nm */
    base[2] = appear_bsdf_conductor(appear_conductor_make(g015, gold_eta, gold_k));
    base[3] = appear_bsdf_lambert(appear_lambert_make(appear_spectrum_splat(0.7f)));
    color[0] = color[1] = color[2] = white;
    color[3] = amber; /* the coat's transmittance at normal incidence */
    sc->env_top = appear_spectrum_rgb(0.30f, 0.36f, 0.48f);
    sc->env_bottom = appear_spectrum_rgb(0.03f, 0.03f, 0.03f);
    floor_m = tracer_add_material(sc, tracer_mat_lambert(appear_spectrum_splat(0.3f)));
    tracer_add_box(sc, appear_vec3_make(-20, -1.5f, -20), appear_vec3_make(20, -0.55f, 20), floor_m,
                   -1);
    tracer_add_sphere_light(sc, appear_vec3_make(-2.5f, 3.0f, 6.0f), 1.2f,
                            appear_spectrum_splat(16.0f));
    for (i = 0; i < N; ++i) {
        tracer_material m;
        int s;
        if (!ref) { /* appear_plastic_make is appear_coated_make over a Lambert base */
            appear_coated c = i < 2 ? appear_plastic_make(i == 0 ? smooth : g02, 1.5f, red, white)
                                    : appear_coated_make(coat[i], &base[i], color[i],
                                                         APPEAR_COATED_ALBEDO);
            m = tracer_mat_coated(c);
        } else {
            tracer_layered l;
            memset(&l, 0, sizeof l);
            l.coat = coat[i];
            l.top = coat[i].smooth ? TRACER_TOP_SINGLE : TRACER_TOP_COMP;
            l.base = base[i];
            /* an absorbing slab of the coat's colour (albedo 0); the clear coats: no slab */
            l.slab = appear_slab_none();
            if (i == 3) l.slab = appear_slab_from_transmittance(amber, black, 0.0f);
            l.samples = 1; l.max_depth = APPEAR_LAYERED_MAX_DEPTH;
            m = tracer_mat_layered(l);
        }
        s = tracer_add_sphere(sc, appear_vec3_make(((float)i - 1.5f) * 1.12f, 0.0f, 0.0f), 0.5f,
                              tracer_add_material(sc, m), -1);
        label(sc, s, labels[i], TRACER_EXPECT_NONE);
    }
    sc->eye = appear_vec3_make(0, 0.7f, 7.5f);
    sc->look = appear_vec3_make(0, -0.02f, 0);
    sc->fov = 0.26f;
}
#endif

/* ---- heterogeneous cloud ---------------------------------------------- */
static void cloud(tracer_scene *sc)
{
    appear_vec3 lo = appear_vec3_make(-1.6f, -0.7f, -1.0f), hi = appear_vec3_make(1.6f, 0.9f, 1.0f);
    int floor_m, med, s;
    tracer_scene_init(sc, "cloud");
    sc->env_top = appear_spectrum_rgb(0.25f, 0.35f, 0.6f);
    sc->env_bottom = appear_spectrum_rgb(0.05f, 0.05f, 0.05f);
    floor_m = tracer_add_material(sc, tracer_mat_lambert(appear_spectrum_splat(0.4f)));
    tracer_add_box(sc, appear_vec3_make(-20, -2.0f, -20), appear_vec3_make(20, -1.0f, 20), floor_m, -1);
    tracer_add_sphere_light(sc, appear_vec3_make(2.5f, 4.0f, -2.0f), 1.0f, appear_spectrum_rgb(30.0f, 26.0f, 20.0f));
#if TRACER_HAS_TRACKERS
    med = tracer_add_medium(sc, medium_cloud(lo, hi, 8.0f, appear_spectrum_splat(0.95f), hg(0.6f)));
#else
    med = tracer_add_medium(sc, medium_homogeneous(appear_spectrum_splat(2.0f), appear_spectrum_splat(0.95f), hg(0.6f)));
#endif
    s = tracer_add_box(sc, lo, hi, tracer_add_material(sc, tracer_mat_none()), med);
    label(sc, s, "cloud", TRACER_EXPECT_NONE);
    sc->eye = appear_vec3_make(0, 0.7f, 4.4f); sc->look = appear_vec3_make(0, -0.1f, 0); sc->fov = 0.75f;
}

#if TRACER_HAS_SGGX
/* ---- isotropic vs SGGX fiber media, same flake density ---------------- */
static void fibers(tracer_scene *sc)
{
    tracer_medium m;
    int floor_m, none, s;
    tracer_scene_init(sc, "fibers");
    sc->env_top = appear_spectrum_rgb(0.2f, 0.25f, 0.35f);
    sc->env_bottom = appear_spectrum_rgb(0.04f, 0.04f, 0.04f);
    floor_m = tracer_add_material(sc, tracer_mat_lambert(appear_spectrum_splat(0.4f)));
    tracer_add_box(sc, appear_vec3_make(-20, -2.0f, -20), appear_vec3_make(20, -1.0f, 20), floor_m, -1);
    tracer_add_sphere_light(sc, appear_vec3_make(-4.0f, 2.5f, 2.0f), 0.8f, appear_spectrum_rgb(40.0f, 36.0f, 30.0f));
    none = tracer_add_material(sc, tracer_mat_none());
    memset(&m, 0, sizeof m);
    m.kind = MED_HOMOGENEOUS; m.phase = appear_phase_isotropic();
    m.sigma_t = appear_spectrum_splat(3.0f); m.albedo = appear_spectrum_rgb(0.95f, 0.85f, 0.6f);
    s = tracer_add_box(sc, appear_vec3_make(-1.9f, -1.0f, -0.7f), appear_vec3_make(-0.3f, 0.9f, 0.7f), none, tracer_add_medium(sc, m));
    label(sc, s, "isotropic medium", TRACER_EXPECT_NONE);
    /* vertical fibres (hair-like), flake density 3: sigma_t(w) = 3 sigma(w) */
    m.kind = MED_SGGX; m.sigma_max = 3.0f;
    m.sggx = appear_sggx_make_fiber(appear_vec3_make(0, 1, 0), 0.2f);
    m.phase = appear_phase_sggx_specular(m.sggx);
    s = tracer_add_box(sc, appear_vec3_make(0.3f, -1.0f, -0.7f), appear_vec3_make(1.9f, 0.9f, 0.7f), none, tracer_add_medium(sc, m));
    label(sc, s, "SGGX fibres (vertical), alpha 0.2", TRACER_EXPECT_NONE);
    sc->eye = appear_vec3_make(0, 0.6f, 5.0f); sc->look = appear_vec3_make(0, -0.1f, 0); sc->fov = 0.75f;
}
#endif

#if TRACER_HAS_CTRACKER
/* ---- chromatic heterogeneous cloud ------------------------------------- */
static void chroma(tracer_scene *sc)
{
    appear_vec3 lo = appear_vec3_make(-1.6f, -0.7f, -1.0f), hi = appear_vec3_make(1.6f, 0.9f, 1.0f);
    tracer_medium m;
    int floor_m, s;
    tracer_scene_init(sc, "chroma");
    sc->env_top = appear_spectrum_rgb(0.3f, 0.35f, 0.45f);
    sc->env_bottom = appear_spectrum_rgb(0.05f, 0.05f, 0.05f);
    floor_m = tracer_add_material(sc, tracer_mat_lambert(appear_spectrum_splat(0.4f)));
    tracer_add_box(sc, appear_vec3_make(-20, -2.0f, -20), appear_vec3_make(20, -1.0f, 20), floor_m,
                   -1);
    tracer_add_sphere_light(sc, appear_vec3_make(2.5f, 4.0f, -2.0f), 1.0f,
                            appear_spectrum_splat(28.0f));
    memset(&m, 0, sizeof m);
    m.kind = MED_CLOUD_CHROMATIC; m.lo = lo; m.hi = hi; m.phase = hg(0.5f);
    m.sigma_t = appear_spectrum_rgb(12.0f, 6.0f, 3.0f);    /* red 4x denser than blue */
    m.albedo = appear_spectrum_rgb(0.97f, 0.8f, 0.2f);     /* red scatters, blue is absorbed */
    s = tracer_add_box(sc, lo, hi, tracer_add_material(sc, tracer_mat_none()),
                       tracer_add_medium(sc, m));
    label(sc, s, "chromatic cloud", TRACER_EXPECT_NONE);
    sc->eye = appear_vec3_make(0, 0.7f, 4.4f);
    sc->look = appear_vec3_make(0, -0.1f, 0);
    sc->fov = 0.75f;
}
#endif

#if TRACER_HAS_MATERIALS
/* ---- named metals (spectral against RGB) ------------------------------ */
/* Grey everything but the metals: the spectral render's light is D65 (tracer.h), the
   illuminant appear_metal_to_rgb integrates under, so the two renders differ only by the RGB
   forms' error and by what RGB products miss in the interreflections. */
static void metals(tracer_scene *sc)
{
    enum { N = 6 };
    static const int ids[N] = { APPEAR_METAL_AU, APPEAR_METAL_CU, APPEAR_METAL_AL,
                                APPEAR_METAL_AG, APPEAR_METAL_CR, APPEAR_METAL_TI };
    static const char *const labels[N] = { "gold (Au)", "copper (Cu)", "aluminium (Al)",
                                           "silver (Ag)", "chromium (Cr)", "titanium (Ti)" };
    appear_microfacet d = appear_microfacet_make(APPEAR_GGX, 0.25f, 0.25f, APPEAR_SAMPLE_VISIBLE);
    int i, floor_m;
    tracer_scene_init(sc, "metals");
    sc->env_top = appear_spectrum_splat(0.5f);
    sc->env_bottom = appear_spectrum_splat(0.03f);
    floor_m = tracer_add_material(sc, tracer_mat_lambert(appear_spectrum_splat(0.3f)));
    tracer_add_box(sc, appear_vec3_make(-20, -1.5f, -20), appear_vec3_make(20, -0.55f, 20), floor_m,
                   -1);
    tracer_add_sphere_light(sc, appear_vec3_make(-2.0f, 3.0f, 6.0f), 1.0f,
                            appear_spectrum_splat(20.0f));
    for (i = 0; i < N; ++i) {
        int s = tracer_add_sphere(sc, appear_vec3_make(((float)i - 2.5f) * 1.12f, 0.0f, 0.0f),
                                  0.5f, tracer_add_material(sc, tracer_mat_metal(d, ids[i])), -1);
        label(sc, s, labels[i], TRACER_EXPECT_NONE);
    }
    sc->eye = appear_vec3_make(0, 0.7f, 7.5f);
    sc->look = appear_vec3_make(0, -0.02f, 0);
    sc->fov = 0.3f;
}

/* ---- a dispersive prism --------------------------------------------- */
/* A triangular prism, its axis vertical: the three side planes of the triangle with centre
   (cx, cz) and circumradius r, its first corner at angle rot (radians, from +x toward +z), and
   the caps y0 <= y <= y1. */
static int add_prism(tracer_scene *sc, float cx, float cz, float r, float rot, float y0, float y1,
                     int material)
{
    float pl[5][4];
    int i;
    for (i = 0; i < 3; ++i) { /* the side between corners i and i + 1: outward normal at the
                                 angle halfway between them, at distance r cos 60 deg */
        float a = rot + 2.0943951f * ((float)i + 0.5f);
        pl[i][0] = cosf(a); pl[i][1] = 0.0f; pl[i][2] = sinf(a);
        pl[i][3] = pl[i][0] * cx + pl[i][2] * cz + 0.5f * r;
    }
    pl[3][0] = 0.0f; pl[3][1] = 1.0f; pl[3][2] = 0.0f; pl[3][3] = y1;
    pl[4][0] = 0.0f; pl[4][1] = -1.0f; pl[4][2] = 0.0f; pl[4][3] = -y0;
    return tracer_add_convex(sc, (const float (*)[4])pl, 5, material, -1);
}

/* The classic view of dispersion: a thin white bar seen through a prism. The camera's rays
   cross the prism near its minimum deviation (about 66 degrees for SF11, n_d 1.785) and reach
   the bar: each wavelength at its own angle, so the bar's image fans out into the spectrum (about
   8 degrees from 420 to 680 nm). Camera paths find it (prism, prism, bar: delta events and an
   emitter), so no caustic needs to be found from the floor. */
static void prism(tracer_scene *sc)
{
    appear_microfacet smooth = appear_microfacet_make(APPEAR_GGX, 0.0f, 0.0f,
                                                      APPEAR_SAMPLE_VISIBLE);
    tracer_material bar = tracer_mat_lambert(appear_spectrum_splat(0.0f));
    int floor_m, s;
    tracer_scene_init(sc, "prism");
    sc->env_top = appear_spectrum_splat(0.3f);
    sc->env_bottom = appear_spectrum_splat(0.01f);
    floor_m = tracer_add_material(sc, tracer_mat_lambert(appear_spectrum_splat(0.15f)));
    tracer_add_box(sc, appear_vec3_make(-20, -1.6f, -20), appear_vec3_make(20, -0.6f, 20), floor_m,
                   -1);
    s = add_prism(sc, 0.0f, 0.0f, 0.92f, -0.5585f, -0.6f, 0.8f,
                  tracer_add_material(sc, tracer_mat_glass(smooth, APPEAR_DIELECTRIC_SF11)));
    label(sc, s, "SF11 prism", TRACER_EXPECT_NONE);
    bar.kind = MAT_EMITTER; /* an emitter without a NEE light: found by the paths alone */
    bar.emission = appear_spectrum_splat(4.0f);
    s = tracer_add_box(sc, appear_vec3_make(-2.70f, -0.6f, -1.39f),
                       appear_vec3_make(-2.64f, 2.0f, -1.33f), tracer_add_material(sc, bar), -1);
    sc->eye = appear_vec3_make(0, 1.3f, 6.0f);
    sc->look = appear_vec3_make(0.1f, 0.12f, 0);
    sc->fov = 0.34f;
}
#endif

#if TRACER_HAS_OPENPBR
/* ---- OpenPBR presets ---------------------------------------------------- */
/* The gallery's sky, floor and light; two rows of five spheres (examples/openpbr_presets.c). The
   brushed aluminium's tangent (the NDF's long axis; the grooves run across it, [OpenPBR11]
   "Microfacet model") along the latitude circles: vertical grooves, highlights drawn sideways. */
static void openpbr_gallery(tracer_scene *sc)
{
    int i, floor_m, n = openpbr_n_presets < 10 ? openpbr_n_presets : 10;
    tracer_scene_init(sc, "openpbr");
    sc->env_top = appear_spectrum_rgb(0.35f, 0.45f, 0.65f);
    sc->env_bottom = appear_spectrum_rgb(0.08f, 0.07f, 0.06f);
    floor_m = tracer_add_material(sc, tracer_mat_lambert(appear_spectrum_splat(0.5f)));
    tracer_add_box(sc, appear_vec3_make(-20, -1.5f, -20), appear_vec3_make(20, -0.5f, 20), floor_m,
                   -1);
    tracer_add_sphere_light(sc, appear_vec3_make(-3.0f, 5.0f, 4.0f), 1.0f,
                            appear_spectrum_splat(12.0f));
    for (i = 0; i < n; ++i) {
        appear_openpbr_params p = openpbr_presets[i].params();
        int row = i / 5, col = i % 5, s;
        float x = ((float)col - 2.0f) * 1.15f + (row & 1 ? 0.3f : 0.0f);
        s = tracer_add_openpbr_sphere(sc, appear_vec3_make(x, 0.0f, -1.4f * (float)row), 0.5f, &p);
        if (s < 0) continue;
        sc->shapes[s].tangent_mode = openpbr_presets[i].brushed;
        label(sc, s, openpbr_presets[i].name, TRACER_EXPECT_NONE);
    }
    sc->eye = appear_vec3_make(0, 2.0f, 5.6f);
    sc->look = appear_vec3_make(0, -0.1f, -0.6f);
    sc->fov = 0.6f;
}

/* ---- OpenPBR white furnace ------------------------------------------------ */
/* [OpenPBR11] "White furnace testing": white metal, white diffuse and subsurface bases, the
   translucent base (depth 0, and depth > 0 with a white scattering interior), their mixes, with
   a white coat and a white fuzz, anisotropy and opacity. Each sphere alone in a white environment
   (isolate). tol: the model's own error from tests/test_openpbr.c's furnace (appear.h SECTION
   openpbr): opaque isotropic 3e-3 of the directional albedo; anisotropy 0.5 up to 5.3% low at
   grazing view; translucent 1e-2 (E_T from two tables, worse near grazing); these bound a
   sphere's mean, which averages over the view angles. Coat and fuzz over a glass lose what they
   reflect back inside (down to 0.874 of the light from inside): expected <= 1. */
typedef struct {
    const char *label;
    int base; /* 0 diffuse, 1 metal, 2 subsurface, 3 metal / diffuse, 4 glass, 5 glass + medium,
                 6 glass / diffuse */
    float rough, aniso, coat, fuzz, opacity, tol;
} pbr_white;
static appear_openpbr_params pbr_white_params(const pbr_white *w)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    p.base_color = p.subsurface_color = appear_spectrum_splat(1.0f); /* colours: white (default) */
    p.specular_roughness = w->rough;
    p.specular_roughness_anisotropy = w->aniso;
    switch (w->base) {
    case 1: p.base_metalness = 1.0f; break;                                /* metal */
    case 2: p.subsurface_weight = 1.0f; break;                             /* subsurface */
    case 3: p.base_metalness = 0.5f; break;                                /* metal / diffuse */
    case 4: p.transmission_weight = 1.0f; break;                           /* glass, depth 0 */
    case 5: /* glass around a white scattering medium: mu_s = 1 / depth, albedo 1 */
        p.transmission_weight = 1.0f;
        p.transmission_depth = 1.0f;
        p.transmission_scatter = appear_spectrum_splat(1.0f);
        p.transmission_scatter_anisotropy = 0.5f;
        break;
    case 6: p.transmission_weight = 0.5f; break;                           /* glass / diffuse */
    default: break;                                                        /* diffuse */
    }
    p.coat_weight = w->coat;
    p.coat_roughness = 0.2f;
    p.fuzz_weight = w->fuzz;
    p.geometry_opacity = w->opacity;
    return p;
}
static void openpbr_furnace(tracer_scene *sc)
{
    /* three rows of five: opaque bases, layers over them, translucent bases */
    static const pbr_white items[] = {
        { "white metal r 0.3", 1, 0.3f, 0.0f, 0.0f, 0.0f, 1.0f, 3e-3f },
        { "white metal r 0.3 aniso 0.5", 1, 0.3f, 0.5f, 0.0f, 0.0f, 1.0f, 0.02f },
        { "white diffuse, specular r 0.3", 0, 0.3f, 0.0f, 0.0f, 0.0f, 1.0f, 3e-3f },
        { "white subsurface", 2, 0.3f, 0.0f, 0.0f, 0.0f, 1.0f, 3e-3f },
        { "metalness 0.5 (metal / diffuse)", 3, 0.3f, 0.0f, 0.0f, 0.0f, 1.0f, 3e-3f },
        { "coat r 0.2 over diffuse", 0, 0.3f, 0.0f, 1.0f, 0.0f, 1.0f, 3e-3f },
        { "fuzz 1 over diffuse", 0, 0.3f, 0.0f, 0.0f, 1.0f, 1.0f, 3e-3f },
        { "coat + fuzz over metal r 0.5", 1, 0.5f, 0.0f, 1.0f, 1.0f, 1.0f, 3e-3f },
        { "coat + fuzz 0.5 over subsurface", 2, 0.3f, 0.0f, 1.0f, 0.5f, 1.0f, 3e-3f },
        { "opacity 0.5, coat over diffuse", 0, 0.3f, 0.0f, 1.0f, 0.0f, 0.5f, 3e-3f },
        { "smooth glass", 4, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 1e-2f },
        { "rough glass r 0.3", 4, 0.3f, 0.0f, 0.0f, 0.0f, 1.0f, 1e-2f },
        { "glass r 0.3, white medium inside", 5, 0.3f, 0.0f, 0.0f, 0.0f, 1.0f, 1e-2f },
        { "transmission 0.5 (glass / diffuse)", 6, 0.3f, 0.0f, 0.0f, 0.0f, 1.0f, 1e-2f },
        { "coat + fuzz over rough glass", 4, 0.3f, 0.0f, 1.0f, 1.0f, 1.0f, 0.0f },
    };
    const int n = (int)(sizeof items / sizeof items[0]);
    int i;
    tracer_scene_init(sc, "openpbr_furnace");
    sc->env_top = sc->env_bottom = appear_spectrum_splat(1.0f);
    for (i = 0; i < n; ++i) {
        appear_openpbr_params p = pbr_white_params(&items[i]);
        int s = tracer_add_openpbr_sphere(sc, grid_pos(i, n, 5, 1.1f, 0.0f), 0.48f, &p);
        /* the glass under coat and fuzz: lossy from inside (expected <= 1) */
        int lossy = items[i].base >= 4 && (items[i].coat > 0.0f || items[i].fuzz > 0.0f);
        if (s < 0) continue;
        sc->shapes[s].tangent_mode = items[i].aniso > 0.0f;
        sc->shapes[s].tol = items[i].tol;
        label(sc, s, items[i].label, lossy ? TRACER_EXPECT_AT_MOST_ONE : TRACER_EXPECT_ONE);
    }
    sc->isolate = 1; /* each sphere faces the furnace alone */
    sc->eye = appear_vec3_make(0, 0, 7.5f);
    sc->look = appear_vec3_make(0, 0, 0);
    sc->fov = 0.5f;
}
#endif

int tracer_scene_build(tracer_scene *sc, const char *name)
{
#if TRACER_HAS_OPENPBR
    if (!strcmp(name, "openpbr")) { openpbr_gallery(sc); return 0; }
    if (!strcmp(name, "openpbr_furnace")) { openpbr_furnace(sc); return 0; }
#endif
#if TRACER_HAS_CTRACKER
    if (!strcmp(name, "chroma")) { chroma(sc); return 0; }
#endif
#if TRACER_HAS_SGGX
    if (!strcmp(name, "fibers")) { fibers(sc); return 0; }
#endif
#if TRACER_HAS_EON && TRACER_HAS_SHEEN
    if (!strcmp(name, "diffuse")) { diffuse(sc); return 0; }
#endif
#if TRACER_HAS_LAYERED
    if (!strcmp(name, "layered")) { layered(sc, 0); return 0; }
    if (!strcmp(name, "layered_ref")) { layered(sc, 1); return 0; }
#endif
#if TRACER_HAS_MATERIALS
    if (!strcmp(name, "metals")) { metals(sc); return 0; }
    if (!strcmp(name, "prism")) { prism(sc); return 0; }
#endif
    if (!strcmp(name, "furnace")) { furnace(sc); return 0; }
    if (!strcmp(name, "gallery")) { gallery(sc); return 0; }
    if (!strcmp(name, "cloud")) { cloud(sc); return 0; }
    return -1;
}
