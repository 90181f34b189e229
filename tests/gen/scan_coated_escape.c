/* tests/gen/scan_coated_escape.c - the accuracy of appear_coated's escape tables
   (tests/gen/gen_coated_escape.c) between their nodes:
       cc -O2 -I. tests/gen/scan_coated_escape.c -o build/scan_coated_escape -lm
       ./build/scan_coated_escape [points] [walks]
   At random points with every coordinate half-way between two nodes (mu, alpha_b, alpha_c,
   eta: the cells' centres, where linear interpolation errs most), the escape esc(e, tau) of
   the header's form (appear__coated_escape_node at the two mu nodes around, each turned into
   esc as appear_coated_make does, linear in mu as a call does) against the walk at the point
   itself, tallying e^n exp(-tau L) directly (n base bounces, L the optical path), for e in
   {0.4, 0.7, 0.9, 1} (between the points where the tables fit their k) and tau in {0, 0.1, 0.5, 1.2} (coat colours 1, 0.90, 0.61, 0.30). Prints
   the largest (also where mu >= 0.05) and the mean absolute difference, the mean per tau, and
   the coat's reflection (rq E_c) against its walk. */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#define APPEAR_IMPLEMENTATION
#include "appear.h"

static appear_vec3 neg(appear_vec3 v) { return appear_vec3_make(-v.x, -v.y, -v.z); }
static const double ES[4] = { 0.4, 0.7, 0.9, 1.0 }, TS[4] = { 0.0, 0.1, 0.5, 1.2 };

/* the walk at one point: esc[e][tau] and R */
static void walk(double mu, double ab, double ac, double eta, long n, unsigned seed, double esc[4][4], double *R)
{
    appear_dielectric coat = appear_dielectric_make(
        appear_microfacet_make(APPEAR_GGX, (float)ac, (float)ac, APPEAR_SAMPLE_VISIBLE), (float)eta);
    appear_conductor base = appear_conductor_make_reflectance(
        appear_microfacet_make(APPEAR_GGX, (float)ab, (float)ab, APPEAR_SAMPLE_VISIBLE), appear_spectrum_splat(1.0f));
    appear_vec3 wo = appear_vec3_make((float)sqrt(1.0 - mu * mu), 0.0f, (float)mu);
    appear_rng rng = appear_rng_make(seed);
    double ent = 0, refl = 0, tot = 0;
    long w;
    int a, b;
    for (a = 0; a < 4; ++a) for (b = 0; b < 4; ++b) esc[a][b] = 0;
    for (w = 0; w < n; ++w) {
        appear_bsdf_record s;
        appear_vec3 t;
        double wt = 1, L;
        int it;
        if (!appear_dielectric_ms_sample(&coat, wo, &rng, &s)) continue;
        tot += 1;
        if (s.wi.z > 0.0f) { refl += 1; continue; }
        ent += 1;
        t = s.wi;
        L = 1.0 / -t.z;
        for (it = 1; it <= 200; ++it) {
            if (!appear_conductor_sample(&base, neg(t), 0.5f, appear_rng_next(&rng), appear_rng_next(&rng), &s) ||
                !(s.wi.z > 0.0f))
                break;
            wt *= s.weight.v[0];
            t = s.wi;
            L += 1.0 / t.z;
            if (!appear_dielectric_ms_sample(&coat, neg(t), &rng, &s)) break;
            if (s.wi.z > 0.0f) {
                for (a = 0; a < 4; ++a) for (b = 0; b < 4; ++b) esc[a][b] += wt * pow(ES[a], it) * exp(-TS[b] * L);
                break;
            }
            t = s.wi;
            L += 1.0 / -t.z;
        }
    }
    for (a = 0; a < 4; ++a) for (b = 0; b < 4; ++b) esc[a][b] /= ent > 0 ? ent : 1;
    *R = tot > 0 ? refl / tot : 0;
}

/* the header's form at node i (appear__coated_esc_of, e at every bounce) */
static double form(double e, double tau, const float *q)
{
    appear_spectrum es = appear_spectrum_splat((float)e);
    return appear__coated_esc_of(q, es, es, appear_spectrum_splat((float)tau), 1.0f).v[0];
}

int main(int argc, char **argv)
{
    int np = argc > 1 ? atoi(argv[1]) : 200, p, a, b;
    long nw = argc > 2 ? atol(argv[2]) : 200000;
    double worst = 0, sum = 0, rworst = 0, worst_off = 0, st[4] = { 0, 0, 0, 0 }; /* worst_off: mu >= 0.05 */
    long cnt = 0;
    srand(12345);
    for (p = 0; p < np; ++p) {
        int im = rand() % (APPEAR__CE_MU - 1), ib = rand() % (APPEAR__CE_AB - 1), ic = rand() % (APPEAR__CE_AC - 1);
        int ie = rand() % (APPEAR__CE_ETA - 1);
        double xm = (im + 0.5) / (APPEAR__CE_MU - 1), s = 0.5 * (sqrt(1 + 8 * xm) - 1), mu = s * s;
        double xb = (ib + 0.5) / (APPEAR__CE_AB - 1), ab = xb * xb * xb;
        double xc = (ic + 0.5) / (APPEAR__CE_AC - 1), ac = 2 * xc * xc * xc;
        double xe = (ie + 0.5) / (APPEAR__CE_ETA - 1), eta = 1 + 2 * xe * xe;
        double esc[4][4], R, wm, rf;
        float qa[APPEAR__COATED_Q], qb[APPEAR__COATED_Q], w;
        int n = appear__coated_node((float)mu, &w);
        float ra = appear__coated_escape_node((float)ab, (float)ac, (float)eta, n, qa);
        float rb = appear__coated_escape_node((float)ab, (float)ac, (float)eta, n + 1, qb);
        wm = w;
        walk(mu, ab, ac, eta, nw, 777u + (unsigned)p, esc, &R);
        { /* rq times the compensated coat's E_c: the table's R */
            float a = (float)ac, m = (float)mu, e = (float)eta;
            double ec = appear_dielectric_reflect_albedo(APPEAR_GGX, a, e, m) / appear_dielectric_albedo(APPEAR_GGX, a, e, m);
            rf = (ra + wm * (rb - ra)) * ec;
        }
        rworst = fmax(rworst, fabs(rf - R));
        for (a = 0; a < 4; ++a)
            for (b = 0; b < 4; ++b) {
                double v = form(ES[a], TS[b], qa) + wm * (form(ES[a], TS[b], qb) - form(ES[a], TS[b], qa));
                double d = fabs(v - esc[a][b]);
                if (d > worst) {
                    worst = d;
                    printf("new worst %.4f at mu %.3f alpha_b %.3f alpha_c %.3f eta %.3f e %.2f tau %.1f: "
                           "table %.4f walk %.4f\n", d, mu, ab, ac, eta, ES[a], TS[b], v, esc[a][b]);
                }
                if (mu >= 0.05) worst_off = fmax(worst_off, d);
                sum += d;
                st[b] += d;
                ++cnt;
            }
    }
    printf("%d cell centres, %ld walks each: |esc table - walk| max %.4f (%.4f at mu >= 0.05), mean %.4f; "
           "|R table - walk| max %.4f\n", np, nw, worst, worst_off, sum / cnt, rworst);
    printf("mean |esc table - walk| at tau 0, 0.1, 0.5, 1.2: %.4f %.4f %.4f %.4f\n", st[0] * 4 / cnt, st[1] * 4 / cnt,
           st[2] * 4 / cnt, st[3] * 4 / cnt);
    return 0;
}
