/* tests/gen/gen_coated_escape.c - writes the escape tables of appear_coated's microfacet
   conductor bases: SECTION tables (grep >>tables), between the lines BEGIN / END GENERATED
   COATED ESCAPE TABLES; the accessors and the lookup that follow the block are hand-written:
       cc -O2 -Wall -I. tests/gen/gen_coated_escape.c -o build/gen_coated_escape -lm
       ./build/gen_coated_escape part 0 2 > build/ce0 & ./build/gen_coated_escape part 1 2 > build/ce1
       ./build/gen_coated_escape assemble build/ce0 build/ce1 > build/coated_escape_tables.h
       python3 tests/gen/splice.py build/coated_escape_tables.h
   (or ./build/gen_coated_escape > build/coated_escape_tables.h in one process).

   What is tabulated: the random walk of SECTION layered (appear_layered, the reference of
   appear_coated) through a rough dielectric coat (GGX alpha_c, eta; its multiple-scattering
   interface appear_dielectric_ms, the walk's own top) over a single-scattering GGX conductor
   base of roughness alpha_b with F = 1, nothing between. Light arrives from outside at cosine
   mu. Per node (mu, alpha_b, alpha_c, eta):
     rq    the fraction R the coat reflects at once over appear_coated's reflection albedo
           E_c = R_ss / E of the compensated single-scattering coat (a table of its own over
           mu, alpha_c, eta; 1 for a smooth coat: R = F = E_c);
     and, of the light that enters, by the number n of base bounces before it leaves, with
     the base's single-scattering loss (the weight G2 / G1 of its visible-normal samples):
     P1    the part that leaves after one bounce;
     Q     the part that leaves after two or more;
     k     the ratio of a geometric series in n for the latter, fitted so that
           sum_{n >= 2} P_n e^n = Q e^2 (1 - k) / (1 - e k), at e = 0.5, 0.8 and 0.95 (three
           k: the header takes k linear in e between and beyond them; over a smooth base the
           counts are no geometric series, the light keeping its angle, and one k fitted at
           0.8 made the sum 6.5% too bright at e 0.94, gold's red; a rough base's three k
           agree);
     l1    the optical path, in units of the coat's normal optical depth tau, of the light
           that leaves after one bounce (entry and exit), fitted so that
           E[exp(-tau0 L1)] = exp(-tau0 l1) at tau0 = 0.35;
     l2    the same per bounce for the light that leaves after n >= 2, its whole path (entry,
           every round trip, exit) over n, weighted as the series weights it (e0^n): the light
           trapped by total internal reflection takes more bounces AND longer legs, its first
           included (l1, fitted on the light that leaves at once, missed that: the
           multiple-bounce part 20-35% too bright at tau 0.1, gold under a rough coat at
           grazing view; tau0 0.35 balances the error at tau 0.1 and 0.5), weighted at e0 =
           0.8.
   appear_coated_make turns them into the base's escape for its Fresnel factor e per bounce
   and its coat's optical depth tau (per channel):
       esc = e a1 P1 + Q e^2 a^2 (1 - k) / (1 - e a k),   a1 = exp(-tau l1), a = exp(-tau l2),
   k taken at e a.
   A white Lambertian base has a table of its own over (mu, alpha_c, eta) (the walk's base a
   cosine-weighted reflection of weight 1). Stored as round(v * 65535) in unsigned short: P1,
   Q, k(0.5), k(0.8), k(0.95), 2 / l1, 2 / l2 (each path >= 2), rq / 2. Axes (x = index /
   (nodes - 1)): mu: (sqrt(mu) + mu) / 2 = x (node 0 walked at mu = 1e-3); alpha_b: x^3, 13
   nodes to 1 (a rougher base reads 1's; the nodes crowd toward smooth, where a grazing
   view's light meets the critical angle and the escape changes fastest; 10 nodes of 2 x^3
   to 2 until 2026-12-06 put P1 7% above the walk at 0.8 between 0.59 and 0.94, gold under a
   smooth coat); alpha_c: 2 x^3, 10 nodes; eta: 1 + 2 x^2. Walks per node: CE_WALKS
   (escape), CE_R_WALKS (rq). Seeds: the node index. Output: rq[eta][alpha_c][mu], then
   E[eta][alpha_c][alpha_b][mu][7], then L[eta][alpha_c][mu][7]; 16 values a line. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#define APPEAR_IMPLEMENTATION
#define APPEAR_NO_LAYERED /* the walk's parts only: the header compiles without the tables it writes */
#include "appear.h"

#define CE_MU 12
#define CE_AB 13
#define CE_AC 10
#define CE_ETA 8
#define CE_WALKS 150000
#define CE_MAX_BOUNCES 64
#define CE_R_WALKS 200000
#define N_R (CE_ETA * CE_AC * CE_MU)
#define N_E (CE_ETA * CE_AC * CE_AB * CE_MU)
#define N_L (CE_ETA * CE_AC * CE_MU)
#define N_ALL (N_R + N_E + N_L)
#define PER_LINE 16
static const double E0 = 0.8, TAU0 = 0.35, EK[3] = { 0.5, 0.8, 0.95 }; /* k's fitting points */
#define CE_Q 7 /* the quantities per escape node */

static double node_mu(int i)
{
    double x = (double)i / (CE_MU - 1), s = 0.5 * (-1.0 + sqrt(1.0 + 8.0 * x));
    return i ? s * s : 1e-3;
}
static double node_alpha(int i, int n) { double x = (double)i / (n - 1); return 2.0 * x * x * x; }
static double node_alpha_b(int i) { double x = (double)i / (CE_AB - 1); return x * x * x; } /* to 1 */
static double node_eta(int i) { double x = (double)i / (CE_ETA - 1); return 1.0 + 2.0 * x * x; }
static unsigned q16(double v) { v = v < 0 ? 0 : v > 1 ? 1 : v; return (unsigned)floor(v * 65535.0 + 0.5); }
static appear_vec3 neg(appear_vec3 v) { return appear_vec3_make(-v.x, -v.y, -v.z); }
static appear_dielectric coat_of(double ac, double eta)
{
    return appear_dielectric_make(appear_microfacet_make(APPEAR_GGX, (float)ac, (float)ac, APPEAR_SAMPLE_VISIBLE),
                                  (float)eta);
}

/* rq: the fraction of CE_R_WALKS arrivals at mu the coat reflects, over E_c */
static void node_r(int n, unsigned *v)
{
    int m = n % CE_MU, c = n / CE_MU % CE_AC, e = n / (CE_MU * CE_AC);
    double mu = node_mu(m), ac = node_alpha(c, CE_AC), eta = node_eta(e), r = 0;
    appear_dielectric coat = coat_of(ac, eta);
    appear_vec3 wo = appear_vec3_make((float)sqrt(1.0 - mu * mu), 0.0f, (float)mu);
    appear_rng rng = appear_rng_make(0x5eed0000u + (unsigned)n);
    long k, got = 0;
    if (coat.smooth) { v[0] = q16(0.5); return; } /* R = F = E_c */
    for (k = 0; k < CE_R_WALKS; ++k) {
        appear_bsdf_record s;
        if (!appear_dielectric_ms_sample(&coat, wo, &rng, &s)) continue;
        ++got;
        r += s.wi.z > 0.0f;
    }
    r = got ? r / got : 0.0;
    { /* over the compensated single-scattering coat's E_c = R_ss / E (appear_coated's) */
        float a = (float)ac, m = (float)mu, e = (float)eta;
        double ec = appear_dielectric_reflect_albedo(APPEAR_GGX, a, e, m) / appear_dielectric_albedo(APPEAR_GGX, a, e, m);
        v[0] = q16(ec > 1e-4 ? 0.5 * r / ec : 0.5);
    }
}

/* the escape quantities at (mu, alpha_b, alpha_c, eta) (see the head); alpha_b < 0: a white
   Lambertian base */
static void walk_node(double mu, double ab, double ac, double eta, unsigned seed, unsigned *v)
{
    appear_dielectric coat = coat_of(ac, eta);
    appear_conductor base = appear_conductor_make_reflectance(
        appear_microfacet_make(APPEAR_GGX, (float)(ab > 0 ? ab : 0), (float)(ab > 0 ? ab : 0), APPEAR_SAMPLE_VISIBLE),
        appear_spectrum_splat(1.0f));
    appear_lambert lam = appear_lambert_make(appear_spectrum_splat(1.0f));
    appear_vec3 wo = appear_vec3_make((float)sqrt(1.0 - mu * mu), 0.0f, (float)mu);
    appear_rng rng = appear_rng_make(seed);
    double p1 = 0, q = 0, g = 0, gk[3] = { 0, 0, 0 }, a1 = 0, a2 = 0, ent = 0, k, l1, l2;
    long w;
    int j;
    for (w = 0; w < CE_WALKS; ++w) {
        appear_bsdf_record s;
        appear_vec3 t; /* the direction of travel */
        double wt = 1, L1, L2 = 0;
        int it;
        if (!appear_dielectric_ms_sample(&coat, wo, &rng, &s) || s.wi.z > 0.0f) continue;
        ent += 1;
        t = s.wi;
        L1 = 1.0 / -t.z;
        for (it = 1; it <= CE_MAX_BOUNCES; ++it) {
            if (ab < 0 ? !appear_lambert_sample(&lam, neg(t), 0.5f, appear_rng_next(&rng), appear_rng_next(&rng), &s)
                       : !appear_conductor_sample(&base, neg(t), 0.5f, appear_rng_next(&rng), appear_rng_next(&rng), &s)
                || !(s.wi.z > 0.0f))
                break; /* the single-scattering base's loss */
            wt *= s.weight.v[0];
            t = s.wi;
            if (it == 1) L1 += 1.0 / t.z; else L2 += 1.0 / t.z;
            if (!appear_dielectric_ms_sample(&coat, neg(t), &rng, &s)) break;
            if (s.wi.z > 0.0f) { /* leaves */
                if (it == 1) { p1 += wt; a1 += wt * exp(-TAU0 * L1); }
                else {
                    double en = pow(E0, it);
                    q += wt; g += wt * en; a2 += wt * en * exp(-TAU0 * (L1 + L2) / it);
                    for (j = 0; j < 3; ++j) gk[j] += wt * pow(EK[j], it);
                }
                break;
            }
            t = s.wi; /* reflected back down */
            L2 += 1.0 / -t.z;
            if (it == CE_MAX_BOUNCES) q += wt; /* still inside: counted as leaving, late */
        }
    }
    if (ent < 1) ent = 1;
    l1 = p1 > 0 && a1 > 0 ? -log(a1 / p1) / TAU0 : 2.0;
    l2 = g > 0 && a2 > 0 ? -log(a2 / g) / TAU0 : 2.0;
    v[0] = q16(p1 / ent);
    v[1] = q16(q / ent);
    for (j = 0; j < 3; ++j) { /* (1 - k) / (1 - e k) = r at e = EK[j] */
        double r = q > 0 ? gk[j] / (q * EK[j] * EK[j]) : 1.0;
        k = fabs(r * EK[j] - 1.0) > 1e-12 ? (r - 1.0) / (r * EK[j] - 1.0) : 0.0;
        v[2 + j] = q16(k);
    }
    v[5] = q16(2.0 / (l1 > 2.0 ? l1 : 2.0));
    v[6] = q16(2.0 / (l2 > 2.0 ? l2 : 2.0));
}
static void node_e(int n, unsigned *v)
{
    int m = n % CE_MU, b = n / CE_MU % CE_AB, c = n / (CE_MU * CE_AB) % CE_AC, e = n / (CE_MU * CE_AB * CE_AC);
    walk_node(node_mu(m), node_alpha_b(b), node_alpha(c, CE_AC), node_eta(e), 0xe5c00000u + (unsigned)n, v);
}
static void node_l(int n, unsigned *v)
{
    int m = n % CE_MU, c = n / CE_MU % CE_AC, e = n / (CE_MU * CE_AC);
    walk_node(node_mu(m), -1.0, node_alpha(c, CE_AC), node_eta(e), 0x1a3b0000u + (unsigned)n, v);
}

static int node_width(int n) { return n < N_R ? 1 : CE_Q; }
static unsigned *node_slot(unsigned *v, int n) { return n < N_R ? v + n : v + N_R + CE_Q * (n - N_R); }
static void node_value(int n, unsigned *v)
{
    if (n < N_R) node_r(n, v);
    else if (n < N_R + N_E) node_e(n - N_R, v);
    else node_l(n - N_R - N_E, v);
}

static void print_block(const unsigned *v, int count)
{
    int i;
    for (i = 0; i < count; ++i)
        printf("%u%s%s", v[i], i + 1 < count ? "," : "", (i + 1) % PER_LINE == 0 || i + 1 == count ? " \\\n" : "");
}

int main(int argc, char **argv)
{
    static unsigned v[N_R + CE_Q * (N_E + N_L)];
    static char seen[N_ALL];
    int n, j;
    if ((argc == 4 || argc == 5) && !strcmp(argv[1], "part")) {
        /* "part P NP [from]"; "part P NP rq": the rq nodes alone (they read appear_dielectric_albedo
           and _reflect_albedo: rerun when those tables change; assemble after a file with every
           node, later files override) */
        int p = atoi(argv[2]), np = atoi(argv[3]), rq = argc == 5 && !strcmp(argv[4], "rq");
        int from = argc == 5 && !rq ? atoi(argv[4]) : 0;
        for (n = from + p; n < (rq ? N_R : N_ALL); n += np) {
            unsigned x[CE_Q];
            node_value(n, x);
            printf("%d", n);
            for (j = 0; j < node_width(n); ++j) printf(" %u", x[j]);
            printf("\n");
            fflush(stdout);
        }
        return 0;
    }
    if (argc >= 3 && !strcmp(argv[1], "assemble")) {
        int a, got = 0;
        for (a = 2; a < argc; ++a) {
            FILE *f = fopen(argv[a], "r");
            if (!f) return 1;
            while (fscanf(f, "%d", &n) == 1 && n >= 0 && n < N_ALL) {
                unsigned *dst = node_slot(v, n);
                for (j = 0; j < node_width(n); ++j)
                    if (fscanf(f, "%u", dst + j) != 1) return 1;
                got += !seen[n];
                seen[n] = 1;
            }
            fclose(f);
        }
        if (got != N_ALL) { fprintf(stderr, "incomplete: %d of %d nodes\n", got, N_ALL); return 1; }
    } else
        for (n = 0; n < N_ALL; ++n) node_value(n, node_slot(v, n));
    printf("/* BEGIN GENERATED COATED ESCAPE TABLES (tests/gen/gen_coated_escape.c; do not edit) */\n");
    printf("#define APPEAR__CE_MU %d\n#define APPEAR__CE_AB %d\n#define APPEAR__CE_AC %d\n#define APPEAR__CE_ETA %d\n"
           "#define APPEAR__CE_Q %d\n", CE_MU, CE_AB, CE_AC, CE_ETA, CE_Q);
    printf("#define APPEAR__CE_R_DATA { \\\n");
    print_block(v, N_R);
    printf("}\n#define APPEAR__CE_DATA { \\\n");
    print_block(v + N_R, CE_Q * N_E);
    printf("}\n#define APPEAR__CE_L_DATA { \\\n");
    print_block(v + N_R + CE_Q * N_E, CE_Q * N_L);
    printf("}\n/* END GENERATED COATED ESCAPE TABLES */\n");
    return 0;
}
