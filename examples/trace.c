/* examples/trace.c - a tiny path tracer that renders appear.h's validation
   scenes, using only the public API of appear.h, as a renderer would.

   Scene "furnace": under a uniform white environment (radiance 1), a
   lossless sphere of each model must render as exactly 1 everywhere (up to
   noise): a white Lambertian sphere (left) and a sphere of white,
   non-absorbing Henyey-Greenstein medium, g = 0.7 (right). Anything that
   loses or creates energy shows as a deviation from 1, which the program
   prints (mean and max deviation over the image).

   usage: trace [--out DIR] [--spp N] [--width W] [--threads T]
*/
#define _POSIX_C_SOURCE 200809L
#include "../appear.h"
#include "image_io.h"
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* ---- random numbers: PCG32, one stream per pixel ---- */
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
static float rng_f(rng *r) { return (float)(rng_u32(r) >> 8) * (1.0f / 16777216.0f); }
static rng rng_make(uint64_t seed, uint64_t stream)
{
    rng r;
    r.state = 0; r.inc = (stream << 1u) | 1u;
    rng_u32(&r); r.state += seed; rng_u32(&r);
    return r;
}

/* ---- scene ---- */
typedef enum { MAT_LAMBERT, MAT_MEDIUM_HG } mat_kind;
typedef struct {
    appear_vec3 c; float r;
    mat_kind kind;
    appear_lambert lambert;
    float sigma_t, albedo, g; /* medium: extinction, single-scattering albedo, HG g */
} sphere;

typedef struct {
    sphere s[4]; int n;
    float env; /* uniform environment radiance */
    appear_vec3 eye; float fov;
} scene;

/* nearest hit of the ray o + t d, t in (tmin, inf): returns t or -1 */
static float hit_sphere(const sphere *s, appear_vec3 o, appear_vec3 d, float tmin, int *inside)
{
    appear_vec3 oc = appear_sub(o, s->c);
    float b = appear_dot(oc, d), c = appear_dot(oc, oc) - s->r * s->r, disc = b * b - c, q, t0, t1;
    if (disc < 0) return -1;
    q = sqrtf(disc);
    t0 = -b - q; t1 = -b + q;
    if (t0 > tmin) { *inside = 0; return t0; }
    if (t1 > tmin) { *inside = 1; return t1; }
    return -1;
}

static float radiance(const scene *sc, appear_vec3 o, appear_vec3 d, rng *r)
{
    float throughput = 1.0f;
    int depth;
    for (depth = 0; depth < 64; ++depth) {
        int i, best = -1, inside = 0;
        float tbest = 1e30f;
        for (i = 0; i < sc->n; ++i) {
            int in;
            float t = hit_sphere(&sc->s[i], o, d, 1e-4f, &in);
            if (t > 0 && t < tbest) { tbest = t; best = i; inside = in; }
        }
        if (best < 0) return throughput * sc->env;
        {
            const sphere *s = &sc->s[best];
            appear_vec3 p = appear_add(o, appear_scale(d, tbest));
            appear_vec3 n = appear_scale(appear_sub(p, s->c), 1.0f / s->r);
            if (s->kind == MAT_LAMBERT) {
                appear_frame f = appear_frame_from_normal(n);
                appear_bsdf_sample bs;
                appear_vec3 wo = appear_frame_to_local(f, appear_neg(d));
                if (!appear_lambert_sample(&s->lambert, wo, rng_f(r), rng_f(r), rng_f(r), &bs)) return 0.0f;
                throughput *= bs.weight.v[0];
                o = p; d = appear_frame_to_world(f, bs.wi);
            } else if (!inside) {
                o = p; /* enter the medium: continue the same ray inside */
            } else {
                /* inside a homogeneous medium: sample a free flight */
                float t = -logf(1.0f - rng_f(r)) / s->sigma_t;
                if (t >= tbest) { o = p; continue; } /* leaves the sphere */
                o = appear_add(o, appear_scale(d, t));
                throughput *= s->albedo;
                {
                    appear_phase_sample ps;
                    if (!appear_hg_sample(s->g, appear_neg(d), rng_f(r), rng_f(r), &ps)) return 0.0f;
                    throughput *= ps.weight;
                    d = ps.wi;
                }
            }
            if (depth > 8) { /* Russian roulette */
                float q = throughput < 0.95f ? throughput : 0.95f;
                if (rng_f(r) >= q) return 0.0f;
                throughput /= q;
            }
        }
    }
    return 0.0f;
}

typedef struct {
    const scene *sc; int w, h, spp;
    float *img; int next_row; pthread_mutex_t lock; int rows_done;
    double t0;
} job;

static double now_s(void) { struct timespec ts; clock_gettime(CLOCK_MONOTONIC, &ts); return ts.tv_sec + 1e-9 * ts.tv_nsec; }

static void *worker(void *arg)
{
    job *jb = (job *)arg;
    for (;;) {
        int y, x, k;
        pthread_mutex_lock(&jb->lock);
        y = jb->next_row++;
        pthread_mutex_unlock(&jb->lock);
        if (y >= jb->h) break;
        for (x = 0; x < jb->w; ++x) {
            rng r = rng_make(1234, (uint64_t)y * jb->w + x);
            double sum = 0;
            for (k = 0; k < jb->spp; ++k) {
                float px = (x + rng_f(&r)) / jb->w * 2 - 1, py = 1 - (y + rng_f(&r)) / jb->h * 2;
                float a = (float)jb->w / jb->h, t = tanf(jb->sc->fov * 0.5f);
                appear_vec3 d = appear_normalize(appear_vec3_make(px * t * a, py * t, -1.0f));
                sum += radiance(jb->sc, jb->sc->eye, d, &r);
            }
            for (k = 0; k < 3; ++k) jb->img[3 * ((size_t)y * jb->w + x) + k] = (float)(sum / jb->spp);
        }
        pthread_mutex_lock(&jb->lock);
        ++jb->rows_done;
        if (isatty(2) && (100 * jb->rows_done / jb->h) != (100 * (jb->rows_done - 1) / jb->h)) {
            double el = now_s() - jb->t0, eta = el / jb->rows_done * (jb->h - jb->rows_done);
            int bar = 40 * jb->rows_done / jb->h, i;
            fprintf(stderr, "\r[");
            for (i = 0; i < 40; ++i) fputc(i < bar ? '#' : '.', stderr);
            fprintf(stderr, "] %3d%%  %.1fs elapsed, ~%.1fs left ", 100 * jb->rows_done / jb->h, el, eta);
        }
        pthread_mutex_unlock(&jb->lock);
    }
    return NULL;
}

int main(int argc, char **argv)
{
    const char *out = "examples/out";
    int w = 320, h = 160, spp = 64, threads = 2, i;
    scene sc;
    job jb;
    pthread_t tid[64];
    char path[512];
    const char *names[3] = { "R", "G", "B" };
    double mean = 0, maxdev = 0;
    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--out") && i + 1 < argc) out = argv[++i];
        else if (!strcmp(argv[i], "--spp") && i + 1 < argc) spp = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--width") && i + 1 < argc) { w = atoi(argv[++i]); h = w / 2; }
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc) threads = atoi(argv[++i]);
        else { fprintf(stderr, "usage: %s [--out DIR] [--spp N] [--width W] [--threads T]\n", argv[0]); return 2; }
    }
    if (threads < 1) threads = 1;
    if (threads > 64) threads = 64;
    memset(&sc, 0, sizeof sc);
    sc.env = 1.0f; sc.eye = appear_vec3_make(0, 0, 4.0f); sc.fov = 0.9f;
    sc.s[0].c = appear_vec3_make(-1.1f, 0, 0); sc.s[0].r = 1.0f; sc.s[0].kind = MAT_LAMBERT;
    sc.s[0].lambert = appear_lambert_make(appear_spectrum_splat(1.0f));
    sc.s[1].c = appear_vec3_make(1.1f, 0, 0); sc.s[1].r = 1.0f; sc.s[1].kind = MAT_MEDIUM_HG;
    sc.s[1].sigma_t = 4.0f; sc.s[1].albedo = 1.0f; sc.s[1].g = 0.7f;
    sc.n = 2;

    jb.sc = &sc; jb.w = w; jb.h = h; jb.spp = spp; jb.next_row = 0; jb.rows_done = 0;
    jb.img = (float *)calloc((size_t)w * h * 3, sizeof(float));
    pthread_mutex_init(&jb.lock, NULL);
    jb.t0 = now_s();
    fprintf(stderr, "furnace: %dx%d, %d spp, %d threads\n", w, h, spp, threads);
    for (i = 0; i < threads; ++i) pthread_create(&tid[i], NULL, worker, &jb);
    for (i = 0; i < threads; ++i) pthread_join(tid[i], NULL);
    fprintf(stderr, "\n");
    for (i = 0; i < w * h; ++i) {
        double v = jb.img[3 * i];
        mean += v;
        if (fabs(v - 1.0) > maxdev) maxdev = fabs(v - 1.0);
    }
    mean /= (double)w * h;
    mkdir(out, 0777);
    snprintf(path, sizeof path, "%s/furnace.exr", out);
    if (img_write_exr(path, w, h, 3, names, jb.img)) { fprintf(stderr, "cannot write %s\n", path); return 1; }
    printf("wrote %s\n", path);
    snprintf(path, sizeof path, "%s/furnace.png", out);
    if (img_write_png(path, w, h, jb.img, 0.8f)) { fprintf(stderr, "cannot write %s\n", path); return 1; }
    printf("wrote %s (exposure 0.8, so 1.0 shows as light grey)\n", path);
    printf("furnace: mean %.5f (expected 1), max pixel deviation %.4f at %d spp, %.1f s\n", mean, maxdev, spp, now_s() - jb.t0);
    free(jb.img);
    return 0;
}
