/* examples/tracer.h - a small volumetric path tracer built on appear.h.

   It exists to render validation images of appear.h's models and to let the
   tests check them numerically. It uses only the public API of appear.h, as
   a renderer would. Deliberately small and plain:

     geometry   spheres, axis-aligned boxes and convex polyhedra (a prism:
                intersections of half-spaces); no acceleration structure, a
                scene has a few dozen shapes at most
     lights     an environment (uniform, or a vertical two-colour gradient)
                reached by BSDF/phase sampling, and spherical area lights
                sampled by next-event estimation (uniform cone sampling)
                combined with BSDF/phase sampling by MIS (power heuristic);
                any other shape of MAT_EMITTER is found by the paths alone
     surfaces   every BSDF of appear.h, through its generic interface
                (appear_bsdf: the tracer names no model; the scenes pick
                them, see the TRACER_HAS_* switches below); the composites
                by reference (appear_coated, appear_layered) are made at
                each shading point from the material (MAT_COATED,
                MAT_LAYERED), and so are the named metals and glasses, at
                the path's wavelengths (MAT_METAL, MAT_GLASS; the dispersive
                dielectric, which the generic interface does not hold,
                through its own functions). A stochastic model
                (APPEAR_MODEL_STOCHASTIC: eval and pdf are noisy estimates)
                is not joined by MIS, which estimated pdfs would bias: at
                its vertices the light is reached by light samples alone
                (weight 1), and a BSDF-sampled path that hits the light
                after a non-delta event of such a model adds nothing (with
                no_nee: BSDF sampling alone, as everywhere). OpenPBR
                (MAT_OPENPBR) by reference too, with its opacity (a
                stochastic cutout), emission and interior medium
     media      inside a shape whose surface is MAT_NONE (an index-matched
                boundary) or transmits (a sampled refraction crosses into
                the medium: an OpenPBR glass's interior): homogeneous (closed-form free flights,
                chromatic sigma_t with appear's spectral MIS), procedural
                heterogeneous "cloud" (delta tracking for free flights,
                ratio tracking for shadow rays, appear's caller-driven
                trackers), and anisotropic SGGX micro-flake media (when the
                header provides SGGX). Phase: any appear_phase.
   Media shapes must not contain or overlap other shapes; the camera is
   outside every shape. Light paths are unbiased apart from the depth cap
   (TRACER_MAX_DEPTH scattering events), which tests take into account.

   Colour, two modes (tracer_options.spectral):
     RGB        the channels of appear_spectrum are linear sRGB (channels
                past the third, in a wider build, repeat blue and are not
                written out)
     spectral   hero-wavelength sampling [Wilkie et al. 2014, Hero
                Wavelength Spectral Sampling, EGSR]: per path one wavelength
                uniform in 360-830 nm (the hero, channel 0) and the others
                at equal spacing after it, rotated into the range; one per
                channel, APPEAR_SPECTRUM_SAMPLES in all. The named metals
                and glasses (MAT_METAL, MAT_GLASS) are made at the path's
                wavelengths; a refraction by a dispersive glass terminates
                the secondary wavelengths (APPEAR_SAMPLE_TERMINATE_SECONDARY,
                pbrt-v4's SampledWavelengths::TerminateSecondary). The hero
                is stratified over a pixel's samples. Radiance goes to XYZ
                by the CIE 1931 observer, then to linear sRGB (D65 white):
                examples/cie_data.h. The scene's other values
                are read as flat spectra, so a spectral scene makes them grey
                (tracer_render refuses lights that are not): a light of
                value L is L times D65, scaled so that a white diffuser under
                it renders RGB (1, 1, 1) (the RGB mode's white).
   TRACER_SPECTRAL (build/trace-spectral: APPEAR_SPECTRUM_SAMPLES 4, the
   width the header suggests for hero wavelengths) makes trace render the
   spectral scenes by default; the RGB build renders them on request, with
   3 wavelengths a path. */
#ifndef APPEAR_TRACER_H
#define APPEAR_TRACER_H
#include "../appear.h"

/* Which optional models the header provides. Each part of appear.h defines
   its own macros; a scene entry that needs a missing part is compiled out. */
#if defined(APPEAR_HAS_WARD)
#define TRACER_HAS_WARD 1
#else
#define TRACER_HAS_WARD 0
#endif
#if defined(APPEAR_HAS_MICROFACET)
#define TRACER_HAS_MICROFACET 1
#else
#define TRACER_HAS_MICROFACET 0
#endif
#if defined(APPEAR_HAS_MEDIA)
#define TRACER_HAS_TRACKERS 1
#else
#define TRACER_HAS_TRACKERS 0
#endif
#if defined(APPEAR_HAS_CTRACKER)
#define TRACER_HAS_CTRACKER 1
#else
#define TRACER_HAS_CTRACKER 0
#endif
#if defined(APPEAR_HAS_FLAKES)
#define TRACER_HAS_SGGX 1
#else
#define TRACER_HAS_SGGX 0
#endif
/* Energy-compensated conductors (albedo scaling) and thin-film conductors:
   the gallery's "multiple scattering on/off" and "iridescent coating"
   spheres and the furnace's compensated entry. */
#if defined(APPEAR_HAS_MULTISCATTER)
#define TRACER_HAS_MULTISCATTER 1
#else
#define TRACER_HAS_MULTISCATTER 0
#endif
#if TRACER_HAS_MICROFACET && defined(APPEAR_HAS_THINFILM)
#define TRACER_HAS_THINFILM 1
#else
#define TRACER_HAS_THINFILM 0
#endif
/* Rough diffuse (EON) and the LTC sheen layered over a base (the "diffuse" scene, the
   furnace's entries) */
#if defined(APPEAR_HAS_EON)
#define TRACER_HAS_EON 1
#else
#define TRACER_HAS_EON 0
#endif
#if defined(APPEAR_HAS_SHEEN)
#define TRACER_HAS_SHEEN 1
#else
#define TRACER_HAS_SHEEN 0
#endif
/* Layered materials (the "layered" scene): appear_coated, the deterministic coat, and
   appear_layered, the reference random walk, whose value the tracer builds at each shading point
   with that point's appear_rng */
#if defined(APPEAR_HAS_LAYERED) && defined(APPEAR_HAS_COATED) && TRACER_HAS_MICROFACET
#define TRACER_HAS_LAYERED 1
#else
#define TRACER_HAS_LAYERED 0
#endif

/* OpenPBR Surface (MAT_OPENPBR: the "openpbr" and "openpbr_furnace" scenes) */
#if defined(APPEAR_HAS_OPENPBR)
#define TRACER_HAS_OPENPBR 1
#else
#define TRACER_HAS_OPENPBR 0
#endif

/* Named metals and glasses (MAT_METAL, MAT_GLASS: the "metals" and "prism" scenes) */
#if defined(APPEAR_HAS_MATERIALS) && TRACER_HAS_MICROFACET
#define TRACER_HAS_MATERIALS 1
#else
#define TRACER_HAS_MATERIALS 0
#endif
#ifndef TRACER_SPECTRAL
#define TRACER_SPECTRAL 0
#endif
/* the wavelength range of spectral mode, nm: the CIE tables' and appear.h's material tables' */
#define TRACER_LAMBDA_MIN 360.0f
#define TRACER_LAMBDA_MAX 830.0f

#define TRACER_MAX_DEPTH 256  /* scattering events per path */
#define TRACER_MAX_SHAPES 48
#define TRACER_MAX_MATERIALS 32
#define TRACER_MAX_MEDIA 8
#define TRACER_MAX_PLANES 8  /* faces of a convex polyhedron */

/* ---- surfaces ---- */
typedef enum {
    MAT_NONE = 0,     /* index-matched boundary of a medium: rays pass */
    MAT_BSDF,         /* any BSDF of appear.h, through its generic interface (appear_bsdf) */
    MAT_EMITTER,      /* black surface with emission (an area light) */
    MAT_COATED,       /* appear_bsdf_coated(&coated): the value refers to the material's copy */
    MAT_LAYERED,      /* appear_layered built from the recipe `layered` at each shading point */
    MAT_METAL,        /* a named metal (APPEAR_METAL_*) over the microfacet d: spectral mode at
                         the path's wavelengths (appear_conductor_make_metal), RGB mode with
                         appear_metal_to_rgb's eta, k or (metal_form) its F82 form */
    MAT_GLASS,        /* a named dielectric (APPEAR_DIELECTRIC_*) over d, in vacuum:
                         appear_dielectric_make_dispersive at the path's wavelengths; RGB mode:
                         its n_d in every channel (no dispersion) */
    MAT_OPENPBR       /* appear_bsdf_openpbr(&openpbr): the value refers to the material's copy;
                         geometry_opacity: a hit passes as a MAT_NONE boundary with probability
                         1 - opacity (shadow rays: transmittance times 1 - opacity); emission:
                         appear_openpbr_emission, found by the paths alone (no NEE); a translucent
                         base's interior medium: the shape's medium (tracer_add_openpbr_sphere) */
} tracer_mat_kind;
/* MAT_METAL in RGB mode: appear_conductor_make(d, eta, k) or appear_conductor_make_f82(d, f0,
   f82_tint), from appear_metal_to_rgb */
enum { TRACER_METAL_ETA_K = 0, TRACER_METAL_F82 };

#if TRACER_HAS_LAYERED
/* The top interface of a layered recipe: appear_bsdf_dielectric, _comp, or _ms (the random walk,
   drawing from the shading point's appear_rng) */
enum { TRACER_TOP_SINGLE = 0, TRACER_TOP_COMP, TRACER_TOP_MS };
/* The reference random walk (appear_layered) as a recipe. appear_layered holds copies of its two
   parts; a stochastic part (the _ms top) points to an appear_rng, as the walk's generic value
   does, and an rng must not be shared between threads: so the scene stores this recipe and the
   tracer makes the appear_layered at each shading point, on its stack, with an appear_rng seeded
   there from the path's generator (tracer_layered_make). */
typedef struct tracer_layered {
    appear_dielectric coat; /* the top interface */
    int top;                /* TRACER_TOP_* */
    appear_bsdf base;       /* a value that refers to nothing (no composite, no rng) */
    appear_slab slab;       /* between them (appear_slab_none, appear_slab_from_transmittance) */
    int samples, max_depth; /* appear_layered_make's */
} tracer_layered;
/* The appear_layered of the recipe, drawing from *rng (which it and its value refer to). */
appear_layered tracer_layered_make(const tracer_layered *l, appear_rng *rng);
#endif

typedef struct tracer_material {
    int kind;
    appear_bsdf bsdf;         /* MAT_BSDF: appear_bsdf_lambert(...), appear_bsdf_conductor(...) */
    appear_spectrum emission; /* MAT_EMITTER */
#if TRACER_HAS_MATERIALS
    appear_microfacet d;      /* MAT_METAL, MAT_GLASS */
    int named;                /* MAT_METAL: APPEAR_METAL_*; MAT_GLASS: APPEAR_DIELECTRIC_* */
    int metal_form;           /* MAT_METAL in RGB mode: TRACER_METAL_* */
#endif
#if TRACER_HAS_LAYERED
    appear_coated coated;     /* MAT_COATED (copied with the scene: the value is made per hit) */
    tracer_layered layered;   /* MAT_LAYERED */
#endif
#if TRACER_HAS_OPENPBR
    /* MAT_OPENPBR (copied with the scene: the value is made per hit); its emission toward the
       normal is in `emission` (nonzero: the tracer adds appear_openpbr_emission at each hit) */
    appear_openpbr openpbr;
#endif
#if TRACER_HAS_SHEEN
    /* MAT_BSDF with has_sheen: the LTC sheen over bsdf (a base with a density lobe),
       f = f_sheen + appear_sheen_base_weight(sheen_mode) f_base; one-sample mixture sampling */
    int has_sheen, sheen_mode;
    appear_sheen sheen;
#endif
} tracer_material;

/* ---- media ---- */
typedef enum {
    MED_HOMOGENEOUS = 0,  /* sigma_t (chromatic), albedo */
    MED_CLOUD,            /* sigma_t(x) = sigma_max * cloud density in [0,1], albedo */
    MED_SGGX,             /* sigma_t(x, w) = density * sigma_sggx(w), albedo (needs SGGX) */
    MED_CLOUD_CHROMATIC   /* sigma_t(x) = sigma_t (spectrum) * cloud density, albedo (spectrum);
                             appear_ctracker: spectral-MIS delta tracking with the path's hero,
                             chromatic ratio tracking for shadow rays (needs the ctracker) */
} tracer_med_kind;
typedef struct tracer_medium {
    int kind;
    appear_phase phase;       /* any phase function of appear.h (appear_phase_hg(...), ...) */
    appear_spectrum sigma_t;  /* MED_HOMOGENEOUS; MED_CLOUD_CHROMATIC: peak extinction (majorant) */
    float sigma_max;          /* MED_CLOUD: majorant = peak extinction; MED_SGGX: density */
    appear_spectrum albedo;   /* single-scattering albedo sigma_s / sigma_t */
    appear_vec3 lo, hi;       /* MED_CLOUD: box the noise is laid out in */
#if TRACER_HAS_SGGX
    appear_sggx sggx;         /* MED_SGGX: flake distribution (its projected area) */
#endif
} tracer_medium;

/* ---- shapes ---- */
/* SHAPE_CONVEX: the intersection of half-spaces n . x <= c (a prism, a wedge) */
typedef enum { SHAPE_SPHERE = 0, SHAPE_BOX, SHAPE_CONVEX } tracer_shape_kind;
enum { TRACER_EXPECT_NONE = 0, TRACER_EXPECT_ONE, TRACER_EXPECT_AT_MOST_ONE };
typedef struct tracer_shape {
    int kind;
    appear_vec3 c; float r;      /* sphere */
    appear_vec3 lo, hi;          /* box */
    float plane[TRACER_MAX_PLANES][4]; int n_planes; /* convex: (n unit, c), n . x <= c */
    int material;                /* index into scene.mats */
    int medium;                  /* index into scene.media, -1 = none; the surface: MAT_NONE,
                                    or one that transmits (a sampled transmission crosses into
                                    or out of the medium, as a MAT_NONE crossing does) */
    int tangent_mode;            /* 0: frame from the normal; 1: tangent around the y axis */
    int expect;                  /* furnace expectation: TRACER_EXPECT_* */
    float tol;                   /* furnace: the model's own error allowed beyond the noise
                                    (|mean - 1| <= 4 SE + tol; 0 for an exact model) */
    const char *label;           /* for reports */
} tracer_shape;

typedef struct tracer_scene {
    const char *name;
    tracer_shape shapes[TRACER_MAX_SHAPES]; int n_shapes;
    tracer_material mats[TRACER_MAX_MATERIALS]; int n_mats;
    tracer_medium media[TRACER_MAX_MEDIA]; int n_media;
    appear_spectrum env_top, env_bottom;  /* environment radiance, lerp by direction y */
    appear_vec3 eye, look, up; float fov; /* pinhole camera, vertical fov in radians */
    int light;                            /* shape index of the NEE light (emissive sphere), -1 none */
    int isolate;                          /* 1: each object sees only itself and the environment
                                             (furnace: no inter-reflection between objects) */
} tracer_scene;

/* Scene building helpers (return the new index). */
void tracer_scene_init(tracer_scene *sc, const char *name);
int  tracer_add_material(tracer_scene *sc, tracer_material m);
int  tracer_add_medium(tracer_scene *sc, tracer_medium m);
int  tracer_add_sphere(tracer_scene *sc, appear_vec3 c, float r, int material, int medium);
int  tracer_add_box(tracer_scene *sc, appear_vec3 lo, appear_vec3 hi, int material, int medium);
/* A convex polyhedron: the points x with n . x <= c for each plane (n, c) of planes[0 .. n - 1]
   (n need not be unit: it is normalised here; the planes must bound a finite solid). Returns -1
   for n outside 1 .. TRACER_MAX_PLANES. */
int  tracer_add_convex(tracer_scene *sc, const float (*planes)[4], int n, int material,
                       int medium);
/* An emissive sphere, also registered as the scene's NEE light. */
int  tracer_add_sphere_light(tracer_scene *sc, appear_vec3 c, float r, appear_spectrum radiance);
tracer_material tracer_mat_bsdf(appear_bsdf bsdf);
tracer_material tracer_mat_lambert(appear_spectrum albedo);
tracer_material tracer_mat_none(void);
#if TRACER_HAS_MATERIALS
tracer_material tracer_mat_metal(appear_microfacet d, int metal);       /* APPEAR_METAL_* */
tracer_material tracer_mat_glass(appear_microfacet d, int dielectric);  /* APPEAR_DIELECTRIC_* */
#endif
#if TRACER_HAS_LAYERED
tracer_material tracer_mat_coated(appear_coated c);
tracer_material tracer_mat_layered(tracer_layered l);
#endif
#if TRACER_HAS_OPENPBR
/* appear_openpbr_make(p) as a material (an invalid model: flags 0, which tests catch) */
tracer_material tracer_mat_openpbr(const appear_openpbr_params *p);
/* A sphere of the OpenPBR material p; a translucent base with transmission_depth > 0 gets its
   interior medium (appear_openpbr_medium: homogeneous sigma_t and albedo, HG g) inside. Returns
   the shape index, -1 when the scene is full. */
int tracer_add_openpbr_sphere(tracer_scene *sc, appear_vec3 c, float r,
                              const appear_openpbr_params *p);
#endif
#if TRACER_HAS_SHEEN
/* sheen over base (mode APPEAR_SHEEN_LAYER_ALBEDO or _RECIPROCAL) */
tracer_material tracer_mat_sheen_over(appear_sheen sheen, appear_bsdf base, int mode);
#endif

/* The procedural cloud density in [0, 1] at a point (box-relative fBm with
   a soft falloff to the box faces); exposed for tests. */
float tracer_cloud_density(const tracer_medium *m, appear_vec3 p);

/* ---- the demo scenes (examples/scenes.c) ---- */
/* Builds the named scene; returns 0, or -1 for an unknown name or a scene
   whose models appear.h does not provide. names: NULL-terminated list;
   "layered_ref", the reference twin of "layered", builds too (unlisted:
   trace renders it with "layered"). */
int tracer_scene_build(tracer_scene *sc, const char *name);
extern const char *const tracer_scene_names[];
/* a short statement of what the scene must show */
const char *tracer_scene_expectation(const char *name);
/* 1: the scene is made for spectral mode (named metals and glasses, grey otherwise) */
int tracer_scene_is_spectral(const char *name);

/* ---- rendering ---- */
typedef struct tracer_image {
    int w, h;
    float *rgb;   /* w*h*3, mean radiance per pixel */
    float *var;   /* w*h*3, per pixel and channel the variance of ONE sample (unbiased estimate) */
    int   *id;    /* w*h, shape index hit by the ray through the pixel centre, -1 = environment */
    long  nonfinite; /* samples that came out NaN or Inf (dropped, counted): must be 0 */
    double seconds;  /* render wall time */
} tracer_image;

typedef struct tracer_options {
    int w, h, spp, threads;
    unsigned long long seed;
    int progress;        /* 1: progress bar with time estimate on stderr (when a tty) */
    int no_nee;          /* 1: no next-event estimation (lights found by BSDF/phase sampling only) */
    int pixel_centre;    /* 1: every sample through the pixel centre (no anti-aliasing; for tests) */
    int spectral;        /* 1: spectral mode (see the top); 0: RGB (needs 3 channels or more) */
} tracer_options;

/* Renders sc into img (allocated here; free with tracer_image_free).
   Returns 0 on success; -1 for bad options, or spectral mode with a light or environment that
   is not grey. */
int  tracer_render(const tracer_scene *sc, const tracer_options *opt, tracer_image *img);
void tracer_image_free(tracer_image *img);

/* Spectral mode's colour at lambda_nm (clamped to 360-830): *illum, the lights' relative
   spectrum (D65 over its luminance integral, so that a white diffuser renders Y = 1), and
   rgb_bar[3], the linear sRGB matching functions (CIE 1931 xbar, ybar, zbar through the XYZ to
   linear sRGB matrix): a path's pixel value is (830 - 360) / n sum_j L_j illum_j rgb_bar_j over
   its n wavelengths. A flat spectrum of 1 maps to (1, 1, 1) in expectation; for tests. */
void tracer_spectral_colour(float lambda_nm, float *illum, float rgb_bar[3]);

/* Writes DIR/NAME.exr (R, G, B, and "var", the per-sample variance
   averaged over the channels) and
   DIR/NAME.png (sRGB preview at the given exposure). Returns 0 on success. */
int  tracer_write(const tracer_image *img, const char *dir, const char *name, float exposure);

#endif
