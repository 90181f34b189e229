/* examples/trace.c - renders appear.h's validation scenes (examples/scenes.c)
   with the small path tracer of examples/tracer.c, writing EXR + PNG.

   usage: trace [--out DIR] [--scene NAME]... [--spp N] [--scale S]
                [--threads T] [--no-nee] [--list]
     --scene   render only the named scene(s) (default: all of them)
     --spp     samples per pixel (default per scene, see below)
     --scale   image size multiplier (default 1; 2 = twice the width)
   `make demo` runs it with the defaults (about a minute on two cores);
   e.g. `./build/trace --scale 2 --spp 1024` for README-quality images.

   For the furnace it prints, per object, the mean and the largest pixel
   deviation from 1 and the expectation (= 1 lossless, <= 1 lossy). */
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
    { "fibers",  320, 200, 48, 1.0f },
};

static void furnace_report(const tracer_scene *sc, const tracer_image *img)
{
    int s;
    for (s = 0; s < sc->n_shapes; ++s) {
        double sum = 0, maxdev = 0, maxv = 0;
        long n = 0, i;
        for (i = 0; i < (long)img->w * img->h; ++i) {
            double v;
            if (img->id[i] != s) continue;
            v = (img->rgb[3 * i] + img->rgb[3 * i + 1] + img->rgb[3 * i + 2]) / 3.0;
            sum += v; ++n;
            if (fabs(v - 1.0) > maxdev) maxdev = fabs(v - 1.0);
            if (v > maxv) maxv = v;
        }
        if (!n) continue;
        printf("  %-34s mean %.4f  max|v-1| %.4f  max %.4f  (expect %s)\n", sc->shapes[s].label ? sc->shapes[s].label : "?",
               sum / n, maxdev, maxv,
               sc->shapes[s].expect == TRACER_EXPECT_ONE ? "1" : sc->shapes[s].expect == TRACER_EXPECT_AT_MOST_ONE ? "<= 1" : "-");
    }
}

int main(int argc, char **argv)
{
    const char *out = "examples/out";
    const char *only[16];
    int n_only = 0, spp = 0, threads = 0, no_nee = 0, i, k, rc = 0;
    float scale = 1.0f;
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--out") && i + 1 < argc) out = argv[++i];
        else if (!strcmp(argv[i], "--scene") && i + 1 < argc && n_only < 16) only[n_only++] = argv[++i];
        else if (!strcmp(argv[i], "--spp") && i + 1 < argc) spp = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--scale") && i + 1 < argc) scale = (float)atof(argv[++i]);
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc) threads = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--no-nee")) no_nee = 1;
        else if (!strcmp(argv[i], "--list")) {
            for (k = 0; tracer_scene_names[k]; ++k) printf("%-8s %s\n", tracer_scene_names[k], tracer_scene_expectation(tracer_scene_names[k]));
            return 0;
        } else {
            fprintf(stderr, "usage: %s [--out DIR] [--scene NAME]... [--spp N] [--scale S] [--threads T] [--no-nee] [--list]\n", argv[0]);
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
        int j, sel = n_only == 0;
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
        if (tracer_render(&sc, &opt, &img)) { fprintf(stderr, "render failed\n"); return 1; }
        if (tracer_write(&img, out, name, d->exposure)) { fprintf(stderr, "cannot write %s/%s.{exr,png}\n", out, name); rc = 1; }
        else printf("  wrote %s/%s.exr and .png in %.1f s%s\n", out, name, img.seconds, img.nonfinite ? " (NON-FINITE SAMPLES!)" : "");
        if (img.nonfinite) { printf("  %ld non-finite samples\n", img.nonfinite); rc = 1; }
        if (!strcmp(name, "furnace")) furnace_report(&sc, &img);
        tracer_image_free(&img);
    }
    return rc;
}
