/* tests/gen/gen_sheen.c - the reference data of appear.h's LTC sheen (SECTION sheen, >>sheen):
   a random walk through the volumetric sheen layer of [Zeltner22], built from appear.h's own
   parts, and the per-node LTC fit of its reflected lobe.

       cc -O2 -I. tests/gen/gen_sheen.c -o build/gen_sheen -lm
       ./build/gen_sheen 0.003 20220801 > tests/gen/sheen_ref.h        (about 6.7 CPU minutes)
       ./build/gen_sheen 0.003 20220802 mid > tests/gen/sheen_mid.h    (about 6.8 CPU minutes)
   (arguments: the relative standard error of E aimed at per node (see NPILOT), seed, and
   "mid" for the held-out midpoints between the nodes, without the lobe fit; these are the
   committed files': 32 x 40 nodes, 3.5e8 paths; 31 x 39 midpoints.)
   appear.h's table is written from this file by tests/gen/fit_sheen.c, and
   tests/test_sheen.c compares it against both files.

   The layer [Zeltner22, Sec. 2; its reference code's VolumeSheenBrdf]: a slab of unit
   thickness and unit flake density, single-scattering albedo 1 (no absorption), nothing
   below it (a path that leaves through the bottom is lost: a black base), filled with
   fiber-like SGGX micro-flakes [Heitz15] whose fibers stand along the normal z, with specular
   flakes. The paper's roughness r maps to the SGGX fiber cross section sigma = r^2, S =
   diag(1, 1, sigma^2): here appear_sggx_make_fiber(z, r * r) (appear.h's fiber parameter is
   that sigma: sigma(z) = r^2, sigma(w perpendicular to z) = 1). Extinction along the
   direction of travel d: sigma_t(d) = appear_sggx_sigma(d) (density 1).
   A path enters at the top going d = -wo, wo = (sqrt(1 - mu^2), 0, mu) (the view direction,
   azimuth 0); free flight by appear_homogeneous_sample1 over the distance to the slab's
   boundary along d; a collision scatters by appear_sggx_specular_sample(-d) (its wo is the
   direction the path came from); a pass through the top is a reflected path, recorded with
   its exit direction; through the bottom, lost. No bounce limit: the paper's reference code
   stops at 16 bounces (a path still inside is lost); the column E16 holds that truncated
   estimate, for comparison (much smaller at low roughness and grazing view, where paths take
   hundreds of bounces: at r = 0.125, mu = 0.0625, E = 0.26 against E16 = 0.12).

   Per node (mu, r): E = fraction of paths reflected (the directional albedo; binomial
   standard error SE), and the LTC fit of the reflected lobe: the exit directions in a
   histogram, 32 bins uniform in cos(theta) x 32 in |phi| in [0, pi] (the lobe is symmetric
   about the plane of incidence), then (a, b) of the LTC [Heitz16 LTC; Zeltner22, Eq. 1]
       M^-1 = [[a, 0, b], [0, a, 0], [0, 0, 1]]   (frame of wo: wo in the xz plane, x >= 0),
       D(w) = a^2 w.z / (pi |M^-1 w|^4)             (a density over the hemisphere, integral 1)
   by maximum likelihood of the binned counts (each bin's probability by 4 x 4 Gauss-Legendre
   points; Nelder-Mead over (log a, b), from the previous roughness's solution; the paper
   minimises an L3 distance of BRDF values instead). Reported per node: TV = total variation
   distance (1/2 sum |p_hist - p_ltc|) between the histogram and the fitted LTC, and TV0, the
   same distance expected from the histogram's noise alone (sum over bins of
   sqrt(p (1 - p) / (2 pi N))), so TV - TV0 is the LTC's own misfit.
   Random numbers: splitmix64 (one stream per node: seed + node index; the pilot its own),
   24-bit floats. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "appear.h"

#define NMU 32
#define NR 40
#define NT 32
#define NPH 32
/* The nodes (appear.h's appear__sheen_mu_node / appear__sheen_r_node, the same formulas):
   mu_i = 0.01 + 0.99 (i / 31)^2 (uniform in sqrt(mu - 0.01): crowded at grazing view, where
   the albedo falls fastest at low roughness), r_j = (0.1^(1/2) + (1 - 0.1^(1/2)) j / 39)^4
   (uniform in r^(1/4): crowded at low roughness, where E at grazing view climbs from 0 to 0.5
   within r < 0.06). */
static double node_mu(double t) { return 0.01 + 0.99 * t * t; }
static double node_r(double t)
{
    double a = sqrt(0.1), v = a + (1.0 - a) * t;
    return v * v * v * v;
}

/* Paths per node: a pilot of NPILOT paths (its own random stream, not counted) estimates E,
   then the node runs n = (1 - E) / (E tau^2) paths (relative standard error tau), at least
   NMIN (also where E < 0.03, where the absolute error counts) and at most NMAX. */
#define NPILOT 20000
#define NMIN 100000
#define NMAX 3000000
static unsigned long long sm_state;
static float rnd(void)
{
    unsigned long long z = (sm_state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return (float)(z >> 40) * (1.0f / 16777216.0f);
}

static double hist[NT][NPH];
static double bins_p[NT][NPH];

/* LTC density in the frame of wo, at unit w */
static double ltc_D(double a, double b, double x, double y, double z)
{
    double px = a * x + b * z, py = a * y, l2 = px * px + py * py + z * z;
    return z > 0.0 ? a * a * z / (M_PI * l2 * l2) : 0.0;
}

/* each bin's probability: 4 x 4 Gauss-Legendre in (cos theta, phi), both halves of phi */
static void ltc_bins(double a, double b)
{
    static const double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                 0.8611363115940526};
    static const double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                 0.3478548451374538};
    int i, j, k, l;
    for (i = 0; i < NT; ++i)
        for (j = 0; j < NPH; ++j) {
            double s = 0.0;
            for (k = 0; k < 4; ++k)
                for (l = 0; l < 4; ++l) {
                    double c = (i + 0.5 + 0.5 * gx[k]) / NT, ph = (j + 0.5 + 0.5 * gx[l]) * M_PI / NPH;
                    double st = sqrt(fmax(0.0, 1.0 - c * c));
                    s += gw[k] * gw[l] * ltc_D(a, b, st * cos(ph), st * sin(ph), c);
                }
            /* area of the bin (1/NT) (pi/NPH), quarter of the weights' sum 4; x2: phi < 0 */
            bins_p[i][j] = 2.0 * s * 0.25 * (1.0 / NT) * (M_PI / NPH);
        }
}

static double nll(const double *x)
{
    double a = exp(x[0]), b = x[1], s = 0.0, tot = 0.0;
    int i, j;
    if (!(a > 1e-3 && a < 1e3 && fabs(b) < 1e3)) return 1e300;
    ltc_bins(a, b);
    for (i = 0; i < NT; ++i)
        for (j = 0; j < NPH; ++j) {
            tot += bins_p[i][j];
            if (hist[i][j] > 0.0) s -= hist[i][j] * log(fmax(bins_p[i][j], 1e-300));
        }
    (void)tot;
    return s;
}

/* Nelder-Mead in 2D */
static void nelder_mead(double *x0, double step)
{
    double p[3][2], f[3], c[2], xr[2], xe[2], xc[2];
    int i, it, lo, hi, mid;
    for (i = 0; i < 3; ++i) { p[i][0] = x0[0]; p[i][1] = x0[1]; }
    p[1][0] += step; p[2][1] += step;
    for (i = 0; i < 3; ++i) f[i] = nll(p[i]);
    for (it = 0; it < 2000; ++it) {
        lo = 0; hi = 0;
        for (i = 1; i < 3; ++i) { if (f[i] < f[lo]) lo = i; if (f[i] > f[hi]) hi = i; }
        mid = 3 - lo - hi;
        if (lo == hi) mid = (lo + 1) % 3, hi = (lo + 2) % 3;
        if (fabs(f[hi] - f[lo]) < 1e-10 * (fabs(f[lo]) + 1e-10) &&
            fabs(p[hi][0] - p[lo][0]) + fabs(p[hi][1] - p[lo][1]) < 1e-7) break;
        c[0] = 0.5 * (p[lo][0] + p[mid][0]); c[1] = 0.5 * (p[lo][1] + p[mid][1]);
        xr[0] = 2 * c[0] - p[hi][0]; xr[1] = 2 * c[1] - p[hi][1];
        {
            double fr = nll(xr);
            if (fr < f[lo]) {
                double fe;
                xe[0] = 3 * c[0] - 2 * p[hi][0]; xe[1] = 3 * c[1] - 2 * p[hi][1];
                fe = nll(xe);
                if (fe < fr) { p[hi][0] = xe[0]; p[hi][1] = xe[1]; f[hi] = fe; }
                else { p[hi][0] = xr[0]; p[hi][1] = xr[1]; f[hi] = fr; }
            } else if (fr < f[mid]) {
                p[hi][0] = xr[0]; p[hi][1] = xr[1]; f[hi] = fr;
            } else {
                double fc;
                xc[0] = 0.5 * (c[0] + p[hi][0]); xc[1] = 0.5 * (c[1] + p[hi][1]);
                fc = nll(xc);
                if (fc < f[hi]) { p[hi][0] = xc[0]; p[hi][1] = xc[1]; f[hi] = fc; }
                else {
                    for (i = 0; i < 3; ++i)
                        if (i != lo) {
                            p[i][0] = 0.5 * (p[i][0] + p[lo][0]); p[i][1] = 0.5 * (p[i][1] + p[lo][1]);
                            f[i] = nll(p[i]);
                        }
                }
            }
        }
    }
    lo = 0;
    for (i = 1; i < 3; ++i) if (f[i] < f[lo]) lo = i;
    x0[0] = p[lo][0]; x0[1] = p[lo][1];
}

typedef struct { double E, se, e16, a, b, tv, tv0, bounces; long nrefl, n; } node_out;

/* n paths from (mu, r) on the stream seed: reflected paths into hist, counts out */
static void walk(const appear_sggx *m, double mu, double r, long n, unsigned long long seed, long *nrefl_, long *n16_,
                 double *nb_)
{
    appear_vec3 wo = appear_vec3_make((float)sqrt(1.0 - mu * mu), 0.0f, (float)mu);
    long p, nrefl = 0, n16 = 0;
    double nb = 0.0;
    sm_state = seed;
    for (p = 0; p < n; ++p) {
        appear_vec3 d = appear_vec3_make(-wo.x, -wo.y, -wo.z);
        float h = 1.0f; /* height above the bottom */
        int k = 0;
        for (;;) {
            appear_medium_sample1 fs;
            appear_phase_record ps;
            float st = appear_sggx_sigma(m, d);
            float dist = d.z < 0.0f ? h / -d.z : (d.z > 0.0f ? (1.0f - h) / d.z : HUGE_VALF);
            int res = appear_homogeneous_sample1(st, dist, rnd(), &fs);
            float u1, u2;
            if (res != APPEAR_MEDIUM_SCATTERED) {
                if (res == APPEAR_MEDIUM_PASSED && d.z > 0.0f) {
                    double c = d.z, ph = atan2(fabs((double)d.y), (double)d.x);
                    int it = (int)(c * NT), ip = (int)(ph / M_PI * NPH);
                    it = it < 0 ? 0 : (it >= NT ? NT - 1 : it);
                    ip = ip < 0 ? 0 : (ip >= NPH ? NPH - 1 : ip);
                    hist[it][ip] += 1.0;
                    ++nrefl;
                    n16 += k <= 16;
                    nb += k;
                }
                break;
            }
            h += fs.t * d.z;
            h = h < 0.0f ? 0.0f : (h > 1.0f ? 1.0f : h);
            u1 = rnd();
            u2 = rnd();
            if (!appear_sggx_specular_sample(m, appear_vec3_make(-d.x, -d.y, -d.z), u1, u2, &ps)) {
                fprintf(stderr, "sample failed at mu %g r %g\n", mu, r);
                exit(1);
            }
            d = ps.wi;
            ++k;
        }
    }
    *nrefl_ = nrefl; *n16_ = n16; *nb_ = nb;
}

/* tau: the relative standard error aimed at (see NPILOT); fit: the LTC fit of the lobe */
static node_out run_node(double mu, double r, double tau, unsigned long long seed, double *xinit, int fit)
{
    node_out o;
    appear_sggx m = appear_sggx_make_fiber(appear_vec3_make(0.0f, 0.0f, 1.0f), (float)(r * r));
    long nrefl, n16, n;
    double nb, ep;
    int i, j;
    walk(&m, mu, r, NPILOT, seed ^ 0x5bd1e9955bd1e995ull, &nrefl, &n16, &nb); /* the pilot */
    ep = (double)nrefl / NPILOT;
    n = ep < 0.03 ? NMIN : (long)fmin((double)NMAX, fmax((double)NMIN, (1.0 - ep) / (ep * tau * tau)));
    memset(hist, 0, sizeof hist);
    walk(&m, mu, r, n, seed, &nrefl, &n16, &nb);
    o.n = n;
    o.nrefl = nrefl;
    o.E = (double)nrefl / (double)n;
    o.se = sqrt(o.E * (1.0 - o.E) / (double)n);
    o.e16 = (double)n16 / (double)n;
    o.bounces = nrefl ? nb / (double)nrefl : 0.0;
    o.a = o.b = 0.0; o.tv = o.tv0 = 0.0;
    if (fit && nrefl >= 1000) {
        double x[2];
        x[0] = xinit[0]; x[1] = xinit[1];
        nelder_mead(x, 0.2);
        nelder_mead(x, 0.05); /* restart: Nelder-Mead's simplex may collapse early */
        xinit[0] = x[0]; xinit[1] = x[1];
        o.a = exp(x[0]); o.b = x[1];
        ltc_bins(o.a, o.b);
        for (i = 0; i < NT; ++i)
            for (j = 0; j < NPH; ++j) {
                double ph = hist[i][j] / (double)nrefl, pl = bins_p[i][j];
                o.tv += 0.5 * fabs(ph - pl);
                o.tv0 += sqrt(pl * (1.0 - pl) / (2.0 * M_PI * (double)nrefl));
            }
    }
    return o;
}

int main(int argc, char **argv)
{
    double tau = argc > 1 ? atof(argv[1]) : 0.003;
    unsigned long long seed = argc > 2 ? strtoull(argv[2], 0, 10) : 20220801ull;
    static node_out out[NR][NMU];
    int i, j, mid = argc > 3 && strcmp(argv[3], "mid") == 0;
    double mus[NMU], rs[NR], paths = 0.0;
    const char *tag = mid ? "mid" : "ref";
    int nmu = mid ? NMU - 1 : NMU, nr = mid ? NR - 1 : NR;
    /* "mid": the midpoints between the nodes in the nodes' own coordinates (sqrt(mu - 0.01),
       r^(1/4)), 31 x 39, a held-out set for the table's interpolation (tests/gen/sheen_mid.h;
       no lobe fit there) */
    for (i = 0; i < nmu; ++i) mus[i] = node_mu((i + (mid ? 0.5 : 0.0)) / (NMU - 1));
    for (j = 0; j < nr; ++j) rs[j] = node_r((j + (mid ? 0.5 : 0.0)) / (NR - 1));
    if (!mid) { mus[NMU - 1] = 1.0; rs[NR - 1] = 1.0; }
    for (j = nr - 1; j >= 0; --j) { /* from the roughest: the fits start from their neighbour */
        for (i = nmu - 1; i >= 0; --i) {
            static double xi[NMU][2];
            if (j == nr - 1) { xi[i][0] = 0.0; xi[i][1] = 0.0; }
            out[j][i] = run_node(mus[i], rs[j], tau, seed + (unsigned long long)(j * NMU + i) * 0x632be59bd9b4e019ull,
                                 xi[i], !mid);
            paths += (double)out[j][i].n;
            fprintf(stderr, "r %.4f mu %.4f  n %ld  E %.5f +- %.5f  E16 %.5f  a %.4f b %+.4f  TV %.4f (noise %.4f)  bounces %.2f\n",
                    rs[j], mus[i], out[j][i].n, out[j][i].E, out[j][i].se, out[j][i].e16, out[j][i].a, out[j][i].b,
                    out[j][i].tv, out[j][i].tv0, out[j][i].bounces);
        }
    }
    printf("/* tests/gen/sheen_%s.h - GENERATED by tests/gen/gen_sheen.c, do not edit:\n"
           "       cc -O2 -I. tests/gen/gen_sheen.c -o build/gen_sheen -lm\n"
           "       ./build/gen_sheen %g %llu%s > tests/gen/sheen_%s.h\n"
           "   The volumetric sheen layer of [Zeltner22] (unit thickness and density, albedo 1,\n"
           "   fiber-like SGGX flakes of cross section r^2 along the normal, black below), by a\n"
           "   random walk (seed %llu), paths per node for a relative standard error of %g\n"
           "   (%d to %d; %.4g paths in all): see gen_sheen.c.\n"
           "   Per node [r][mu]: E (directional albedo), its standard error, E16 (the paper's\n"
           "   16-bounce truncation), the LTC fit (a, b) of the reflected lobe (0 where fewer\n"
           "   than 1000 paths reflected%s), TV (total variation distance, fitted LTC against\n"
           "   the histogram) and TV0 (the part of TV expected from the histogram's noise). */\n",
           tag, tau, seed, mid ? " mid" : "", tag, seed, tau, NMIN, NMAX, paths, mid ? ", and everywhere here" : "");
    if (mid) printf("/* held out: the midpoints between the nodes of sheen_ref.h */\n");
    printf("#define SHEEN_%s_NMU %d\n#define SHEEN_%s_NR %d\n", mid ? "MID" : "REF", nmu, mid ? "MID" : "REF", nr);
    printf("static const double sheen_%s_mu[%d] = {", tag, nmu);
    for (i = 0; i < nmu; ++i) printf("%s%.6f", i ? ", " : "", mus[i]);
    printf("};\nstatic const double sheen_%s_r[%d] = {", tag, nr);
    for (i = 0; i < nr; ++i) printf("%s%.6f", i ? ", " : "", rs[i]);
    printf("};\n/* E, SE, E16, a, b, TV, TV0 */\nstatic const double sheen_%s[%d][%d][7] = {\n", tag, nr, nmu);
    for (j = 0; j < nr; ++j) {
        printf("  { /* r = %.4f */\n", rs[j]);
        for (i = 0; i < nmu; ++i) {
            node_out *o = &out[j][i];
            printf("    {%.6f, %.6f, %.6f, %.6f, %+.6f, %.5f, %.5f}%s\n", o->E, o->se, o->e16, o->a, o->b, o->tv,
                   o->tv0, i + 1 < nmu ? "," : "");
        }
        printf("  }%s\n", j + 1 < nr ? "," : "");
    }
    printf("};\n");
    return 0;
}
