/* Compile check of tests/check.h alone (make check-compile builds it as C99 -pedantic and
   as C++11/17, gcc and clang): the header's own example, a renderer's Lambertian of albedo
   0.8, in the translation unit that defines CHECK_IMPLEMENTATION; tu_check2.c includes the
   declarations only. Exits 0 when the checks ran and gave the example's verdicts. */
#define CHECK_IMPLEMENTATION
#include "../check.h"
#include "../check.h" /* a second include must be harmless */
#include <math.h>
#include <stdio.h>

int check_tu2_lossless(void); /* tu_check2.c */

static double ev(void *c, check_vec3 o, check_vec3 i)
{ (void)c; return o.z * i.z > 0 ? 0.8 / 3.14159265358979 : 0; }
static double pd(void *c, check_vec3 o, check_vec3 i)
{ (void)c; return o.z * i.z > 0 ? fabs(i.z) / 3.14159265358979 : 0; }
static int sa(void *c, check_vec3 o, double uc, double u1, double u2, check_sample *s)
{ double r = sqrt(u1), p = 6.283185307179586 * u2; (void)uc;
  s->wi.x = r * cos(p); s->wi.y = r * sin(p); s->wi.z = copysign(sqrt(1 - u1), o.z);
  s->f = ev(c, o, s->wi); s->pdf = pd(c, o, s->wi); s->weight = 0.8; s->delta = 0;
  return s->pdf > 0; }

int main(void)
{
    check_model m = check_model_make("my lambert", NULL, 1, ev, pd, sa);
    check_vec3 wo = check_vec3_make(0.6, 0, 0.8);
    check_furnace_result fr;
    check_chi2_result cr;
    check_chi2_opts o;
    check_reciprocity_result rr;
    check_consistency_result cc;
    int ok = 1;
    o.n_z = 16; o.n_phi = 32; o.n_samples = 50000; o.axis = check_vec3_make(0, 0, 0);
    o.zmin = 0; o.seed = 3;
    ok &= m.eta == 1.0 && m.eval_is_estimate == 0 && m.sigma == NULL && m.ctx == NULL;
    ok &= check_furnace(&m, wo, 100000, 1, &fr) == 0 && fabs(fr.albedo - 0.8) < 1e-9;
    ok &= check_chi2(&m, wo, &o, &cr) == 0 && cr.p > 1e-4 && cr.dof > 100;
    ok &= check_reciprocity(&m, 2000, 1e-4, 1, 5, &rr) == 0 && rr.compared > 100 && rr.max_rel < 1e-12;
    ok &= check_consistency(&m, wo, 2000, 1e-9, 7, &cc) == 0 && cc.checked == 2000 && cc.bad == 0;
    ok &= check_tu2_lossless();
    printf("tests/check.h example: albedo %.4f +- %.4f  chi2 p %.3f  %s\n", fr.albedo, fr.se, cr.p,
           ok ? "ok" : "FAILED");
    check_chi2_free(&cr);
    return ok ? 0 : 1;
}
