/* examples/appear_check.c - build/appear-check: check and time any model of
   appear.h from the command line.

     appear-check SUBCOMMAND MODEL [--option value]...
     appear-check transmittance [--kind K] [--profile P] [--tightness T]...
     appear-check --help | appear-check SUBCOMMAND [MODEL] --help
     appear-check --version

   Subcommands: furnace, reciprocity, chi2, consistency, lobe, bench,
   transmittance. Every check runs through tests/check.h (the same interface
   a renderer can use on its own materials). Bad input prints one line
   naming the option and exits 2. --version (also the last line of --help,
   and bench's header and CSV column) names the compiler and the flags the
   program was built with: the Makefile builds it with the flags the README
   recommends for renderers (-O3 -march=native -fno-math-errno), so bench's
   batch rows show the vectorised figure, and passes them as
   APPEAR_CHECK_CFLAGS. */
#define _POSIX_C_SOURCE 200809L
#include "../appear.h"
#include "../tests/adapters.h"
/* check.h's code is compiled here, in the program; the test binary that includes this file
   (tests/test_check.c, with APPEAR_CHECK_NO_MAIN) has it from tests/harness.c */
#ifndef APPEAR_CHECK_NO_MAIN
#define CHECK_IMPLEMENTATION
#endif
#include "../tests/check.h"
#include "image_io.h"
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>

#if defined(__GNUC__)
#define AC_NOINLINE __attribute__((noinline))
#else
#define AC_NOINLINE
#endif

/* The build, printed by --version, --help and bench: the flags come from the Makefile
   (-DAPPEAR_CHECK_CFLAGS='"cc -std=c99 -O3 ..."'), the compiler's version from itself. */
#ifndef APPEAR_CHECK_CFLAGS
#define APPEAR_CHECK_CFLAGS "unknown flags (not built by the Makefile)"
#endif
#if defined(__clang__) && defined(__VERSION__)
#define AC_COMPILER __VERSION__
#elif defined(__GNUC__) && defined(__VERSION__)
#define AC_COMPILER "gcc " __VERSION__
#else
#define AC_COMPILER "unknown compiler"
#endif
static const char ac_build[] = APPEAR_CHECK_CFLAGS " (" AC_COMPILER ")";

/* ------------------------------------------------------------------------ */
/* Subcommands, models, options                                              */
/* ------------------------------------------------------------------------ */

enum { C_FURNACE, C_RECIPROCITY, C_CHI2, C_CONSISTENCY, C_LOBE, C_BENCH, C_TRANSMITTANCE, C_COUNT };
static const char *const ac_cmd_name[C_COUNT] = { "furnace", "reciprocity", "chi2", "consistency", "lobe", "bench", "transmittance" };
static const char *const ac_cmd_help[C_COUNT] = {
    "albedo per incident angle (mean sample weight, transmission as energy R + e^2 T) with its standard error and the energy lost",
    "max relative violation of f(wo,wi) = f(wi,wo) (refraction: n_i^2 f(wo,wi) = n_o^2 f(wi,wo); flakes: sigma-weighted)",
    "chi-square of sample() against pdf() on equal-area bins: statistic, dof, p; --exr/--png write the histograms",
    "sample() against eval()/pdf() at the sampled directions: max relative differences",
    "picture of the lobe f|cos| (BSDF: reflection and transmission disks; phase: lat-long), --png/--exr, in-plane slice",
    "ns per call: throughput loop, latency chain (noinline, input from the previous output), batch entry points",
    "heterogeneous-media trackers on a 1D test profile: mean, variance, lookups, efficiency vs ratio tracking, exact T; free flight" };

/* the models: tests/adapters.h's registry (AD_FAMILIES), in its order: ac_models[AD_WARD].name
   is "ward"; .bsdf, .opts (the model's options, space-separated) and .help */
#define ac_models (ad_families())

/* option flags: which subcommands use it (bit per C_*), or a model option */
#define CM(c) (1u << (c))
#define C_BSDFCMDS (CM(C_FURNACE) | CM(C_RECIPROCITY) | CM(C_CHI2) | CM(C_CONSISTENCY) | CM(C_LOBE) | CM(C_BENCH))
#define C_ALL (C_BSDFCMDS | CM(C_TRANSMITTANCE))
typedef struct { const char *name; int flag; const char *def; const char *help; unsigned cmds; int model; } ac_opt;
enum {
    O_THETA, O_PHI, O_SAMPLES, O_SEED, O_CSV, O_PLOT, O_PNG, O_EXR, O_CAP, O_BINS, O_AXIS, O_SIZE, O_REPEATS, O_FLOOR, O_TOL,
    O_DIST, O_ALPHA, O_SAMPLING, O_ETA, O_K, O_ALBEDO, O_VARIANT, O_RHO_D, O_RHO_S, O_G, O_G1, O_G2,
    O_W, O_DIAMETER, O_TABLE,
    O_FILM_ETA, O_THICKNESS, O_SHAPE, O_P, O_TILT,
    O_F0, O_KIND, O_PROFILE, O_TIGHTNESS, O_SEGMENTS, O_CHROMATIC, O_CHANNELS, O_MAJORANT,
    O_FREE_FLIGHT, O_SIGMA, O_LENGTH, O_ROUGH_SIGMA, O_EON_SAMPLING, O_HELP, O_COUNT
};
static const ac_opt ac_opts[O_COUNT] = {
    { "theta", 0, "furnace 0,30,60,75,85,89; others 45", "incident angles of wo from +z in degrees (list: a,b,c)", C_BSDFCMDS, 0 },
    { "phi", 0, "0", "azimuth of wo in degrees", C_BSDFCMDS, 0 },
    { "samples", 0, "furnace 100000, reciprocity 20000 pairs, chi2 200000, consistency 20000, bench 1000000, transmittance 20000",
      "samples per angle / pairs / estimates", C_ALL & ~CM(C_LOBE), 0 },
    { "seed", 0, "1", "random seed", C_ALL, 0 },
    { "csv", 1, "off", "print CSV instead of the table", C_ALL, 0 },
    { "plot", 0, "none", "draw the curve into FILE.png with gnuplot (skipped with a note when gnuplot is missing)", CM(C_FURNACE) | CM(C_LOBE) | CM(C_TRANSMITTANCE), 0 },
    { "png", 0, "none", "chi2: observed | expected | residual histograms; lobe: the picture (PNG)", CM(C_CHI2) | CM(C_LOBE), 0 },
    { "exr", 0, "none", "same as --png as float EXR (chi2 channels obs, exp, res; lobe Y = f|cos|)", CM(C_CHI2) | CM(C_LOBE), 0 },
    { "cap", 0, "-1 (whole sphere)", "chi2: bins cover cos(angle to axis) in [CAP, 1] (resolves narrow lobes)", CM(C_CHI2), 0 },
    { "bins", 0, "32,64 (sggx-diffuse: 16,32)", "chi2: bins in cos theta, phi", CM(C_CHI2), 0 },
    { "axis", 0, "auto (BSDF: the mirror direction of wo; phase: -wo)", "chi2: pole of the bins, x,y,z", CM(C_CHI2), 0 },
    { "size", 0, "128", "lobe: disk / lat-long height in pixels", CM(C_LOBE), 0 },
    { "repeats", 0, "64", "reciprocity: eval calls averaged per side for stochastic evals (random walks)", CM(C_RECIPROCITY), 0 },
    { "floor", 0, "1e-4", "reciprocity: pairs with both values below are not compared", CM(C_RECIPROCITY), 0 },
    { "tol", 0, "1e-3", "consistency: relative tolerance", CM(C_CONSISTENCY), 0 },
    { "dist", 0, "ggx", "microfacet distribution: ggx | beckmann", C_BSDFCMDS, 1 },
    { "alpha", 0, "0.3 (draine: 1)", "roughness a[,ay] in [0, 100] (sggx: [0, 1]; sheen: r in (0, 1]); draine: its alpha >= -1", C_BSDFCMDS, 1 },
    { "sampling", 0, "visible", "visible | bounded (ggx reflection) | full (D cos)", C_BSDFCMDS, 1 },
    { "eta", 0, "1.5 (conductors: 0.2)", "dielectric, layered coat: n_inside/n_outside in [1e-4, 1e4] (coated: [1, 3]); conductor / film base: real IOR in [0, 1e6]", C_BSDFCMDS, 1 },
    { "k", 0, "3.9", "conductor / film base: extinction coefficient in [0, 1e6] (eta 0 k 0 gives F = 1)", C_BSDFCMDS, 1 },
    { "albedo", 0, "0.8", "lambert: reflectance in [0, 1]; eon: rho; sheen: its colour; layered: the Lambert base's", C_BSDFCMDS, 1 },
    { "variant", 0, "original", "ward: original | duer | balanced", C_BSDFCMDS, 1 },
    { "rho-d", 0, "0.2", "ward: diffuse reflectance", C_BSDFCMDS, 1 },
    { "rho-s", 0, "0.5", "ward: specular reflectance (rho-d + rho-s <= 1)", C_BSDFCMDS, 1 },
    { "g", 0, "0.5", "hg, draine: mean cosine in [-1, 1] (> 0 forward: wi ~ -wo)", C_BSDFCMDS, 1 },
    { "g1", 0, "0.8", "dhg: first lobe", C_BSDFCMDS, 1 },
    { "g2", 0, "-0.3", "dhg: second lobe", C_BSDFCMDS, 1 },
    { "w", 0, "0.7", "dhg: weight of the first lobe in [0, 1]", C_BSDFCMDS, 1 },
    { "diameter", 0, "10", "mie: droplet diameter in micrometres, [0, 50]", C_BSDFCMDS, 1 },
    { "table", 0, "none", "table: text file, '#' comments; lines 'mu p' (mu = cos theta = -wo.wi from -1 to 1, "
      "increasing) or one value p per line (uniform nodes from mu = -1 to 1); at most 256 rows; any scale", C_BSDFCMDS, 1 },
    { "film-eta", 0, "1.33", "thinfilm-conductor: film index in (0, 1e3]", C_BSDFCMDS, 1 },
    { "thickness", 0, "400", "thinfilm-conductor: film thickness in nm, [0, 1e5]", C_BSDFCMDS, 1 },
    { "shape", 0, "surface", "sggx: surface (normals about the axis) | fiber (normals orthogonal to the axis)", C_BSDFCMDS, 1 },
    { "p", 0, "10", "fiber: exponent of |sin theta_m|^p, [0, 1024]", C_BSDFCMDS, 1 },
    { "tilt", 0, "0 (fiber: 90)", "sggx, fiber: angle of the flake axis from +z toward +x, degrees", C_BSDFCMDS, 1 },
    { "f0", 0, "0.9", "conductor-f0 (or conductor, -comp, -ms instead of eta, k): constant Fresnel "
      "F0 in [0, 1], R or R,G,B (appear_conductor_make_reflectance)", C_BSDFCMDS, 1 },
    { "kind", 0, "all", "delta | ratio (= track-length) | next-flight | residual | urm | "
      "power-series | "
      "ray-march | spectral (--chromatic only) | all (--chromatic: delta, ratio, next-flight, "
      "spectral)", CM(C_TRANSMITTANCE), 0 },
    { "profile", 0, "bump", "constant | cosine | bump | hole | ramp-up | ramp-down (Georgiev et al. 2019, on [0, 1])", CM(C_TRANSMITTANCE), 0 },
    { "tightness", 0, "1", "majorant max/T, minorant min*T, T in (0, 1] (1 = exact bounds)", CM(C_TRANSMITTANCE), 0 },
    { "segments", 0, "1", "piecewise-constant majorant segments, [1, 64]", CM(C_TRANSMITTANCE), 0 },
    { "chromatic", 1, "off",
      "chromatic trackers (appear_ctracker) on channel densities k_i x profile",
      CM(C_TRANSMITTANCE), 0 },
    { "channels", 0, "0.1,1,10", "--chromatic: k_i per channel, 3 values in [0, 1e4]",
      CM(C_TRANSMITTANCE), 0 },
    { "majorant", 0, "common", "--chromatic: common (max over the channels) | per-channel",
      CM(C_TRANSMITTANCE), 0 },
    { "free-flight", 1, "off", "homogeneous single-channel free flight appear_homogeneous_sample1 "
      "(--sigma, --length) vs closed forms, ns vs appear_homogeneous_sample",
      CM(C_TRANSMITTANCE), 0 },
    { "sigma-t", 0, "1", "--free-flight: extinction sigma_t in [1e-6, 1e6]", CM(C_TRANSMITTANCE), 0 },
    { "length", 0, "1", "--free-flight: length d of the ray segment [0, d] the flight crosses, "
      "in [1e-6, 1e6]", CM(C_TRANSMITTANCE), 0 },
    { "sigma", 0, "0.5", "eon: roughness in [0, 1] (0: Lambert)", C_BSDFCMDS, 1 },
    { "eon-sampling", 0, "cltc", "eon: cltc (the paper's mixture) | cosine", C_BSDFCMDS, 1 },
    { "help", 1, "", "this help", C_ALL, 0 } };

typedef struct {
    int cmd, model;
    const char *val[O_COUNT]; /* NULL = default */
    int set[O_COUNT];
    /* parsed */
    double theta[32]; int n_theta;
    double phi, alpha[2], eta, k, albedo, rho_d, rho_s, g, g1, g2, w, diameter, film_eta, thickness;
    double p, tilt;
    double cap, axis[3], floor_, tol, tightness, f0[3], channels[3], sigma, length, rough_sigma;
    int has_f0, chromatic, per_channel, free_flight;
    int eon_sampling;
    int dist, sampling, variant, shape, n_z, n_phi, size, repeats, kind, profile, segments, csv, has_axis;
    long samples;
    unsigned long seed;
} ac_config;

/* ------------------------------------------------------------------------ */
/* Parsing                                                                   */
/* ------------------------------------------------------------------------ */

static int ac_err(char *err, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, n, fmt, ap);
    va_end(ap);
    return 2;
}
static int ac_number(const char *s, double *v)
{
    char *end;
    if (!s || !*s) return 0;
    errno = 0;
    *v = strtod(s, &end);
    return *end == 0 && errno == 0 && isfinite(*v);
}
static int ac_list(const char *s, double *v, int max)
{   /* comma-separated numbers; returns the count, 0 on error */
    char buf[512], *tok, *save = 0;
    int n = 0;
    if (!s || strlen(s) >= sizeof buf) return 0;
    strcpy(buf, s);
    for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(0, ",", &save)) {
        if (n >= max || !ac_number(tok, &v[n])) return 0;
        ++n;
    }
    return n;
}
static int ac_choice(const char *s, const char *const *names, int n)
{
    int i;
    for (i = 0; i < n; ++i) if (!strcmp(s, names[i])) return i;
    return -1;
}
static const char *const ac_dist_names[] = { "ggx", "beckmann" };
static const char *const ac_sampling_names[] = { "visible", "bounded", "full" };
static const char *const ac_variant_names[] = { "original", "duer", "balanced" };
static const char *const ac_shape_names[] = { "surface", "fiber" };
static const char *const ac_kind_names[] = { "delta", "ratio", "next-flight", "residual", "urm", "power-series", "ray-march", "all",
                                             "track-length",
                                             "spectral" };
static const char *const ac_profile_names[] = { "constant", "cosine", "bump", "hole", "ramp-up", "ramp-down" };

static int ac_model_uses(int model, const char *opt)
{
    const char *s = ac_models[model].opts;
    size_t n = strlen(opt);
    while ((s = strstr(s, opt)) != NULL) {
        if ((s == ac_models[model].opts || s[-1] == ' ') && (s[n] == 0 || s[n] == ' ')) return 1;
        s += n;
    }
    return 0;
}

/* number option with a default and a range check */
static int ac_num_opt(ac_config *c, int o, double def, double lo, double hi, double *out, char *err, size_t en)
{
    if (!c->val[o]) { *out = def; return 0; }
    if (!ac_number(c->val[o], out)) return ac_err(err, en, "option --%s: '%s' is not a number", ac_opts[o].name, c->val[o]);
    if (!(*out >= lo && *out <= hi)) return ac_err(err, en, "option --%s: %s is out of range [%g, %g]", ac_opts[o].name, c->val[o], lo, hi);
    return 0;
}
static int ac_int_opt(ac_config *c, int o, long def, long lo, long hi, long *out, char *err, size_t en)
{
    char *end;
    if (!c->val[o]) { *out = def; return 0; }
    errno = 0;
    *out = strtol(c->val[o], &end, 10);
    if (!*c->val[o] || *end || errno) return ac_err(err, en, "option --%s: '%s' is not an integer", ac_opts[o].name, c->val[o]);
    if (*out < lo || *out > hi) return ac_err(err, en, "option --%s: %s is out of range [%ld, %ld]", ac_opts[o].name, c->val[o], lo, hi);
    return 0;
}
static int ac_choice_opt(ac_config *c, int o, const char *const *names, int n, int def, int *out, char *err, size_t en)
{
    if (!c->val[o]) { *out = def; return 0; }
    *out = ac_choice(c->val[o], names, n);
    if (*out < 0) return ac_err(err, en, "option --%s: unknown value '%s'", ac_opts[o].name, c->val[o]);
    return 0;
}

/* Parses argv into c. Returns 0 (run), 1 (help was requested: c->cmd / c->model
   say for what; -1 when unknown), 2 (error: err holds one line naming the
   option). Prints nothing. */
static int ac_parse(int argc, char **argv, ac_config *c, char *err, size_t en)
{
    int i = 1, o, r;
    long l;
    memset(c, 0, sizeof *c);
    c->cmd = c->model = -1;
    if (argc < 2) return ac_err(err, en, "missing subcommand (furnace, reciprocity, chi2, consistency, lobe, bench, transmittance); try --help");
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) return 1;
    c->cmd = ac_choice(argv[1], ac_cmd_name, C_COUNT);
    if (c->cmd < 0) return ac_err(err, en, "unknown subcommand '%s' (furnace, reciprocity, chi2, consistency, lobe, bench, transmittance)", argv[1]);
    i = 2;
    if (c->cmd != C_TRANSMITTANCE) {
        if (i >= argc || argv[i][0] == '-') {
            if (i < argc && (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h"))) return 1;
            return ac_err(err, en, "%s: missing model (one of lambert, ward, conductor, ..., see --help)", ac_cmd_name[c->cmd]);
        }
        for (c->model = 0; c->model < AD_COUNT; ++c->model) if (!strcmp(argv[i], ac_models[c->model].name)) break;
        if (c->model == AD_COUNT) { c->model = -1; return ac_err(err, en, "unknown model '%s' (see appear-check --help)", argv[i]); }
        ++i;
    }
    for (; i < argc; ++i) {
        const char *a = argv[i];
        if (!strcmp(a, "-h")) a = "--help";
        if (strncmp(a, "--", 2)) return ac_err(err, en, "unexpected argument '%s' (options start with --)", a);
        for (o = 0; o < O_COUNT; ++o)
            if (!strcmp(a + 2, ac_opts[o].name) && (ac_opts[o].cmds & CM(c->cmd))) break;
        if (o == O_COUNT && !strcmp(a, "--sigma") && c->cmd == C_TRANSMITTANCE) /* until 2026-12 */
            return ac_err(err, en, "unknown option '--sigma' for transmittance (now --sigma-t; "
                          "--sigma is EON's roughness)");
        if (o == O_COUNT && !strcmp(a, "--d")) /* one name had two meanings until 2026-12 */
            return ac_err(err, en, "unknown option '--d' for %s (now --diameter for mie, --length "
                          "for transmittance --free-flight)", ac_cmd_name[c->cmd]);
        if (o == O_COUNT || !(ac_opts[o].cmds & CM(c->cmd))) return ac_err(err, en, "unknown option '%s' for %s", a, ac_cmd_name[c->cmd]);
        if (o == O_HELP) return 1;
        if (ac_opts[o].model && !ac_model_uses(c->model, ac_opts[o].name))
            return ac_err(err, en, "option --%s does not apply to model %s (its options: %s)", ac_opts[o].name, ac_models[c->model].name,
                          *ac_models[c->model].opts ? ac_models[c->model].opts : "none");
        c->set[o] = 1;
        if (ac_opts[o].flag) { c->val[o] = "1"; continue; }
        if (i + 1 >= argc) return ac_err(err, en, "option --%s: missing value", ac_opts[o].name);
        c->val[o] = argv[++i];
    }
    /* common */
    c->csv = c->set[O_CSV];
    if (c->val[O_THETA]) {
        c->n_theta = ac_list(c->val[O_THETA], c->theta, 32);
        if (!c->n_theta) return ac_err(err, en, "option --theta: '%s' is not a list of numbers", c->val[O_THETA]);
        for (o = 0; o < c->n_theta; ++o)
            if (!(c->theta[o] >= 0 && c->theta[o] <= 180)) return ac_err(err, en, "option --theta: %g is out of range [0, 180]", c->theta[o]);
    } else if (c->cmd == C_FURNACE) {
        static const double t[6] = { 0, 30, 60, 75, 85, 89 };
        memcpy(c->theta, t, sizeof t); c->n_theta = 6;
    } else { c->theta[0] = 45; c->n_theta = 1; }
    if ((r = ac_num_opt(c, O_PHI, 0, -360, 360, &c->phi, err, en))) return r;
    {
        static const long defn[C_COUNT] = { 100000, 20000, 200000, 20000, 0, 1000000, 20000 };
        if ((r = ac_int_opt(c, O_SAMPLES, defn[c->cmd], 1, 1000000000L, &c->samples, err, en))) return r;
    }
    if ((r = ac_int_opt(c, O_SEED, 1, 0, 2147483647L, &l, err, en))) return r;
    c->seed = (unsigned long)l;
    if ((r = ac_num_opt(c, O_CAP, -1, -1, 0.999, &c->cap, err, en))) return r;
    if (c->val[O_BINS]) {
        double b[2];
        if (ac_list(c->val[O_BINS], b, 2) != 2 || b[0] < 1 || b[1] < 1 || b[0] > 1024 || b[1] > 1024 || b[0] != floor(b[0]) || b[1] != floor(b[1]))
            return ac_err(err, en, "option --bins: '%s' is not NZ,NPHI (integers in [1, 1024])", c->val[O_BINS]);
        c->n_z = (int)b[0]; c->n_phi = (int)b[1];
    } else if (c->model == AD_SGGX_DIFFUSE) { c->n_z = 16; c->n_phi = 32; } /* its pdf costs 256 evals */
    else { c->n_z = 32; c->n_phi = 64; }
    if (c->val[O_AXIS]) {
        double len;
        if (ac_list(c->val[O_AXIS], c->axis, 3) != 3) return ac_err(err, en, "option --axis: '%s' is not x,y,z", c->val[O_AXIS]);
        len = sqrt(c->axis[0] * c->axis[0] + c->axis[1] * c->axis[1] + c->axis[2] * c->axis[2]);
        if (!(len > 0)) return ac_err(err, en, "option --axis: zero vector");
        c->has_axis = 1;
    }
    if ((r = ac_int_opt(c, O_SIZE, 128, 8, 4096, &l, err, en))) return r;
    c->size = (int)l;
    if ((r = ac_int_opt(c, O_REPEATS, 64, 1, 100000, &l, err, en))) return r;
    c->repeats = (int)l;
    if ((r = ac_num_opt(c, O_FLOOR, 1e-4, 0, 1e30, &c->floor_, err, en))) return r;
    if ((r = ac_num_opt(c, O_TOL, 1e-3, 0, 1, &c->tol, err, en))) return r;
    if ((r = ac_choice_opt(c, O_KIND, ac_kind_names, 10, 7, &c->kind, err, en))) return r;
    if (c->kind == 8) c->kind = APPEAR_TRACK_RATIO;
    if ((r = ac_choice_opt(c, O_PROFILE, ac_profile_names, 6, 2, &c->profile, err, en))) return r;
    if ((r = ac_num_opt(c, O_TIGHTNESS, 1, 1e-6, 1, &c->tightness, err, en))) return r;
    if ((r = ac_int_opt(c, O_SEGMENTS, 1, 1, 64, &l, err, en))) return r;
    c->segments = (int)l;
    c->chromatic = c->set[O_CHROMATIC];
    c->free_flight = c->set[O_FREE_FLIGHT];
    c->channels[0] = 0.1; c->channels[1] = 1; c->channels[2] = 10;
    if (c->val[O_CHANNELS]) {
        if (ac_list(c->val[O_CHANNELS], c->channels, 3) != 3)
            return ac_err(err, en, "option --channels: '%s' is not k0,k1,k2", c->val[O_CHANNELS]);
        for (o = 0; o < 3; ++o)
            if (!(c->channels[o] >= 0 && c->channels[o] <= 1e4))
                return ac_err(err, en, "option --channels: %g is out of range [0, 1e4]",
                              c->channels[o]);
    }
    {
        static const char *const mn[] = { "common", "per-channel" };
        if ((r = ac_choice_opt(c, O_MAJORANT, mn, 2, 0, &c->per_channel, err, en))) return r;
    }
    if ((r = ac_num_opt(c, O_SIGMA, 1, 1e-6, 1e6, &c->sigma, err, en))) return r;
    if ((r = ac_num_opt(c, O_LENGTH, 1, 1e-6, 1e6, &c->length, err, en))) return r;
    if (c->cmd == C_TRANSMITTANCE) {
        if (c->chromatic && c->free_flight)
            return ac_err(err, en, "option --free-flight: not with --chromatic");
        if (c->kind == 9 && !c->chromatic)
            return ac_err(err, en, "option --kind: spectral needs --chromatic");
        if (c->chromatic && c->kind >= APPEAR_TRACK_RESIDUAL && c->kind < 7)
            return ac_err(err, en, "option --kind: %s is not a chromatic tracker (delta, ratio, "
                          "next-flight, spectral, all)", c->val[O_KIND]);
        if (!c->chromatic && (c->set[O_CHANNELS] || c->set[O_MAJORANT]))
            return ac_err(err, en, "option --%s: needs --chromatic",
                          c->set[O_CHANNELS] ? "channels" : "majorant");
        if (!c->free_flight && (c->set[O_SIGMA] || c->set[O_LENGTH]))
            return ac_err(err, en, "option --%s: needs --free-flight",
                          c->set[O_SIGMA] ? "sigma-t" : "length");
        return 0;
    }
    /* model */
    if ((r = ac_choice_opt(c, O_DIST, ac_dist_names, 2, 0, &c->dist, err, en))) return r;
    if ((r = ac_choice_opt(c, O_SAMPLING, ac_sampling_names, 3, 0, &c->sampling, err, en))) return r;
    if (c->sampling == APPEAR_SAMPLE_BOUNDED && c->dist != APPEAR_GGX) return ac_err(err, en, "option --sampling: bounded needs --dist ggx");
    if ((r = ac_choice_opt(c, O_VARIANT, ac_variant_names, 3, 0, &c->variant, err, en))) return r;
    if ((r = ac_choice_opt(c, O_SHAPE, ac_shape_names, 2, 0, &c->shape, err, en))) return r;
    if (c->model == AD_DRAINE) {
        if ((r = ac_num_opt(c, O_ALPHA, 1, -1, 1e6, &c->alpha[0], err, en))) return r;
    } else {
        double hi = (c->model == AD_SGGX_SPECULAR || c->model == AD_SGGX_DIFFUSE) ? 1 : (c->model == AD_WARD ? 100 : 100);
        double lo = c->model == AD_WARD ? 1e-30 : 0;
        int n = 1;
        c->alpha[0] = c->alpha[1] = 0.3;
        if (c->val[O_ALPHA]) {
            n = ac_list(c->val[O_ALPHA], c->alpha, 2);
            if (!n) return ac_err(err, en, "option --alpha: '%s' is not a number or a pair ax,ay", c->val[O_ALPHA]);
            if (n == 1) c->alpha[1] = c->alpha[0];
            for (o = 0; o < 2; ++o)
                if (!(c->alpha[o] >= lo && c->alpha[o] <= hi))
                    return ac_err(err, en, "option --alpha: %g is out of range [%g, %g]", c->alpha[o], lo == 1e-30 ? 0 : lo, hi);
            if (c->model == AD_WARD && (c->alpha[0] <= 0 || c->alpha[1] <= 0)) return ac_err(err, en, "option --alpha: ward needs alpha > 0");
        }
    }
    {
        int cond = c->model == AD_CONDUCTOR || c->model == AD_CONDUCTOR_COMP || c->model == AD_CONDUCTOR_MS || c->model == AD_THINFILM_CONDUCTOR;
        if (cond) { if ((r = ac_num_opt(c, O_ETA, 0.2, 0, 1e6, &c->eta, err, en))) return r; }
        else if ((r = ac_num_opt(c, O_ETA, 1.5, 1e-4, 1e4, &c->eta, err, en))) return r;
    }
    if ((r = ac_num_opt(c, O_K, 3.9, 0, 1e6, &c->k, err, en))) return r;
    if (c->model == AD_THINFILM_CONDUCTOR && !(c->eta > 0)) return ac_err(err, en, "option --eta: the film's base needs eta > 0");
    if ((r = ac_num_opt(c, O_ALBEDO, 0.8, 0, 1, &c->albedo, err, en))) return r;
    if ((r = ac_num_opt(c, O_RHO_D, 0.2, 0, 1, &c->rho_d, err, en))) return r;
    if ((r = ac_num_opt(c, O_RHO_S, 0.5, 0, 1, &c->rho_s, err, en))) return r;
    if (c->rho_d + c->rho_s > 1) return ac_err(err, en, "option --rho-s: rho-d + rho-s = %g exceeds 1", c->rho_d + c->rho_s);
    if ((r = ac_num_opt(c, O_G, 0.5, -1, 1, &c->g, err, en))) return r;
    if ((r = ac_num_opt(c, O_G1, 0.8, -1, 1, &c->g1, err, en))) return r;
    if ((r = ac_num_opt(c, O_G2, -0.3, -1, 1, &c->g2, err, en))) return r;
    if ((r = ac_num_opt(c, O_W, 0.7, 0, 1, &c->w, err, en))) return r;
    if ((r = ac_num_opt(c, O_DIAMETER, 10, 0, 50, &c->diameter, err, en))) return r;
    if ((r = ac_num_opt(c, O_FILM_ETA, 1.33, 1e-6, 1e3, &c->film_eta, err, en))) return r;
    if ((r = ac_num_opt(c, O_THICKNESS, 400, 0, 1e5, &c->thickness, err, en))) return r;
    if ((r = ac_num_opt(c, O_P, 10, 0, 1024, &c->p, err, en))) return r;
    if ((r = ac_num_opt(c, O_ROUGH_SIGMA, 0.5, 0, 1, &c->rough_sigma, err, en))) return r;
    {
        static const char *const en_[] = { "cltc", "cosine" };
        if ((r = ac_choice_opt(c, O_EON_SAMPLING, en_, 2, 0, &c->eon_sampling, err, en))) return r;
    }
    if ((r = ac_num_opt(c, O_TILT, c->model == AD_FIBER ? 90 : 0, -360, 360, &c->tilt, err, en))) return r;
    if (c->model == AD_TABLE && !c->val[O_TABLE]) return ac_err(err, en, "option --table: model table needs --table FILE");
    c->has_f0 = c->model == AD_CONDUCTOR_F0 || c->set[O_F0];
    c->f0[0] = c->f0[1] = c->f0[2] = 0.9;
    if (c->val[O_F0]) {
        int n = ac_list(c->val[O_F0], c->f0, 3);
        if (n != 1 && n != 3)
            return ac_err(err, en, "option --f0: '%s' is not R or R,G,B", c->val[O_F0]);
        if (n == 1) c->f0[1] = c->f0[2] = c->f0[0];
        for (o = 0; o < 3; ++o)
            if (!(c->f0[o] >= 0 && c->f0[o] <= 1))
                return ac_err(err, en, "option --f0: %g is out of range [0, 1]", c->f0[o]);
        if (c->set[O_ETA] || c->set[O_K])
            return ac_err(err, en, "option --f0: not with --eta or --k");
    }
    return 0;
}

static void ac_help(FILE *f, int cmd, int model)
{
    int o, m;
    if (cmd < 0) {
        fprintf(f, "usage: appear-check SUBCOMMAND MODEL [--option value]...\n"
                   "       appear-check transmittance [--kind K] [--profile P] [--tightness T] ...\n"
                   "       appear-check SUBCOMMAND [MODEL] --help   (the options of one subcommand, with defaults)\n"
                   "       appear-check --version   (appear.h's version, compiler, build flags)\n\n"
                   "subcommands:\n");
        for (o = 0; o < C_COUNT; ++o) fprintf(f, "  %-14s %s\n", ac_cmd_name[o], ac_cmd_help[o]);
        fprintf(f, "\nmodels (their options):\n");
        for (m = 0; m < AD_COUNT; ++m)
            fprintf(f, "  %-19s %s%s%s%s\n", ac_models[m].name, ac_models[m].help, *ac_models[m].opts ? " [" : "", ac_models[m].opts,
                    *ac_models[m].opts ? "]" : "");
        fprintf(f, "\noptions (default):\n");
        for (o = 0; o < O_COUNT; ++o)
            fprintf(f, "  --%-11s %s%s  (default: %s)\n", ac_opts[o].name, ac_opts[o].flag ? "      " : "VALUE ", ac_opts[o].help,
                    *ac_opts[o].def ? ac_opts[o].def : "-");
        fprintf(f, "\nexit status: 0 ran (a failed check is reported in the table, and chi2 exits 1 when p < 0.01),\n"
                   "2 bad command line. Example: appear-check furnace dielectric --dist ggx --alpha 0.3 --eta 1.5\n");
        fprintf(f, "\nbuild (appear-check --version): %s\n", ac_build);
        return;
    }
    fprintf(f, "usage: appear-check %s %s [--option value]...\n  %s\n\noptions (default):\n", ac_cmd_name[cmd],
            cmd == C_TRANSMITTANCE ? "" : (model >= 0 ? ac_models[model].name : "MODEL"), ac_cmd_help[cmd]);
    if (model >= 0 && cmd != C_TRANSMITTANCE) fprintf(f, "  (model %s: %s)\n", ac_models[model].name, ac_models[model].help);
    for (o = 0; o < O_COUNT; ++o) {
        if (!(ac_opts[o].cmds & CM(cmd))) continue;
        if (ac_opts[o].model && (cmd == C_TRANSMITTANCE || (model >= 0 && !ac_model_uses(model, ac_opts[o].name)))) continue;
        fprintf(f, "  --%-11s %s%s  (default: %s)\n", ac_opts[o].name, ac_opts[o].flag ? "      " : "VALUE ", ac_opts[o].help,
                *ac_opts[o].def ? ac_opts[o].def : "-");
    }
    if (model < 0 && cmd != C_TRANSMITTANCE) fprintf(f, "  (model options apply to the models listed by appear-check --help)\n");
}

/* ------------------------------------------------------------------------ */
/* Models: tests/adapters.h (shared with the model battery of the tests)    */
/* ------------------------------------------------------------------------ */

/* reads the --table file: returns 0 or fills err */
static int ac_read_table(const char *path, appear_phase_table *t, char *err, size_t en)
{
    static float mu[APPEAR_PHASE_TABLE_MAX + 1], val[APPEAR_PHASE_TABLE_MAX + 1];
    char line[512];
    int n = 0, cols = -1, line_no = 0;
    FILE *f = fopen(path, "r");
    if (!f) return ac_err(err, en, "option --table: cannot open '%s'", path);
    while (fgets(line, sizeof line, f)) {
        double a, b;
        char *s = line, *e;
        int c = 0;
        ++line_no;
        while (*s == ' ' || *s == '\t') ++s;
        if (*s == '#' || *s == '\n' || *s == '\r' || !*s) continue;
        a = strtod(s, &e);
        if (e == s) { fclose(f); return ac_err(err, en, "option --table: %s line %d is not a number", path, line_no); }
        c = 1; s = e;
        b = strtod(s, &e);
        if (e != s) { c = 2; s = e; }
        while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n') ++s;
        if (*s && *s != '#') { fclose(f); return ac_err(err, en, "option --table: %s line %d: trailing text", path, line_no); }
        if (cols < 0) cols = c;
        if (c != cols) { fclose(f); return ac_err(err, en, "option --table: %s line %d: %d columns, the first row had %d", path, line_no, c, cols); }
        if (n >= APPEAR_PHASE_TABLE_MAX) { fclose(f); return ac_err(err, en, "option --table: %s has more than %d rows", path, APPEAR_PHASE_TABLE_MAX); }
        if (c == 2) { mu[n] = (float)a; val[n] = (float)b; } else val[n] = (float)a;
        ++n;
    }
    fclose(f);
    if (!appear_phase_table_make(t, val, cols == 2 ? mu : NULL, n))
        return ac_err(err, en, "option --table: %s rejected by appear_phase_table_make (%d rows; need 2..%d, mu increasing from exactly -1 to 1, values >= 0, not all 0)",
                      path, n, APPEAR_PHASE_TABLE_MAX);
    return 0;
}

/* Builds the model of c into m (the table of AD_TABLE is allocated; ac_free_model frees it).
   Returns 0 or 2 with err. */
static appear_phase_table *ac_table_owned;
static int ac_make_model(const ac_config *c, ad_model *m, char *err, size_t en)
{
    ad_params p;
    float ax = (float)c->alpha[0], ay = (float)c->alpha[1];
    double tr = c->tilt * 3.14159265358979 / 180.0;
    int i, model = c->model;
    memset(&p, 0, sizeof p);
    p.dist = c->dist; p.sampling = c->sampling; p.alpha[0] = ax; p.alpha[1] = ay;
    p.eta = (float)c->eta;
    for (i = 0; i < 3; ++i) {
        p.n[i] = (float)c->eta; p.k[i] = (float)c->k; p.f0[i] = (float)c->f0[i];
        p.albedo[i] = (float)c->albedo; p.rho_d[i] = (float)c->rho_d; p.rho_s[i] = (float)c->rho_s;
    }
    p.fresnel = c->has_f0 ? AD_FRESNEL_F0 : AD_FRESNEL_IOR;
    p.variant = c->variant;
    p.g = (float)c->g; p.g1 = (float)c->g1; p.g2 = (float)c->g2; p.w = (float)c->w;
    p.d = (float)c->diameter;
    p.film_eta = (float)c->film_eta; p.thickness = (float)c->thickness;
    p.shape = c->shape ? AD_SGGX_FIBER : AD_SGGX_SURFACE;
    p.axis[0] = (float)sin(tr); p.axis[1] = 0.0f; p.axis[2] = (float)cos(tr);
    { /* the axis normalised in float, as appear-check always did */
        appear_vec3 a = appear_normalize(appear_vec3_make(p.axis[0], p.axis[1], p.axis[2]));
        p.axis[0] = a.x; p.axis[1] = a.y; p.axis[2] = a.z;
    }
    p.p = (float)c->p;
    p.sigma = (float)c->rough_sigma;
    p.eon_sampling = c->eon_sampling ? APPEAR_EON_SAMPLE_COSINE : APPEAR_EON_SAMPLE_CLTC;
    p.seed = (unsigned)c->seed * 2654435761u + 7u;
    if (model == AD_DRAINE) p.alpha[0] = (float)c->alpha[0];
    if (model == AD_TABLE) {
        int r;
        ac_table_owned = (appear_phase_table *)malloc(sizeof *ac_table_owned);
        if (!ac_table_owned) return ac_err(err, en, "out of memory");
        if ((r = ac_read_table(c->val[O_TABLE], ac_table_owned, err, en))) {
            free(ac_table_owned); ac_table_owned = 0; return r;
        }
        p.table = ac_table_owned;
    }
    ad_make(m, model, &p);
    switch (model) {
    case AD_LAMBERT: snprintf(m->name, sizeof m->name, "lambert albedo %g", c->albedo); break;
    case AD_EON:
        snprintf(m->name, sizeof m->name, "eon albedo %g sigma %g sampling %s", c->albedo,
                 c->rough_sigma, c->eon_sampling ? "cosine" : "cltc");
        break;
    case AD_WARD:
        snprintf(m->name, sizeof m->name, "ward %s alpha %g,%g rho_d %g rho_s %g",
                 ac_variant_names[c->variant], ax, ay, c->rho_d, c->rho_s);
        break;
    case AD_CONDUCTOR: case AD_CONDUCTOR_COMP: case AD_CONDUCTOR_MS: case AD_CONDUCTOR_F0:
        if (c->has_f0)
            snprintf(m->name, sizeof m->name, "%s %s alpha %g,%g F0 %g,%g,%g",
                     ac_models[model].name, ac_dist_names[c->dist], ax, ay, c->f0[0], c->f0[1],
                     c->f0[2]);
        else
            snprintf(m->name, sizeof m->name, "%s %s alpha %g,%g eta %g k %g",
                     ac_models[model].name, ac_dist_names[c->dist], ax, ay, c->eta, c->k);
        break;
    case AD_DIELECTRIC: case AD_DIELECTRIC_COMP: case AD_DIELECTRIC_MS:
        snprintf(m->name, sizeof m->name, "%s %s alpha %g,%g eta %g", ac_models[model].name,
                 ac_dist_names[c->dist], ax, ay, c->eta);
        break;
    case AD_THIN_DIELECTRIC:
        snprintf(m->name, sizeof m->name, "thin-dielectric eta %g", c->eta);
        break;
    case AD_THINFILM_CONDUCTOR:
        snprintf(m->name, sizeof m->name,
                 "thinfilm-conductor %s alpha %g,%g film %g %g nm base %g+%gi", ac_dist_names[c->dist], ax, ay, c->film_eta, c->thickness, c->eta, c->k);
        break;
    case AD_HG: snprintf(m->name, sizeof m->name, "hg g %g", c->g); break;
    case AD_DHG:
        snprintf(m->name, sizeof m->name, "dhg g1 %g g2 %g w %g", c->g1, c->g2, c->w);
        break;
    case AD_DRAINE:
        snprintf(m->name, sizeof m->name, "draine g %g alpha %g", c->g, c->alpha[0]);
        break;
    case AD_MIE: snprintf(m->name, sizeof m->name, "mie diameter %g um", c->diameter); break;
    case AD_TABLE:
        snprintf(m->name, sizeof m->name, "table %s (%d rows)", c->val[O_TABLE], ac_table_owned->n);
        break;
    case AD_SGGX_SPECULAR: case AD_SGGX_DIFFUSE:
        snprintf(m->name, sizeof m->name, "%s %s alpha %g tilt %g", ac_models[model].name,
                 ac_shape_names[c->shape], ax, c->tilt);
        break;
    case AD_FIBER: snprintf(m->name, sizeof m->name, "fiber p %g tilt %g", c->p, c->tilt); break;
    case AD_SHEEN: snprintf(m->name, sizeof m->name, "sheen roughness %g colour %g", ax, c->albedo); break;
    case AD_OPENPBR:
        snprintf(m->name, sizeof m->name, "openpbr plastic: specular roughness %g ior %g base colour %g",
                 sqrt(ax), c->eta, c->albedo);
        break;
    case AD_DIELECTRIC_DISPERSIVE:
        snprintf(m->name, sizeof m->name, "dielectric-dispersive %s alpha %g,%g n_d %g Abbe 30",
                 ac_dist_names[c->dist], ax, ay, c->eta);
        break;
    case AD_LAYERED: case AD_COATED:
        snprintf(m->name, sizeof m->name, "%s: %s coat alpha %g,%g eta %g over lambert albedo %g",
                 model == AD_LAYERED ? "layered" : "coated", ac_dist_names[c->dist], ax, ay, c->eta, c->albedo);
        break;
    default: snprintf(m->name, sizeof m->name, "%s", ac_models[model].name); break;
    }
    if (!m->valid)
        return ac_err(err, en, "model %s: parameters rejected by appear.h's make() (%s)",
                      ac_models[model].name, m->name);
    return 0;
}
static void ac_free_model(ad_model *m) { free(ac_table_owned); ac_table_owned = 0; m->ph.m.table = 0; }


static check_vec3 ac_wo(const ac_config *c, double theta)
{
    return check_dir_theta_phi(theta, c->phi);
}

/* ------------------------------------------------------------------------ */
/* Output helpers                                                            */
/* ------------------------------------------------------------------------ */

/* gnuplot via popen when `command -v gnuplot` succeeds; else one line. data:
   whitespace columns; script: plot commands reading '-' (the data is sent inline). */
static int ac_plot(const char *png, const char *script, const char *data)
{
    FILE *g;
    if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
        printf("plot skipped: gnuplot not found (apt-get install gnuplot-nox), %s not written\n", png);
        return 0;
    }
    g = popen("gnuplot", "w");
    if (!g) { printf("plot skipped: cannot start gnuplot\n"); return 0; }
    fprintf(g, "set terminal pngcairo size 800,500\nset output '%s'\n%s\n%s\ne\n", png, script, data);
    if (pclose(g) != 0) { printf("plot failed: gnuplot returned an error\n"); return 1; }
    printf("plot: %s\n", png);
    return 0;
}
/* heat colour map of v in [0, 1] (display values, written through the sRGB PNG writer) */
static void ac_heat(float v, float *rgb)
{
    float r, g, b;
    v = v < 0 ? 0 : v > 1 ? 1 : v;
    r = 3 * v; g = 3 * v - 1; b = 3 * v - 2;
    if (v < 1.0f / 3) b = 1.5f * v; /* dark blue start */
    rgb[0] = powf(r > 1 ? 1 : r, 2.2f); rgb[1] = powf(g < 0 ? 0 : g > 1 ? 1 : g, 2.2f); rgb[2] = powf(b < 0 ? 0 : b > 1 ? 1 : b, 2.2f);
}
static double ac_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* ------------------------------------------------------------------------ */
/* furnace                                                                   */
/* ------------------------------------------------------------------------ */

static int ac_cmd_furnace(const ac_config *c, ad_model *m)
{
    check_model cm = ad_check_model(m);
    int i;
    char *data = (char *)malloc(64 * 40), *dp = data;
    *data = 0;
    if (c->csv) printf("theta_deg,albedo,se,lost,reflect,transmit,delta,failed,max_weight,n\n");
    else {
        printf("furnace: %s, %ld samples per angle%s\n", m->name, c->samples,
               m->bsdf && m->eta != 1 ? " (transmission counted as energy: weight x e^2)" : "");
        printf("  theta    albedo        se      lost   reflect  transmit     delta   failed   max w\n");
    }
    for (i = 0; i < c->n_theta; ++i) {
        check_furnace_result r;
        check_furnace(&cm, ac_wo(c, c->theta[i]), c->samples, c->seed + 1000u * i, &r);
        if (c->csv)
            printf("%g,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.4g,%ld\n", c->theta[i], r.albedo, r.se, 1 - r.albedo, r.reflect, r.transmit,
                   r.delta, r.failed, r.max_weight, r.n);
        else
            printf("  %5.1f  %8.5f  %8.5f  %8.5f  %8.5f  %8.5f  %8.5f  %7.4f  %6.3g%s\n", c->theta[i], r.albedo, r.se, 1 - r.albedo, r.reflect,
                   r.transmit, r.delta, r.failed, r.max_weight, r.albedo > 1 + 4 * r.se + 1e-6 ? "  GAINS ENERGY (> 1 + 4 se)" : "");
        dp += sprintf(dp, "%g %g %g\n", c->theta[i], r.albedo, r.se);
    }
    if (!c->csv) printf("  (lost = 1 - albedo; a lossless model has |lost| <= 4 se)\n");
    if (c->val[O_PLOT]) {
        char script[512];
        snprintf(script, sizeof script, "set title 'furnace: %s'\nset xlabel 'theta (deg)'\nset ylabel 'albedo'\nset grid\n"
                 "plot '-' using 1:2:3 with yerrorlines title 'albedo +- se'", m->name);
        ac_plot(c->val[O_PLOT], script, data);
    }
    free(data);
    return 0;
}

/* ------------------------------------------------------------------------ */
/* reciprocity                                                               */
/* ------------------------------------------------------------------------ */

static int ac_cmd_reciprocity(const ac_config *c, ad_model *m)
{
    check_model cm = ad_check_model(m);
    check_reciprocity_result r;
    check_reciprocity(&cm, c->samples, c->floor_, c->repeats, c->seed, &r);
    if (c->csv) {
        printf("pairs,compared,max_rel,max_z,wo_x,wo_y,wo_z,wi_x,wi_y,wi_z,f_fwd,f_rev\n");
        printf("%ld,%ld,%.6g,%.4g,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.8g,%.8g\n", r.pairs, r.compared, r.max_rel, r.max_z, r.wo.x, r.wo.y, r.wo.z,
               r.wi.x, r.wi.y, r.wi.z, r.f_fwd, r.f_rev);
        return 0;
    }
    printf("reciprocity: %s\n", m->name);
    printf("  rule: %s\n", cm.sigma ? "sigma(wo) f(wo,wi) = sigma(wi) f(wi,wo) (micro-flake media)"
                                  : m->eta != 1 ? "f(wo,wi) = f(wi,wo); across the interface n_i^2 f(wo,wi) = n_o^2 f(wi,wo)"
                                                : "f(wo,wi) = f(wi,wo)");
    printf("  pairs %ld (half uniform, half sampled), compared %ld (value > %g)\n", r.pairs, r.compared, c->floor_);
    if (!r.compared) {
        printf("  nothing to compare: %s\n", m->delta_only ? "every lobe is a delta (eval is 0)" : "all values below the floor");
        return 0;
    }
    printf("  max relative violation %.3g at wo (%.4f %.4f %.4f) wi (%.4f %.4f %.4f): %.8g vs %.8g\n", r.max_rel, r.wo.x, r.wo.y, r.wo.z,
           r.wi.x, r.wi.y, r.wi.z, r.f_fwd, r.f_rev);
    if (cm.eval_is_estimate)
        printf("  stochastic eval (%d calls averaged per side): max |difference| / its standard error = %.2f (%s)\n", c->repeats, r.max_z,
               r.max_z < 5.5 ? "consistent with noise" : "beyond noise");
    return 0;
}

/* ------------------------------------------------------------------------ */
/* chi2                                                                      */
/* ------------------------------------------------------------------------ */

static check_vec3 ac_chi2_axis(const ac_config *c, const ad_model *m, check_vec3 wo)
{
    if (c->has_axis) return check_vec3_make(c->axis[0], c->axis[1], c->axis[2]);
    if (m->bsdf) return check_vec3_make(-wo.x, -wo.y, wo.z);   /* mirror direction */
    if (m->family == AD_SGGX_SPECULAR || m->family == AD_SGGX_DIFFUSE || m->family == AD_FIBER) return check_vec3_make(0, 0, 1);
    return check_vec3_make(-wo.x, -wo.y, -wo.z);               /* forward */
}
static int ac_write_hist(const ac_config *c, const check_chi2_result *r)
{
    int nz = r->n_z, np = r->n_phi, i, rc = 0;
    double mx = 0;
    if (c->val[O_EXR]) {
        const char *names[3] = { "exp", "obs", "res" };
        float *img = (float *)malloc(sizeof(float) * 3 * nz * np);
        for (i = 0; i < nz * np; ++i) {
            img[3 * i + 0] = (float)r->expected[i];
            img[3 * i + 1] = (float)r->observed[i];
            img[3 * i + 2] = r->expected[i] > 0 ? (float)((r->observed[i] - r->expected[i]) / sqrt(r->expected[i])) : (float)r->observed[i];
        }
        if (img_write_exr(c->val[O_EXR], np, nz, 3, names, img)) { printf("cannot write %s\n", c->val[O_EXR]); rc = 1; }
        else printf("  histograms: %s (channels obs, exp, res = (obs - exp)/sqrt(exp); rows = cos bands from the cap, columns = phi)\n", c->val[O_EXR]);
        free(img);
    }
    if (c->val[O_PNG]) {   /* observed | expected | residual, side by side, each scaled up */
        int s = np >= 128 ? 2 : 4, W = 3 * np * s + 2 * 4, H = nz * s, x, y;
        float *img = (float *)calloc((size_t)W * H * 3, sizeof(float));
        for (i = 0; i < nz * np; ++i) mx = fmax(mx, fmax(r->observed[i], r->expected[i]));
        for (y = 0; y < H; ++y)
            for (x = 0; x < W; ++x) {
                int panel = x / (np * s + 4), px = (x % (np * s + 4)) / s, k = (H - 1 - y) / s * np + px;
                float *o = img + 3 * ((size_t)y * W + x);
                if (px >= np) continue;
                if (panel < 2) ac_heat(mx > 0 ? (float)((panel ? r->expected[k] : r->observed[k]) / mx) : 0, o);
                else {
                    double res = r->expected[k] > 0 ? (r->observed[k] - r->expected[k]) / sqrt(r->expected[k]) : 0;
                    float v = (float)fmin(1.0, fabs(res) / 4.0);
                    o[0] = res > 0 ? v : 0; o[1] = 0.05f; o[2] = res < 0 ? v : 0;
                }
            }
        if (img_write_png(c->val[O_PNG], W, H, img, 1.0f)) { printf("cannot write %s\n", c->val[O_PNG]); rc = 1; }
        else printf("  histograms: %s (observed | expected | residual red + / blue -, 4 sigma = full; top row = cos 1)\n", c->val[O_PNG]);
        free(img);
    }
    return rc;
}
static int ac_cmd_chi2(const ac_config *c, ad_model *m)
{
    check_model cm = ad_check_model(m);
    int i, worst = 0;
    if (m->approx_pdf || m->delta_only) {
        const char *why = m->delta_only ? "every lobe is a delta (nothing to bin; see furnace)"
                          : m->family == AD_LAYERED
                              ? "the layered walk's pdf() is a noisy estimate (appear.h: sample returns the walk's unbiased weight); "
                                "use furnace and consistency (tests/test_layered.c bins the sampler against the estimate's mean)"
                              : "the random walk's pdf() is an approximation by design (appear.h: sample returns the walk's exact weight); "
                                "use furnace and consistency";
        if (c->csv) printf("theta_deg,chi2,dof,p,n,pdf_mass,rest_obs,rest_exp\n");
        else printf("chi2: %s: not applicable: %s\n", m->name, why);
        return 0;
    }
    if (c->csv) printf("theta_deg,chi2,dof,p,n,pdf_mass,rest_obs,rest_exp\n");
    else printf("chi2: %s, %ld samples, %dx%d bins%s\n", m->name, c->samples, c->n_z, c->n_phi, c->cap > -1 ? " in a cap" : "");
    for (i = 0; i < c->n_theta; ++i) {
        check_chi2_opts o;
        check_chi2_result r;
        check_vec3 wo = ac_wo(c, c->theta[i]);
        memset(&o, 0, sizeof o);
        o.n_z = c->n_z; o.n_phi = c->n_phi; o.n_samples = c->samples; o.seed = c->seed + 17u * i;
        o.axis = ac_chi2_axis(c, m, wo);
        o.zmin = c->cap > -1 ? c->cap : 0;
        if (check_chi2(&cm, wo, &o, &r)) { printf("chi2: cannot run (out of memory)\n"); return 1; }
        if (c->csv) printf("%g,%.3f,%d,%.6g,%ld,%.6f,%ld,%.2f\n", c->theta[i], r.chi2, r.dof, r.p, r.n, r.pdf_mass, r.rest_observed, r.rest_expected);
        else
            printf("  theta %5.1f: chi2 %.1f  dof %d  p %.4g  %s   (pdf mass in bins %.5f; rest cell: observed %ld, expected %.1f)%s\n",
                   c->theta[i], r.chi2, r.dof, r.p, r.p >= 0.01 ? "pass" : "FAIL (p < 0.01)", r.pdf_mass, r.rest_observed, r.rest_expected,
                   r.zero_pdf_hits ? "  samples where pdf = 0!" : "");
        if (r.p < 0.01) worst = 1;
        if (i == 0) ac_write_hist(c, &r);
        check_chi2_free(&r);
    }
    return worst;
}

/* ------------------------------------------------------------------------ */
/* consistency                                                               */
/* ------------------------------------------------------------------------ */

static int ac_cmd_consistency(const ac_config *c, ad_model *m)
{
    check_model cm = ad_check_model(m);
    int i;
    if (c->csv) printf("theta_deg,checked,bad,max_rel_f,max_rel_pdf,max_rel_weight\n");
    else printf("consistency: %s, %ld samples per angle, tolerance %g%s\n", m->name, c->samples, c->tol,
                m->family == AD_LAYERED ? " (stochastic eval: f not compared; the record's pdf and pdf() are two noisy "
                                          "estimates: their difference is noise, only weight = f |cos| / pdf must hold)"
                : m->stochastic_eval    ? " (stochastic eval: f not compared)"
                                        : "");
    for (i = 0; i < c->n_theta; ++i) {
        check_consistency_result r;
        check_consistency(&cm, ac_wo(c, c->theta[i]), c->samples, c->tol, c->seed + i, &r);
        if (c->csv) printf("%g,%ld,%ld,%.4g,%.4g,%.4g\n", c->theta[i], r.checked, r.bad, r.max_rel_f, r.max_rel_pdf, r.max_rel_weight);
        else printf("  theta %5.1f: %ld non-delta samples, %ld beyond tol; max rel diff f %.3g pdf %.3g weight %.3g\n", c->theta[i], r.checked,
                    r.bad, r.max_rel_f, r.max_rel_pdf, r.max_rel_weight);
    }
    return 0;
}

/* ------------------------------------------------------------------------ */
/* lobe                                                                      */
/* ------------------------------------------------------------------------ */

static float ac_eval_avg(ad_model *m, appear_vec3 wo, appear_vec3 wi)
{   /* stochastic evals: average 4 */
    int k, n = m->stochastic_eval ? 4 : 1;
    float s = 0;
    for (k = 0; k < n; ++k) s += ad_eval1(m, wo, wi);
    return s / n;
}
static int ac_cmd_lobe(const ac_config *c, ad_model *m)
{
    int S = c->size, W = 2 * S, H = S, x, y, rc = 0, k;
    float *val = (float *)calloc((size_t)W * H, sizeof(float)), *rgb = (float *)calloc((size_t)W * H * 3, sizeof(float));
    appear_vec3 wo = ad_v(ac_wo(c, c->theta[0])), peak_dir = appear_vec3_make(0, 0, 1);
    double integ[2] = { 0, 0 }, peak = 0, pi = 3.14159265358979;
    char *data = (char *)malloc(200 * 64), *dp = data;
    *data = 0;
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            appear_vec3 wi;
            float v;
            int side = x >= S;
            if (m->bsdf) {   /* orthographic disks: left = wo's side (reflection), right = the other side */
                double px = ((x % S) + 0.5) / S * 2 - 1, py = 1 - (y + 0.5) / S * 2, r2 = px * px + py * py;
                if (r2 >= 1) continue;
                wi = appear_vec3_make((float)px, (float)py, (float)(sqrt(1 - r2) * ((wo.z >= 0) != side ? 1 : -1)));
                v = ac_eval_avg(m, wo, wi) * fabsf(wi.z);
                integ[side] += v * (2.0 / S) * (2.0 / S);   /* f|cos| d(omega) = f dA */
            } else {         /* lat-long: rows theta 0..180 from +z, columns phi 0..360 */
                double th = (y + 0.5) / H * pi, ph = (x + 0.5) / W * 2 * pi;
                wi = appear_vec3_make((float)(sin(th) * cos(ph)), (float)(sin(th) * sin(ph)), (float)cos(th));
                v = ac_eval_avg(m, wo, wi);
                integ[0] += v * sin(th) * (pi / H) * (2 * pi / W);
            }
            val[(size_t)y * W + x] = v;
            if (v > peak) { peak = v; peak_dir = wi; }
        }
    for (k = 0; k < W * H; ++k) ac_heat(peak > 0 ? sqrtf(val[k] / (float)peak) : 0, rgb + 3 * k);
    if (c->csv) printf("angle_deg,%s\n", m->bsdf ? "fcos_reflect,fcos_transmit" : "phase");
    else {
        printf("lobe: %s, wo theta %g phi %g\n", m->name, c->theta[0], c->phi);
        if (m->bsdf) printf("  integral of f|cos| (image quadrature, delta lobes not shown): reflection %.4f, transmission %.4f\n", integ[0], integ[1]);
        else printf("  integral of the phase function over the sphere (image quadrature): %.4f\n", integ[0]);
        printf("  peak %s %.5g at wi (%.3f %.3f %.3f)\n", m->bsdf ? "f|cos|" : "f", peak, peak_dir.x, peak_dir.y, peak_dir.z);
        printf("  in-plane slice (%s):\n", m->bsdf ? "signed theta_i in the plane of incidence; f|cos| reflected / transmitted" : "scattering angle; f");
    }
    for (k = 0; k <= 36; ++k) {   /* slice */
        double a;
        float r0, r1 = 0;
        appear_vec3 wi;
        if (m->bsdf) {
            double cp = cos(c->phi * pi / 180), sp = sin(c->phi * pi / 180), t;
            a = -90 + 5 * k; t = a * pi / 180;
            wi = appear_vec3_make((float)(sin(t) * cp), (float)(sin(t) * sp), (float)(cos(t) * (wo.z >= 0 ? 1 : -1)));
            r0 = ac_eval_avg(m, wo, wi) * fabsf(wi.z);
            wi.z = -wi.z;
            r1 = ac_eval_avg(m, wo, wi) * fabsf(wi.z);
        } else {
            appear_vec3 f = appear_neg(wo), perp = appear_normalize(appear_cross(wo, fabsf(wo.z) < 0.9f ? appear_vec3_make(0, 0, 1) : appear_vec3_make(1, 0, 0)));
            a = 5 * k; 
            wi = appear_normalize(appear_add(appear_scale(f, (float)cos(a * pi / 180)), appear_scale(perp, (float)sin(a * pi / 180))));
            r0 = ac_eval_avg(m, wo, wi);
        }
        if (c->csv) { if (m->bsdf) printf("%g,%.6g,%.6g\n", a, r0, r1); else printf("%g,%.6g\n", a, r0); }
        else if (k % 3 == 0) {
            if (m->bsdf) printf("    %6.1f  %10.5g  %10.5g\n", a, r0, r1); else printf("    %6.1f  %10.5g\n", a, r0);
        }
        dp += sprintf(dp, "%g %g %g\n", a, r0, r1);
    }
    if (c->val[O_PNG]) {
        if (img_write_png(c->val[O_PNG], W, H, rgb, 1.0f)) { printf("cannot write %s\n", c->val[O_PNG]); rc = 1; }
        else printf("  image: %s (%s; sqrt-scaled heat map, white = peak)\n", c->val[O_PNG],
                    m->bsdf ? "left: wo's hemisphere seen from above, right: the other hemisphere (orthographic)" : "lat-long, theta 0 at the top");
    }
    if (c->val[O_EXR]) {
        const char *names[1] = { "Y" };
        if (img_write_exr(c->val[O_EXR], W, H, 1, names, val)) { printf("cannot write %s\n", c->val[O_EXR]); rc = 1; }
        else printf("  image: %s (Y = %s)\n", c->val[O_EXR], m->bsdf ? "f|cos|" : "f");
    }
    if (c->val[O_PLOT]) {
        char script[600];
        if (m->bsdf)
            snprintf(script, sizeof script, "set title 'lobe: %s, theta_o %g'\nset polar\nset angles degrees\nset size square\nset grid polar\n"
                     "plot '-' using ($1+90):2 with lines title 'f cos (in-plane, reflection)'", m->name, c->theta[0]);
        else
            snprintf(script, sizeof script, "set title 'phase: %s'\nset logscale y\nset xlabel 'scattering angle (deg)'\nset grid\n"
                     "plot '-' using 1:2 with lines title 'f'", m->name);
        ac_plot(c->val[O_PLOT], script, data);
    }
    free(val); free(rgb); free(data);
    return rc;
}

/* ------------------------------------------------------------------------ */
/* bench                                                                     */
/* ------------------------------------------------------------------------ */

/* the plain model calls (no stratified eval for SGGX diffuse) */
static void ac_sample_fast(ad_model *m, appear_vec3 wo, float uc, float u1, float u2, ad_rec1 *r)
{
    if (m->family == AD_SGGX_DIFFUSE) {
        appear_phase_record p;
        r->ok = appear_sggx_diffuse_sample(&m->sggx, wo, u1, u2, uc, u2 * 0.5f + 0.25f, &p);
        r->wi = p.wi; r->f = p.f; r->pdf = p.pdf; r->weight = p.weight; r->flags = p.flags;
        return;
    }
    ad_sample1(m, wo, uc, u1, u2, r);
}
static float ac_eval_fast(ad_model *m, appear_vec3 wo, appear_vec3 wi, float u)
{
    if (m->family == AD_SGGX_DIFFUSE) return appear_sggx_diffuse_eval(&m->sggx, wo, wi, u, 1 - u);
    return ad_eval1(m, wo, wi);
}
static AC_NOINLINE void ac_lat_sample(ad_model *m, appear_vec3 wo, float uc, float u1, float u2, ad_rec1 *r) { ac_sample_fast(m, wo, uc, u1, u2, r); }
static AC_NOINLINE float ac_lat_eval(ad_model *m, appear_vec3 wo, appear_vec3 wi, float u) { return ac_eval_fast(m, wo, wi, u); }
static AC_NOINLINE float ac_lat_pdf(ad_model *m, appear_vec3 wo, appear_vec3 wi) { return ad_pdf(m, wo, wi); }

static volatile float ac_sink;
static void ac_bench_row(const ac_config *c, const char *what, const char *how, double ns, long n)
{
    if (c->csv) printf("%s,\"%s\",%.3f,%ld,\"%s\"\n", what, how, ns, n, ac_build);
    else printf("  %-8s %-34s %9.2f ns   (%ld calls)\n", what, how, ns, n);
}
static int ac_cmd_bench(const ac_config *c, ad_model *m)
{
    long n = c->samples, i, j;
    float *u = NULL, *o = NULL, sink = 0;
    appear_vec3 wo = ad_v(ac_wo(c, c->theta[0])), w;
    appear_vec3 *wi;
    double t0, t;
    ad_rec1 r;
    int B = 4096;
    if (!c->set[O_SAMPLES] && (m->family == AD_CONDUCTOR_MS || m->family == AD_DIELECTRIC_MS || m->family == AD_LAYERED))
        n /= 10;
    u = (float *)malloc(sizeof(float) * 3 * n);
    wi = (appear_vec3 *)malloc(sizeof(appear_vec3) * n);
    o = (float *)malloc(sizeof(float) * 12 * B);
    {
        check_rng g = check_rng_make(c->seed);
        for (i = 0; i < 3 * n; ++i) u[i] = (float)check_rand(&g);
    }
    for (i = 0; i < n; ++i) { ac_sample_fast(m, wo, u[3 * i], u[3 * i + 1], u[3 * i + 2], &r); wi[i] = r.ok ? r.wi : appear_vec3_make(0, 0, 1); }
    if (c->csv) printf("verb,method,ns_per_call,calls,build\n");
    else {
        printf("bench: %s, wo theta %g, %ld calls each (inputs drawn before timing)\n", m->name,
               c->theta[0], n);
        printf("  build: %s\n", ac_build);
    }
    /* throughput */
    t0 = ac_now();
    for (i = 0; i < n; ++i) { ac_sample_fast(m, wo, u[3 * i], u[3 * i + 1], u[3 * i + 2], &r); sink += r.weight; }
    ac_bench_row(c, "sample", "throughput (scalar loop)", (ac_now() - t0) * 1e9 / n, n);
    if (!m->delta_only) {
        t0 = ac_now();
        for (i = 0; i < n; ++i) sink += ac_eval_fast(m, wo, wi[i], u[3 * i]);
        ac_bench_row(c, "eval", "throughput (scalar loop)", (ac_now() - t0) * 1e9 / n, n);
        t0 = ac_now();
        for (i = 0; i < n; ++i) sink += m->family == AD_SGGX_DIFFUSE ? 0 : ad_pdf(m, wo, wi[i]);
        if (m->family != AD_SGGX_DIFFUSE) ac_bench_row(c, "pdf", "throughput (scalar loop)", (ac_now() - t0) * 1e9 / n, n);
    }
    /* latency: each call's wo from the previous output, behind a noinline wrapper */
    w = wo;
    t0 = ac_now();
    for (i = 0; i < n; ++i) {
        ac_lat_sample(m, w, u[3 * i], u[3 * i + 1], u[3 * i + 2], &r);
        w = r.ok ? (m->bsdf ? appear_vec3_make(r.wi.x, r.wi.y, fabsf(r.wi.z) + 1e-3f * (r.wi.z == 0)) : r.wi) : wo;
        w = appear_normalize(w);
    }
    sink += w.x;
    ac_bench_row(c, "sample", "latency (chained, noinline)", (ac_now() - t0) * 1e9 / n, n);
    if (!m->delta_only) {
        appear_vec3 a = wo;
        float v = 0;
        t0 = ac_now();
        for (i = 0; i < n; ++i) {   /* wo perturbed by the previous value: a dependency the compiler keeps */
            v = ac_lat_eval(m, a, wi[i], u[3 * i]);
            a.x = wo.x + v * 1e-30f;
        }
        sink += v;
        ac_bench_row(c, "eval", "latency (chained, noinline)", (ac_now() - t0) * 1e9 / n, n);
        if (m->family != AD_SGGX_DIFFUSE) {
            a = wo;
            t0 = ac_now();
            for (i = 0; i < n; ++i) { v = ac_lat_pdf(m, a, wi[i]); a.x = wo.x + v * 1e-30f; }
            sink += v;
            ac_bench_row(c, "pdf", "latency (chained, noinline)", (ac_now() - t0) * 1e9 / n, n);
        }
    }
    /* batch entry points */
    {
        float *wx = o, *wy = o + B, *wz = o + 2 * B, *ix = o + 3 * B, *iy = o + 4 * B, *iz = o + 5 * B, *pd = o + 6 * B, *wt = o + 7 * B;
        float *f3 = o + 8 * B; /* 3 B floats: f planar */
        float *uc = (float *)malloc(sizeof(float) * 3 * B), *u1 = uc + B, *u2 = uc + 2 * B;
        float *sx = (float *)malloc(sizeof(float) * 3 * B), *sy = sx + B, *sz = sx + 2 * B;
        unsigned *fl = (unsigned *)malloc(sizeof(unsigned) * B);
        int have = 0, verb;
        for (j = 0; j < B; ++j) {
            wx[j] = wo.x; wy[j] = wo.y; wz[j] = wo.z; uc[j] = u[3 * j]; u1[j] = u[3 * j + 1]; u2[j] = u[3 * j + 2];
            sx[j] = wi[j % n].x; sy[j] = wi[j % n].y; sz[j] = wi[j % n].z;
        }
        for (verb = 0; verb < 3; ++verb) {
            const char *name = 0;
            long done = 0;
            t0 = ac_now();
            while (done < n) {
                int k = 0;
                switch (m->family * 3 + verb) {
                case AD_LAMBERT * 3: appear_lambert_sample_batch(&m->b.m.lambert, wx, wy, wz, u1, u2, ix, iy, iz, pd, wt, fl, B); name = "appear_lambert_sample_batch"; k = 1; break;
                case AD_WARD * 3: appear_ward_sample_batch(&m->b.m.ward, wx, wy, wz, uc, u1, u2, ix, iy, iz, pd, wt, fl, B); name = "appear_ward_sample_batch"; k = 1; break;
                case AD_CONDUCTOR * 3: appear_conductor_sample_batch(&m->b.m.conductor, wx, wy, wz, uc, u1, u2, ix, iy, iz, pd, wt, fl, B); name = "appear_conductor_sample_batch"; k = 1; break;
                case AD_CONDUCTOR * 3 + 1: appear_conductor_eval_batch(&m->b.m.conductor, wx, wy, wz, sx, sy, sz, f3, B); name = "appear_conductor_eval_batch"; k = 1; break;
                case AD_CONDUCTOR * 3 + 2: appear_conductor_pdf_batch(&m->b.m.conductor, wx, wy, wz, sx, sy, sz, pd, B); name = "appear_conductor_pdf_batch"; k = 1; break;
                case AD_DIELECTRIC * 3: appear_dielectric_sample_batch(&m->b.m.dielectric, wx, wy, wz, uc, u1, u2, ix, iy, iz, pd, wt, fl, B); name = "appear_dielectric_sample_batch"; k = 1; break;
                case AD_DIELECTRIC * 3 + 1: appear_dielectric_eval_batch(&m->b.m.dielectric, wx, wy, wz, sx, sy, sz, f3, B); name = "appear_dielectric_eval_batch"; k = 1; break;
                case AD_DIELECTRIC * 3 + 2: appear_dielectric_pdf_batch(&m->b.m.dielectric, wx, wy, wz, sx, sy, sz, pd, B); name = "appear_dielectric_pdf_batch"; k = 1; break;
                case AD_HG * 3: appear_hg_sample_batch(&m->ph.m.hg, wx, wy, wz, u1, u2, ix, iy, iz, pd, B); name = "appear_hg_sample_batch"; k = 1; break;
                case AD_HG * 3 + 1: appear_hg_eval_batch(&m->ph.m.hg, wx, wy, wz, sx, sy, sz, pd, B); name = "appear_hg_eval_batch"; k = 1; break;
                default: break;
                }
                if (!k) break;
                sink += pd[B - 1] + f3[0];
                done += B;
            }
            t = ac_now() - t0;
            if (name) { ac_bench_row(c, verb == 0 ? "sample" : verb == 1 ? "eval" : "pdf", name, t * 1e9 / done, done); have = 1; }
        }
        if (!have && !c->csv) printf("  (no batch entry point for this model in appear.h)\n");
        free(uc); free(sx); free(fl);
    }
    ac_sink = sink;
    if (!c->csv) {
        printf("  (one run; this machine is noisy: repeat, treat differences under 25%% as "
               "ties)\n");
        if (!strstr(ac_build, "-march") || !strstr(ac_build, "-O3"))
            printf("  (this build lacks -O3 -march=...: the batch entry points are not\n"
                   "   vectorised and may read slower than the scalar loop; `make\n"
                   "   build/appear-check` builds with the flags the README recommends)\n");
    }
    free(u); free(wi); free(o);
    return 0;
}

/* ------------------------------------------------------------------------ */
/* transmittance: the test profiles of Georgiev et al. 2019 on [0, 1]        */
/* (as tests/test_media.c)                                                   */
/* ------------------------------------------------------------------------ */

#define AC_BUMP_S 0.1
static double ac_prof_sigma(int p, double x)
{
    double g = exp(-(x - 0.5) * (x - 0.5) / (2.0 * AC_BUMP_S * AC_BUMP_S));
    switch (p) {
    case 0: return 2.0;
    case 1: return 1.5 * cos(20.0 * x + 0.8) + 2.0;
    case 2: return 0.5 + 4.0 * g;
    case 3: return 3.0 - 2.9 * g;
    case 4: return 0.2 + 3.8 * x;
    default: return 4.0 - 3.8 * x;
    }
}
static double ac_prof_tau(int p, double x)
{
    double k = AC_BUMP_S * sqrt(3.14159265358979323846 / 2.0);
    double G = k * (erf((x - 0.5) / (AC_BUMP_S * sqrt(2.0))) + erf(0.5 / (AC_BUMP_S * sqrt(2.0))));
    switch (p) {
    case 0: return 2.0 * x;
    case 1: return 2.0 * x + 1.5 / 20.0 * (sin(20.0 * x + 0.8) - sin(0.8));
    case 2: return 0.5 * x + 4.0 * G;
    case 3: return 3.0 * x - 2.9 * G;
    case 4: return 0.2 * x + 1.9 * x * x;
    default: return 4.0 * x - 1.9 * x * x;
    }
}
/* majorant segments: per-segment max/min by dense sampling plus the
   derivative bound |sigma'| <= 30, then loosened to max / tight, min * tight */
static void ac_segments(int p, int n_seg, double tight, appear_majorant_segment *seg)
{
    int i, j;
    for (i = 0; i < n_seg; ++i) {
        double a = (double)i / n_seg, b = (double)(i + 1) / n_seg, mx = -1e30, mn = 1e30;
        for (j = 0; j <= 2000; ++j) {
            double s = ac_prof_sigma(p, a + (b - a) * j / 2000.0);
            mx = s > mx ? s : mx; mn = s < mn ? s : mn;
        }
        if (p != 0) { mx += 30.0 * (b - a) / 4000.0 + 1e-9; mn -= 30.0 * (b - a) / 4000.0 + 1e-9; }
        if (mn < 0.0) mn = 0.0;
        seg[i] = appear_majorant_make(i == n_seg - 1 ? 1.0f : (float)b, (float)(mx / tight), (float)(mn * tight));
        if ((double)seg[i].sigma_maj < mx / tight) seg[i].sigma_maj = nextafterf(seg[i].sigma_maj, 1e30f);
        if ((double)seg[i].sigma_min > mn * tight) seg[i].sigma_min = nextafterf(seg[i].sigma_min, 0.0f);
    }
}
typedef struct { double mean, var, lookups, se, ff_p; long flags; int ff; } ac_tr_stats;
static void ac_run_tracker(const ac_config *c, int kind, const appear_majorant_segment *seg, ac_tr_stats *st)
{
    check_rng g = check_rng_make(c->seed * 31u + (unsigned)kind);
    double s1 = 0, s2 = 0, lk = 0, T1 = exp(-ac_prof_tau(c->profile, 1.0));
    long i, n = c->samples;
    enum { NB = 20 };
    double obs[NB + 1], ex[NB + 1];
    memset(obs, 0, sizeof obs);
    memset(st, 0, sizeof *st);
    for (i = 0; i < n; ++i) {
        appear_tracker tr;
        float t;
        appear_tracker_init(&tr, kind, 1.0f, seg, c->segments, NULL);
        while (appear_tracker_next(&tr, (float)check_rand(&g), (float)check_rand(&g), &t))
            appear_tracker_feed(&tr, (float)ac_prof_sigma(c->profile, t));
        s1 += tr.T; s2 += (double)tr.T * tr.T; lk += tr.lookups;
        st->flags |= tr.flags;
        if (kind == APPEAR_TRACK_DELTA) {
            int b = tr.collided ? (int)(tr.t * NB) : NB;
            obs[b < 0 ? 0 : b > NB ? NB : b] += 1;
        }
    }
    st->mean = s1 / n;
    st->var = fmax(0.0, s2 / n - st->mean * st->mean) * n / (n > 1 ? n - 1 : 1);
    st->se = sqrt(st->var / n);
    st->lookups = lk / n;
    if (kind == APPEAR_TRACK_DELTA) {   /* free flight: collision distances against sigma(t) T(t) */
        double chi2 = 0, pe = 0, po = 0;
        int b, dof = -1;
        for (b = 0; b < NB; ++b) ex[b] = n * (exp(-ac_prof_tau(c->profile, (double)b / NB)) - exp(-ac_prof_tau(c->profile, (double)(b + 1) / NB)));
        ex[NB] = n * T1;
        for (b = 0; b <= NB; ++b) {
            if (ex[b] < 5) { pe += ex[b]; po += obs[b]; continue; }
            chi2 += (obs[b] - ex[b]) * (obs[b] - ex[b]) / ex[b]; ++dof;
        }
        if (pe > 0) { chi2 += (po - pe) * (po - pe) / pe; ++dof; }
        st->ff = 1;
        st->ff_p = check_chi2_pvalue(chi2, dof);
    }
}
/* chromatic trackers: channel i density k_i x profile, majorant k_i x (the
   scalar segments), or their max over the channels (common) */
typedef struct {
    double mean[3], se[3], energy[3], energy_se[3], lookups;
    unsigned long flags;
} ac_ctr_stats;
static void ac_run_ctracker(const ac_config *c, int kind, const appear_majorant_segment *seg,
                            ac_ctr_stats *st)
{
    appear_cmajorant_segment cs[64];
    check_rng g = check_rng_make(c->seed * 37u + (unsigned)kind);
    double s1[3] = { 0, 0, 0 }, s2[3] = { 0, 0, 0 }, e1[3] = { 0, 0, 0 }, e2[3] = { 0, 0, 0 };
    double lk = 0;
    long i, n = c->samples;
    int j, ch, free_flight = kind == APPEAR_TRACK_DELTA || kind == APPEAR_TRACK_SPECTRAL;
    memset(st, 0, sizeof *st);
    for (j = 0; j < c->segments; ++j) {
        appear_spectrum m = appear_spectrum_splat(0.0f);
        float mx = 0.0f;
        for (ch = 0; ch < 3; ++ch) {
            m.v[ch] = (float)(c->channels[ch] * (double)seg[j].sigma_maj);
            if ((double)m.v[ch] < c->channels[ch] * (double)seg[j].sigma_maj)
                m.v[ch] = nextafterf(m.v[ch], 1e30f);
            mx = m.v[ch] > mx ? m.v[ch] : mx;
        }
        if (!c->per_channel) m = appear_spectrum_splat(mx);
        cs[j] = appear_cmajorant_make(seg[j].t_end, m);
    }
    for (i = 0; i < n; ++i) {
        appear_ctracker tr;
        float t;
        appear_ctracker_init(&tr, kind, 1.0f, cs, c->segments, (float)check_rand(&g), NULL);
        while (appear_ctracker_next(&tr, (float)check_rand(&g), (float)check_rand(&g), &t)) {
            appear_spectrum s;
            double p = ac_prof_sigma(c->profile, t);
            for (ch = 0; ch < 3; ++ch) s.v[ch] = (float)(c->channels[ch] * p);
            appear_ctracker_feed(&tr, s);
        }
        lk += tr.lookups;
        st->flags |= tr.flags;
        for (ch = 0; ch < 3; ++ch) {
            double w = free_flight ? (tr.collided ? 0.0 : tr.weight.v[ch]) : tr.T.v[ch];
            s1[ch] += w; s2[ch] += w * w;
            if (free_flight) {   /* E[w sigma_i(t) 1{coll}] + E[w 1{pass}] = 1 */
                double sg = (double)(float)(c->channels[ch] * ac_prof_sigma(c->profile, tr.t));
                double e = tr.collided ? tr.weight.v[ch] * sg : tr.weight.v[ch];
                e1[ch] += e; e2[ch] += e * e;
            }
        }
    }
    for (ch = 0; ch < 3; ++ch) {
        double m = s1[ch] / n, me = e1[ch] / n;
        st->mean[ch] = m;
        st->se[ch] = sqrt(fmax(0.0, s2[ch] / n - m * m) / (n > 1 ? n - 1 : 1));
        st->energy[ch] = me;
        st->energy_se[ch] = sqrt(fmax(0.0, e2[ch] / n - me * me) / (n > 1 ? n - 1 : 1));
    }
    st->lookups = lk / n;
}
static int ac_cmd_chromatic(const ac_config *c)
{
    appear_majorant_segment seg[64];
    static const int kinds[4] = { APPEAR_TRACK_RATIO, APPEAR_TRACK_NEXT_FLIGHT, APPEAR_TRACK_DELTA,
                                  APPEAR_TRACK_SPECTRAL };
    static const char *const kn[4] = { "ratio", "next-flight", "delta", "spectral" };
    double tau = ac_prof_tau(c->profile, 1.0);
    int k, ch;
    ac_segments(c->profile, c->segments, c->tightness, seg);
    if (c->csv) printf("profile,majorant,kind,channel,k,mean,se,exact,z,lookups,efficiency,"
                       "energy,energy_se,flags\n");
    else
        printf("transmittance --chromatic: profile %s x k = (%g, %g, %g), exact T_i = exp(-k_i tau), "
               "tau %.6f;\n  %s majorant, tightness %g, %d segment%s, %ld walks each\n"
               "  %-12s %2s %9s %9s %9s %7s %9s %11s %s\n", ac_profile_names[c->profile],
               c->channels[0], c->channels[1], c->channels[2], tau,
               c->per_channel ? "per-channel" : "common", c->tightness, c->segments,
               c->segments > 1 ? "s" : "", c->samples, "kind", "ch", "mean", "se", "exact", "z",
               "lookups", "efficiency", "energy (free flights: 1)");
    for (k = 0; k < 4; ++k) {
        ac_ctr_stats st;
        int want = c->kind == 7 || (c->kind == 9 ? kinds[k] == APPEAR_TRACK_SPECTRAL : kinds[k] == c->kind);
        if (!want) continue;
        ac_run_ctracker(c, kinds[k], seg, &st);
        for (ch = 0; ch < 3; ++ch) {
            double ex = exp(-c->channels[ch] * tau), var = st.se[ch] * st.se[ch] * (double)c->samples;
            double z = st.se[ch] > 0 ? (st.mean[ch] - ex) / st.se[ch] : (fabs(st.mean[ch] - ex) < 1e-6 ? 0 : 99.99);
            double eff = var > 0 ? 1.0 / (var * fmax(st.lookups, 1e-9)) : HUGE_VAL;
            int ff = kinds[k] == APPEAR_TRACK_DELTA || kinds[k] == APPEAR_TRACK_SPECTRAL;
            double ez = st.energy_se[ch] > 0 ? (st.energy[ch] - 1) / st.energy_se[ch]
                                             : (fabs(st.energy[ch] - 1) < 1e-6 ? 0 : 99.99);
            if (c->csv) {
                printf("%s,%s,%s,%d,%g,%.7f,%.7f,%.7f,%.3f,%.3f,%.6g,", ac_profile_names[c->profile],
                       c->per_channel ? "per-channel" : "common", kn[k], ch, c->channels[ch],
                       st.mean[ch], st.se[ch], ex, z, st.lookups, eff);
                if (ff) printf("%.7f,%.7f,%lu\n", st.energy[ch], st.energy_se[ch], st.flags);
                else printf(",,%lu\n", st.flags);
            } else {
                char e[32], en[64];
                if (isinf(eff)) strcpy(e, "exact"); else snprintf(e, sizeof e, "%.4g", eff);
                if (ff) snprintf(en, sizeof en, "%.5f +- %.2g (z %.2f)", st.energy[ch], st.energy_se[ch], ez);
                else strcpy(en, "-");
                printf("  %-12s %2d %9.6f %9.2g %9.6f %7.2f %9.2f %11s %s%s%s\n", ch ? "" : kn[k], ch,
                       st.mean[ch], st.se[ch], ex, z, st.lookups, e, en,
                       fabs(z) > 4 || (ff && fabs(ez) > 4) ? "  BIASED? |z| > 4" : "",
                       st.flags ? "  flags set!" : "");
            }
        }
    }
    if (!c->csv)
        printf("  (ratio, next-flight: mean of T_i; delta, spectral: mean of weight_i 1{passed} vs T_i, and\n"
               "   energy = E[weight_i sigma_i(t) 1{collided}] + E[weight_i 1{passed}]; "
               "efficiency 1 / (variance x lookups))\n");
    return 0;
}
/* single-channel homogeneous free flight against its closed forms */
static int ac_cmd_free_flight(const ac_config *c)
{
    enum { NU = 4096 };
    static float u[NU], uc[NU];
    check_rng g = check_rng_make(c->seed * 41u + 3u);
    float s = (float)c->sigma, d = (float)c->length;
    double sd = (double)s * (double)d, T = exp(-sd);
    double np = 0, ws = 0, t1 = 0, t2 = 0, nc, P, se, tm, tse, texact, t0, ns1, ns3, sink = 0;
    long i, n = c->samples, reps;
    appear_spectrum s3 = appear_spectrum_splat(s);
    for (i = 0; i < NU; ++i) { u[i] = (float)check_rand(&g); uc[i] = (float)check_rand(&g); }
    for (i = 0; i < n; ++i) {
        appear_medium_sample1 r;
        int k = appear_homogeneous_sample1(s, d, (float)check_rand(&g), &r);
        if (k == APPEAR_MEDIUM_PASSED) { np += 1; ws += r.weight; }
        else if (k == APPEAR_MEDIUM_SCATTERED) { t1 += r.t; t2 += (double)r.t * r.t; }
    }
    nc = (double)n - np;
    P = np / n; se = sqrt(fmax(P * (1 - P), 1e-300) / n);
    tm = nc > 0 ? t1 / nc : 0;
    tse = nc > 1 ? sqrt(fmax(0.0, t2 / nc - tm * tm) / (nc - 1)) : 0;
    texact = 1.0 / (double)s - (double)d * T / (-expm1(-sd));
    reps = n < NU ? NU : n;
    t0 = ac_now();
    for (i = 0; i < reps; ++i) {
        appear_medium_sample1 r;
        appear_homogeneous_sample1(s, d, u[i & (NU - 1)], &r);
        sink += r.t;
    }
    ns1 = (ac_now() - t0) * 1e9 / reps;
    t0 = ac_now();
    for (i = 0; i < reps; ++i) {
        appear_medium_sample r;
        appear_homogeneous_sample(s3, d, uc[i & (NU - 1)], u[i & (NU - 1)], &r);
        sink += r.t;
    }
    ns3 = (ac_now() - t0) * 1e9 / reps;
    if (c->csv) {
        printf("sigma,length,pass,pass_se,exact_pass,mean_pass_weight,mean_t,mean_t_se,"
               "exact_mean_t,ns_sample1,ns_sample\n"
               "%g,%g,%.7f,%.7f,%.7f,%.7f,%.7f,%.7f,%.7f,%.2f,%.2f\n", c->sigma, c->length,
               P, se, T, ws / n, tm, tse, texact, ns1, ns3);
    } else {
        printf("transmittance --free-flight: appear_homogeneous_sample1, sigma %g, "
               "segment length d %g, %ld flights\n", c->sigma, c->length, n);
        printf("  pass probability     %.6f +- %.2g  exact exp(-sigma d) = %.6f  z %.2f%s\n", P, se, T,
               (P - T) / se, fabs(P - T) > 4 * se ? "  BIASED? |z| > 4" : "");
        printf("  E[weight 1{passed}]  %.6f (weight 1 on a pass)\n", ws / n);
        if (nc > 1)
            printf("  mean collision t     %.6f +- %.2g  exact 1/sigma - d e^-sd / (1 - e^-sd) = %.6f  "
                   "z %.2f%s\n", tm, tse, texact, tse > 0 ? (tm - texact) / tse : 0.0,
                   fabs(tm - texact) > 4 * tse + 1e-6 * texact ? "  BIASED? |z| > 4" : "");
        printf("  ns per sample        sample1 %.2f, appear_homogeneous_sample (3 channels, same sigma) "
               "%.2f%s\n", ns1, ns3, sink == 1234.5 ? " " : "");
    }
    return 0;
}
static int ac_cmd_transmittance(const ac_config *c)
{
    if (c->chromatic) return ac_cmd_chromatic(c);
    if (c->free_flight) return ac_cmd_free_flight(c);
    appear_majorant_segment seg[64];
    double exact = exp(-ac_prof_tau(c->profile, 1.0)), ratio_eff = 0;
    ac_tr_stats st[APPEAR_TRACK_KIND_COUNT];
    static const char *const kn[APPEAR_TRACK_KIND_COUNT] = { "delta", "ratio (track-length)", "next-flight", "residual", "urm", "power-series", "ray-march" };
    int k, first = 1;
    char data[2048], *dp = data;
    *data = 0;
    ac_segments(c->profile, c->segments, c->tightness, seg);
    ac_run_tracker(c, APPEAR_TRACK_RATIO, seg, &st[APPEAR_TRACK_RATIO]);
    ratio_eff = st[APPEAR_TRACK_RATIO].var > 0 ? 1.0 / (st[APPEAR_TRACK_RATIO].var * st[APPEAR_TRACK_RATIO].lookups) : HUGE_VAL;
    if (c->csv) printf("profile,tightness,segments,kind,mean,se,exact,z,variance,lookups,efficiency,vs_ratio,flags\n");
    else {
        printf("transmittance: profile %s on [0, 1], tau %.6f, exact T = exp(-tau) = %.6f; majorant tightness %g, %d segment%s, %ld estimates each\n",
               ac_profile_names[c->profile], ac_prof_tau(c->profile, 1.0), exact, c->tightness, c->segments, c->segments > 1 ? "s" : "", c->samples);
        printf("  %-21s %9s %9s %7s %10s %9s %11s %9s\n", "kind", "mean", "se", "z", "variance", "lookups", "efficiency", "vs ratio");
    }
    for (k = 0; k < APPEAR_TRACK_KIND_COUNT; ++k) {
        double eff, z;
        if (c->kind != 7 && k != c->kind) continue;
        if (k != APPEAR_TRACK_RATIO) ac_run_tracker(c, k, seg, &st[k]);
        eff = st[k].var > 0 ? 1.0 / (st[k].var * fmax(st[k].lookups, 1e-9)) : HUGE_VAL;
        z = st[k].se > 0 ? (st[k].mean - exact) / st[k].se : (fabs(st[k].mean - exact) < 1e-6 ? 0 : HUGE_VAL);
        if (c->csv)
            printf("%s,%g,%d,%s,%.7f,%.7f,%.7f,%.3f,%.6g,%.3f,%.6g,%.6g,%lu\n", ac_profile_names[c->profile], c->tightness, c->segments, kn[k], st[k].mean,
                   st[k].se, exact, z, st[k].var, st[k].lookups, eff, eff / ratio_eff, (unsigned long)st[k].flags);
        else {
            char e1[32], e2[32];
            if (isinf(eff)) { strcpy(e1, "exact"); strcpy(e2, "-"); }
            else { snprintf(e1, sizeof e1, "%.4g", eff); snprintf(e2, sizeof e2, isinf(ratio_eff) ? "-" : "%.3gx", eff / ratio_eff); }
            printf("  %-21s %9.6f %9.2g %7.2f %10.4g %9.2f %11s %9s%s%s\n", kn[k], st[k].mean, st[k].se, isinf(z) ? 99.99 : z, st[k].var,
                   st[k].lookups, e1, e2, k == APPEAR_TRACK_RAY_MARCH ? "  (biased by design)" : fabs(z) > 4 && k != APPEAR_TRACK_RAY_MARCH ? "  BIASED? |z| > 4" : "",
                   st[k].flags ? "  flags set!" : "");
        }
        dp += sprintf(dp, "%d %g \"%s\"\n", k, isinf(eff) ? 0 : eff, kn[k]);
        first = 0;
    }
    (void)first;
    if (!c->csv) {
        printf("  (z = (mean - exact) / se; efficiency = 1 / (variance x mean lookups), per Kettunen et al. 2021)\n");
        if (st[0].ff && (c->kind == 7 || c->kind == 0))
            printf("  free flight (delta tracking): collision distances vs sigma(t) T(t) in 20 bins + escaped: chi2 p = %.3g %s\n", st[0].ff_p,
                   st[0].ff_p >= 0.01 ? "pass" : "FAIL");
    }
    if (c->val[O_PLOT]) {
        char script[512];
        snprintf(script, sizeof script, "set title 'transmittance estimators, profile %s, tightness %g'\nset logscale y\nset ylabel 'efficiency 1/(var x lookups)'\n"
                 "set style fill solid\nset boxwidth 0.6\nplot '-' using 1:2:xtic(3) with boxes notitle", ac_profile_names[c->profile], c->tightness);
        ac_plot(c->val[O_PLOT], script, data);
    }
    return 0;
}

/* ------------------------------------------------------------------------ */

static int ac_run(const ac_config *c)
{
    ad_model m;
    char err[512];
    int rc = 0;
    if (c->cmd == C_TRANSMITTANCE) return ac_cmd_transmittance(c);
    if (ac_make_model(c, &m, err, sizeof err)) { fprintf(stderr, "appear-check: %s\n", err); return 2; }
    switch (c->cmd) {
    case C_FURNACE: rc = ac_cmd_furnace(c, &m); break;
    case C_RECIPROCITY: rc = ac_cmd_reciprocity(c, &m); break;
    case C_CHI2: rc = ac_cmd_chi2(c, &m); break;
    case C_CONSISTENCY: rc = ac_cmd_consistency(c, &m); break;
    case C_LOBE: rc = ac_cmd_lobe(c, &m); break;
    default: rc = ac_cmd_bench(c, &m); break;
    }
    if (c->val[O_PLOT] && c->cmd != C_FURNACE && c->cmd != C_LOBE) printf("--plot: no curve for %s\n", ac_cmd_name[c->cmd]);
    ac_free_model(&m);
    return rc;
}

#ifndef APPEAR_CHECK_NO_MAIN
int main(int argc, char **argv)
{
    static ac_config c;
    char err[512];
    int r;
    if (argc == 2 && !strcmp(argv[1], "--version")) {
        printf("appear-check, appear.h %d.%d.%d, built with %s\n", APPEAR_VERSION_MAJOR,
               APPEAR_VERSION_MINOR, APPEAR_VERSION_PATCH, ac_build);
        return 0;
    }
    r = ac_parse(argc, argv, &c, err, sizeof err);
    if (r == 1) { ac_help(stdout, c.cmd, c.model); return 0; }
    if (r) { fprintf(stderr, "appear-check: %s\n", err); return 2; }
    return ac_run(&c);
}
#endif
