/* examples/trace.c - renders appear.h's validation scenes (examples/scenes.c)
   with the small path tracer of examples/tracer.c, writing EXR + PNG.

   usage: trace [--out DIR] [--scene NAME]... [--spp N] [--scale S]
                [--threads T] [--no-nee] [--list]
     --scene   render only the named scene(s) (default: all of this build's
               kind: the RGB scenes, or with TRACER_SPECTRAL metals and prism)
     --spp     samples per pixel (default per scene, see below)
     --scale   image size multiplier (default 1; 2 = twice the width)
   `make demo` runs it with the defaults (about a minute on two cores);
   e.g. `./build/trace --scale 2 --spp 1024` for README-quality images.

   For the furnaces ("furnace", "openpbr_furnace") it prints, per object,
   the mean +- its standard error, mean - 1, the largest pixel, where the
   object is in the image, and flags a mean that breaks its expectation
   (= 1 lossless, <= 1 lossy) by more than 4 standard errors plus the
   model's stated error where the scene sets one (exit status 1). For "layered" (appear_coated) it also
   renders "layered_ref" (the same spheres through the reference walk,
   appear_layered) with the same options, writes layered_diff (|fast - ref|)
   and prints the mean differences. `trace --help` lists scenes and options.

   The spectral scenes (tracer_scene_is_spectral: "metals", "prism") render
   twice: in spectral mode (NAME_spectral) and in RGB mode (NAME_rgb; for
   "metals" also NAME_f82, the metals' F82 form), and "metals" writes
   metals_diff (|spectral - RGB eta, k|) and prints per metal the mean
   difference. This file built with TRACER_SPECTRAL (build/trace-spectral,
   4 wavelengths a path) renders them by default; the RGB build (build/trace)
   renders the other scenes by default and these on request (3 wavelengths a
   path). */
#define _POSIX_C_SOURCE 200809L
#include "tracer.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct { const char *name; int w, h, spp; float exposure; } scene_defaults;
static const scene_defaults defaults[] = {
    { "furnace", 320, 200, 32, 0.8f },
    { "gallery", 400, 240, 48, 1.0f },
    { "cloud",   320, 240, 48, 1.0f },
    { "diffuse", 480, 160, 64, 1.0f },
    { "fibers",  320, 200, 48, 1.0f },
    { "chroma",  320, 240, 48, 1.0f },
    { "layered", 400, 120, 384, 1.0f }, /* and "layered_ref", the same size and spp */
    { "openpbr", 400, 240, 64, 1.0f },
    { "openpbr_furnace", 320, 200, 64, 0.8f },
    { "metals",  480, 112, 64, 1.0f },   /* spectral, RGB eta k, RGB F82 */
    { "prism",   320, 200, 256, 1.0f },  /* spectral, RGB */
};

/* The "layered" pair: the same spheres through appear_coated (fast) and appear_layered (ref,
   the reference random walk). Writes DIR/layered_diff.{exr,png}: |fast - ref| per pixel and
   channel (the EXR's "var": the per-sample variance of the difference, var_fast + var_ref), the
   PNG at DIFF_SCALE times the renders' exposure. Prints the mean |fast - ref| over the image and
   over the spheres, absolute and relative to the reference's mean there, next to what the noise of
   the two renders alone gives (a normal difference: sqrt(2 / pi) sqrt((var_fast + var_ref) / spp)
   per pixel), and per sphere the means with their signed difference and its standard error. */
#define DIFF_SCALE 8.0f
static int layered_compare(const tracer_scene *sc, const tracer_image *fast,
                           const tracer_image *ref, int spp, const char *out, float exposure)
{
    tracer_image d = *fast;
    long n = (long)fast->w * fast->h, i;
    double ad[2] = { 0, 0 }, rm[2] = { 0, 0 }, nz[2] = { 0, 0 }, cnt[2] = { 0, 0 };
    int s, rc;
    d.rgb = (float *)malloc((size_t)n * 3 * sizeof(float));
    d.var = (float *)malloc((size_t)n * 3 * sizeof(float));
    if (!d.rgb || !d.var) { free(d.rgb); free(d.var); return 1; }
    d.nonfinite = fast->nonfinite + ref->nonfinite;
    for (i = 0; i < n; ++i) {
        int c, id = ref->id[i], sphere = id >= 0 && sc->shapes[id].label != NULL, k;
        for (c = 0; c < 3; ++c) {
            long j = 3 * i + c;
            double v = (double)fast->var[j] + ref->var[j];
            d.rgb[j] = fabsf(fast->rgb[j] - ref->rgb[j]);
            d.var[j] = (float)v;
            for (k = 0; k <= sphere; ++k) { /* [0]: the image, [1]: the spheres */
                ad[k] += d.rgb[j] / 3.0; rm[k] += ref->rgb[j] / 3.0;
                nz[k] += sqrt(2.0 / 3.14159265358979 * v / spp) / 3.0;
            }
        }
        cnt[0] += 1; cnt[1] += sphere;
    }
    printf("  fast (layered) against the reference walk (layered_ref), mean over pixels and "
           "channels:\n");
    for (s = 0; s < 2; ++s)
        if (cnt[s] > 0)
            printf("    %-8s mean |fast - ref| %.5f = %.2f%% of the reference's mean %.4f "
                   "(noise alone: %.5f)\n", s ? "spheres" : "image", ad[s] / cnt[s],
                   100.0 * ad[s] / rm[s], rm[s] / cnt[s], nz[s] / cnt[s]);
    /* per sphere: SE from the channels' mean variance, a bound on the channel mean's */
    printf("    %-22s %8s %8s %9s %8s\n", "sphere (channel mean)", "fast", "ref", "fast-ref",
           "+- SE");
    for (s = 0; s < sc->n_shapes; ++s) {
        double f = 0, r = 0, v = 0;
        long m = 0;
        if (!sc->shapes[s].label) continue;
        for (i = 0; i < n; ++i) {
            int c;
            if (ref->id[i] != s) continue;
            for (c = 0; c < 3; ++c) {
                f += fast->rgb[3 * i + c] / 3.0; r += ref->rgb[3 * i + c] / 3.0;
                v += ((double)fast->var[3 * i + c] + ref->var[3 * i + c]) / 3.0;
            }
            ++m;
        }
        if (!m) continue;
        printf("    %-22s %8.4f %8.4f %+8.2f%% %7.2f%%\n", sc->shapes[s].label, f / m, r / m,
               100.0 * (f - r) / r, 100.0 * sqrt(v / spp) / r);
    }
    printf("    (the difference image: %s/layered_diff.exr, and .png at %g x the exposure)\n", out,
           DIFF_SCALE);
    rc = tracer_write(&d, out, "layered_diff", exposure * DIFF_SCALE);
    if (rc) fprintf(stderr, "cannot write %s/layered_diff.{exr,png}\n", out);
    free(d.rgb); free(d.var);
    return rc != 0;
}

/* Per object: the mean over its pixels with the standard error of that mean
   (pixels are independent Monte Carlo estimates, so SE = sd / sqrt(pixels)),
   mean - 1, and a verdict against the expectation that flags only a mean
   beyond 4 SE plus the object's stated model error (tracer_shape.tol, 0 for
   an exact model; printed when set):
   the largest pixel of a Monte Carlo image is noise (Russian roulette and
   caustic paths make single pixels far above 1 in a lossless object), not a
   test. The position column tells which object is which in the image. */
static int furnace_report(const tracer_scene *sc, const tracer_image *img)
{
    int s, flagged = 0;
    printf("  %-34s %8s %8s %8s %8s  %-7s %-17s %s\n", "object", "mean", "+- SE", "mean-1", "max px",
           "expect", "x range (cx,cy)", "verdict");
    for (s = 0; s < sc->n_shapes; ++s) {
        double sum = 0, sum2 = 0, maxv = 0, sx = 0, sy = 0, mean, se;
        long n = 0, i;
        int x0 = img->w, x1 = -1, e = sc->shapes[s].expect;
        double tol = sc->shapes[s].tol;
        const char *verdict = "-", *rel;
        char vbuf[64], tbuf[24];
        int breaks;
        for (i = 0; i < (long)img->w * img->h; ++i) {
            double v;
            int x = (int)(i % img->w);
            if (img->id[i] != s) continue;
            v = (img->rgb[3 * i] + img->rgb[3 * i + 1] + img->rgb[3 * i + 2]) / 3.0;
            sum += v; sum2 += v * v; ++n;
            if (v > maxv) maxv = v;
            x0 = x < x0 ? x : x0; x1 = x > x1 ? x : x1;
            sx += x; sy += (double)(i / img->w);
        }
        if (!n) continue;
        mean = sum / n;
        se = n > 1 ? sqrt(fmax(0.0, (sum2 / n - mean * mean) / (n - 1))) : 0;
        tbuf[0] = '\0';
        if (tol > 0.0) snprintf(tbuf, sizeof tbuf, " + %g", tol); /* the model's stated error */
        breaks = e == TRACER_EXPECT_ONE ? fabs(mean - 1) > 4 * se + 1e-6 + tol
                                        : mean > 1 + 4 * se + 1e-6 + tol;
        if (e == TRACER_EXPECT_ONE) rel = breaks ? "|mean - 1| >" : "|mean - 1| <=";
        else rel = breaks ? "mean > 1 +" : "mean <= 1 +";
        if (e != TRACER_EXPECT_NONE) {
            snprintf(vbuf, sizeof vbuf, "%s%s 4 SE%s%s", breaks ? "BREAKS: " : "ok (", rel, tbuf,
                     breaks ? "" : ")");
            verdict = vbuf;
            flagged |= breaks;
        }
        printf("  %-34s %8.4f %8.4f %+8.4f %8.3f  %-7s %4d..%-4d (%3.0f,%3.0f) %s\n", sc->shapes[s].label ? sc->shapes[s].label : "?", mean, se, mean - 1, maxv,
               e == TRACER_EXPECT_ONE ? "1" : e == TRACER_EXPECT_AT_MOST_ONE ? "<= 1" : "-", x0, x1, sx / n, sy / n, verdict);
    }
    printf("  (max px is one pixel's Monte Carlo estimate: Russian roulette and caustic paths put single pixels above 1\n"
           "   in a lossless object; only the mean is judged, against 4 standard errors)\n");
    return flagged;
}

/* Renders sc with opt and writes DIR/NAME.{exr,png}; 0 on success. The caller frees img. */
static int render_write(const tracer_scene *sc, const tracer_options *opt, const char *out,
                        const char *name, float exposure, tracer_image *img)
{
    if (opt->spectral)
        printf("  %s: spectral, %d wavelengths a path\n", name, APPEAR_SPECTRUM_SAMPLES);
    else printf("  %s: RGB\n", name);
    fflush(stdout);
    if (tracer_render(sc, opt, img)) {
        fprintf(stderr, "render of %s failed\n", name);
        return 1;
    }
    if (tracer_write(img, out, name, exposure)) {
        fprintf(stderr, "cannot write %s/%s.{exr,png}\n", out, name);
        return 1;
    }
    printf("  wrote %s/%s.exr and .png in %.1f s%s\n", out, name, img->seconds,
           img->nonfinite ? " (NON-FINITE SAMPLES!)" : "");
    if (img->nonfinite) printf("  %ld non-finite samples\n", img->nonfinite);
    return img->nonfinite != 0;
}

/* Per labelled sphere of sc (its pixels: id), the means of a and b per channel, their signed
   difference a - b relative to b with its standard error (from the pixels' per-sample variances),
   the mean and largest |a - b| over its pixels and channels, and the mean |a - b| that the noise
   of the two renders alone gives (a normal difference: sqrt(2 / pi) sqrt((var_a + var_b) / spp)
   per pixel). Both are computed as for independent renders, and overstate here: a spectral and
   an RGB render of one scene draw the same random numbers (the path's wavelength draw takes the
   place of its channel draw), which correlates them, and spectral mode stratifies the wavelengths
   over a pixel's samples, so its per-sample variance overstates its mean's. */
static void compare_spheres(const tracer_scene *sc, const tracer_image *a, const tracer_image *b,
                            int spp, const char *an, const char *bn)
{
    long n = (long)a->w * a->h, i;
    int s, c;
    printf("    %-15s %-24s %-24s %-30s %8s %8s %8s\n", "sphere", an, bn,
           "(a - b) / b % (r g b)", "mean|d|", "noise", "max|d|");
    for (s = 0; s < sc->n_shapes; ++s) {
        double ma[3] = { 0, 0, 0 }, mb[3] = { 0, 0, 0 }, v[3] = { 0, 0, 0 }, ad = 0, nz = 0, mx = 0;
        long m = 0;
        if (!sc->shapes[s].label) continue;
        for (i = 0; i < n; ++i) {
            if (a->id[i] != s) continue;
            for (c = 0; c < 3; ++c) {
                long j = 3 * i + c;
                double d = fabs((double)a->rgb[j] - b->rgb[j]), vv = (double)a->var[j] + b->var[j];
                ma[c] += a->rgb[j]; mb[c] += b->rgb[j]; v[c] += vv;
                ad += d / 3.0; nz += sqrt(2.0 / 3.14159265358979 * vv / spp) / 3.0;
                mx = d > mx ? d : mx;
            }
            ++m;
        }
        if (!m) continue;
        printf("    %-15s %7.4f %7.4f %7.4f  %7.4f %7.4f %7.4f ", sc->shapes[s].label, ma[0] / m,
               ma[1] / m, ma[2] / m, mb[0] / m, mb[1] / m, mb[2] / m);
        for (c = 0; c < 3; ++c) /* SE of the difference of the means, relative to b's */
            printf(" %+5.2f+-%4.2f", 100.0 * (ma[c] - mb[c]) / mb[c],
                   100.0 * sqrt(v[c] / spp) / mb[c]);
        printf(" %8.5f %8.5f %8.4f\n", ad / m, nz / m, mx);
    }
}

/* A spectral scene: spectral mode, then RGB mode; "metals" also the F82 form and the
   difference image. Returns 0 on success. */
static int spectral_scene(const char *name, tracer_scene *sc, tracer_options opt, const char *out,
                          float exposure)
{
    tracer_image spec, rgb, f82;
    char nm[64];
    int rc = 0, i;
    opt.spectral = 1;
    snprintf(nm, sizeof nm, "%s_spectral", name);
    if (render_write(sc, &opt, out, nm, exposure, &spec)) { tracer_image_free(&spec); return 1; }
    opt.spectral = 0;
    snprintf(nm, sizeof nm, "%s_rgb", name);
    rc |= render_write(sc, &opt, out, nm, exposure, &rgb);
    if (!rc && !strcmp(name, "metals")) {
        tracer_image d = spec;
        long n = (long)spec.w * spec.h, j;
        for (i = 0; i < sc->n_mats; ++i) /* the RGB form through appear_conductor_make_f82 */
            if (sc->mats[i].kind == MAT_METAL) sc->mats[i].metal_form = TRACER_METAL_F82;
        snprintf(nm, sizeof nm, "%s_f82", name);
        rc |= render_write(sc, &opt, out, nm, exposure, &f82);
        /* |spectral - RGB eta, k|; its EXR's var: the difference's, var_spec + var_rgb */
        d.rgb = (float *)malloc((size_t)n * 3 * sizeof(float));
        d.var = (float *)malloc((size_t)n * 3 * sizeof(float));
        if (!rc && d.rgb && d.var) {
            for (j = 0; j < 3 * n; ++j) {
                d.rgb[j] = fabsf(spec.rgb[j] - rgb.rgb[j]);
                d.var[j] = spec.var[j] + rgb.var[j];
            }
            printf("  per sphere, mean over its pixels (channels r g b; +- the standard error of "
                   "the difference):\n");
            compare_spheres(sc, &spec, &rgb, opt.spp, "spectral", "RGB eta, k");
            compare_spheres(sc, &spec, &f82, opt.spp, "spectral", "RGB F82");
            snprintf(nm, sizeof nm, "%s_diff", name);
            if (tracer_write(&d, out, nm, exposure * DIFF_SCALE)) {
                fprintf(stderr, "cannot write %s/%s.{exr,png}\n", out, nm);
                rc = 1;
            } else {
                printf("  wrote %s/%s.exr and .png: |spectral - RGB eta, k| (the PNG at %g x the "
                       "exposure)\n", out, nm, DIFF_SCALE);
            }
        } else {
            rc = 1;
        }
        free(d.rgb); free(d.var);
        tracer_image_free(&f82);
    }
    tracer_image_free(&spec);
    tracer_image_free(&rgb);
    return rc;
}

static void usage(FILE *f, const char *argv0)
{
    int k;
    fprintf(f, "usage: %s [--out DIR] [--scene NAME]... [--spp N] [--scale S] [--threads T] [--no-nee] [--list] [--help]\n"
               "  --out DIR      output directory for NAME.exr and NAME.png (default: examples/out)\n"
               "  --scene NAME   render only this scene; repeat for several (default: the %s scenes)\n"
               "  --spp N        samples per pixel (default: per scene, below)\n"
               "  --scale S      image size multiplier in (0, 16] (default: 1)\n"
               "  --threads T    render threads (default: the number of CPUs)\n"
               "  --no-nee       no next-event estimation, BSDF sampling only (default: off)\n"
               "  --list         print the scenes and what each one shows, then exit\n"
               "  --help         this help\n"
               "scenes (default size at scale 1, spp):\n", argv0,
            TRACER_SPECTRAL ? "spectral (metals, prism)" : "RGB (all but metals, prism)");
    for (k = 0; tracer_scene_names[k]; ++k) {
        int j;
        const scene_defaults *d = NULL;
        for (j = 0; j < (int)(sizeof defaults / sizeof defaults[0]); ++j) if (!strcmp(defaults[j].name, tracer_scene_names[k])) d = &defaults[j];
        if (d) fprintf(f, "  %-8s %dx%d, %d spp: %s\n", d->name, d->w, d->h, d->spp, tracer_scene_expectation(d->name));
        else fprintf(f, "  %-8s %s\n", tracer_scene_names[k], tracer_scene_expectation(tracer_scene_names[k]));
    }
    fprintf(f, "The furnace scenes print per object its mean +- standard error and mean - 1, and flag a mean\n"
               "beyond 4 SE (plus the model's stated error, where set) of its expectation (exit status 1 when\n"
               "one does). A spectral scene renders in spectral mode (%d wavelengths a path) and in RGB mode.\n"
               "`make demo` renders all scenes with the defaults (build/trace, then build/trace-spectral).\n",
            APPEAR_SPECTRUM_SAMPLES);
}

static int need_value(int i, int argc, char **argv)
{
    if (i + 1 < argc) return 1;
    fprintf(stderr, "%s: option %s: missing value (try --help)\n", argv[0], argv[i]);
    return 0;
}
static int parse_num(const char *argv0, const char *opt, const char *s, double lo, double hi, double *v)
{
    char *end;
    *v = strtod(s, &end);
    if (!*s || *end || !(*v >= lo && *v <= hi)) {
        fprintf(stderr, "%s: option %s: '%s' is not a number in [%g, %g]\n", argv0, opt, s, lo, hi);
        return 0;
    }
    return 1;
}

int main(int argc, char **argv)
{
    const char *out = "examples/out";
    const char *only[16];
    int n_only = 0, spp = 0, threads = 0, no_nee = 0, i, k, rc = 0;
    float scale = 1.0f;
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    for (i = 1; i < argc; ++i) {
        double v;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) { usage(stdout, argv[0]); return 0; }
        else if (!strcmp(argv[i], "--out")) { if (!need_value(i, argc, argv)) return 2; out = argv[++i]; }
        else if (!strcmp(argv[i], "--scene")) {
            if (!need_value(i, argc, argv)) return 2;
            for (k = 0; tracer_scene_names[k] && strcmp(tracer_scene_names[k], argv[i + 1]); ++k) {}
            if (!tracer_scene_names[k]) { fprintf(stderr, "%s: option --scene: unknown scene '%s' (see --list)\n", argv[0], argv[i + 1]); return 2; }
            if (n_only >= 16) { fprintf(stderr, "%s: option --scene: at most 16\n", argv[0]); return 2; }
            only[n_only++] = argv[++i];
        }
        else if (!strcmp(argv[i], "--spp")) { if (!need_value(i, argc, argv) || !parse_num(argv[0], "--spp", argv[i + 1], 1, 1e6, &v)) return 2; spp = (int)v; ++i; }
        else if (!strcmp(argv[i], "--scale")) { if (!need_value(i, argc, argv) || !parse_num(argv[0], "--scale", argv[i + 1], 1e-3, 16, &v)) return 2; scale = (float)v; ++i; }
        else if (!strcmp(argv[i], "--threads")) { if (!need_value(i, argc, argv) || !parse_num(argv[0], "--threads", argv[i + 1], 1, 1024, &v)) return 2; threads = (int)v; ++i; }
        else if (!strcmp(argv[i], "--no-nee")) no_nee = 1;
        else if (!strcmp(argv[i], "--list")) {
            for (k = 0; tracer_scene_names[k]; ++k) printf("%-8s %s\n", tracer_scene_names[k], tracer_scene_expectation(tracer_scene_names[k]));
            return 0;
        } else {
            fprintf(stderr, "%s: unknown option '%s' (try --help)\n", argv[0], argv[i]);
            return 2;
        }
    }
    if (threads <= 0) threads = ncpu > 0 ? (int)ncpu : 2;
    if (!(scale > 0.0f && scale <= 16.0f)) scale = 1.0f;
    for (k = 0; tracer_scene_names[k]; ++k) {
        const char *name = tracer_scene_names[k];
        static tracer_scene sc;
        tracer_image img;
        tracer_options opt;
        const scene_defaults *d = NULL;
        /* by default the build's own kind of scene: spectral ones in the spectral build */
        int j, sel = n_only == 0 && tracer_scene_is_spectral(name) == TRACER_SPECTRAL;
        for (j = 0; j < n_only; ++j) sel |= !strcmp(only[j], name);
        if (!sel) continue;
        for (j = 0; j < (int)(sizeof defaults / sizeof defaults[0]); ++j) if (!strcmp(defaults[j].name, name)) d = &defaults[j];
        if (!d || tracer_scene_build(&sc, name)) { fprintf(stderr, "scene %s not available\n", name); rc = 1; continue; }
        memset(&opt, 0, sizeof opt);
        opt.w = (int)(d->w * scale); opt.h = (int)(d->h * scale);
        opt.spp = spp > 0 ? spp : d->spp;
        opt.threads = threads; opt.seed = 1234; opt.progress = 1; opt.no_nee = no_nee;
        printf("%s: %dx%d, %d spp, %d threads -- %s\n", name, opt.w, opt.h, opt.spp, threads, tracer_scene_expectation(name));
        fflush(stdout);
        if (tracer_scene_is_spectral(name)) {
            rc |= spectral_scene(name, &sc, opt, out, d->exposure);
            continue;
        }
        if (tracer_render(&sc, &opt, &img)) { fprintf(stderr, "render failed\n"); return 1; }
        if (tracer_write(&img, out, name, d->exposure)) { fprintf(stderr, "cannot write %s/%s.{exr,png}\n", out, name); rc = 1; }
        else printf("  wrote %s/%s.exr and .png in %.1f s%s\n", out, name, img.seconds, img.nonfinite ? " (NON-FINITE SAMPLES!)" : "");
        if (img.nonfinite) { printf("  %ld non-finite samples\n", img.nonfinite); rc = 1; }
        if (!strcmp(name, "furnace") || !strcmp(name, "openpbr_furnace"))
            rc |= furnace_report(&sc, &img);
        if (!strcmp(name, "layered")) { /* its reference twin, the same options, the difference */
            static tracer_scene rs;
            tracer_image ref;
            const char *rn = "layered_ref";
            if (tracer_scene_build(&rs, rn)) {
                fprintf(stderr, "scene %s not available\n", rn);
                rc = 1;
            } else {
                printf("%s: the same, through the reference walk (appear_layered)\n", rn);
                fflush(stdout);
                if (tracer_render(&rs, &opt, &ref)) {
                    fprintf(stderr, "render failed\n");
                    return 1;
                }
                if (tracer_write(&ref, out, rn, d->exposure)) {
                    fprintf(stderr, "cannot write %s/%s.{exr,png}\n", out, rn);
                    rc = 1;
                } else {
                    printf("  wrote %s/%s.exr and .png in %.1f s%s\n", out, rn, ref.seconds,
                           ref.nonfinite ? " (NON-FINITE SAMPLES!)" : "");
                }
                if (ref.nonfinite) { printf("  %ld non-finite samples\n", ref.nonfinite); rc = 1; }
                rc |= layered_compare(&rs, &img, &ref, opt.spp, out, d->exposure);
                tracer_image_free(&ref);
            }
        }
        tracer_image_free(&img);
    }
    return rc;
}
