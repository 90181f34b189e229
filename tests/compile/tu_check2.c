/* Compile check: a second translation unit that includes tests/check.h without
   CHECK_IMPLEMENTATION and uses it, to catch duplicate definitions. A phase function
   (isotropic) built with check_model_make and its optional fields set after it. */
#include "../check.h"
#include <math.h>

int check_tu2_lossless(void);

static double iso(void *c, check_vec3 o, check_vec3 i)
{ (void)c; (void)o; (void)i; return 0.07957747154594767; } /* 1 / (4 pi) */
static int iso_sample(void *c, check_vec3 o, double uc, double u1, double u2, check_sample *s)
{ double z = 1.0 - 2.0 * u1, r = sqrt(fmax(0.0, 1.0 - z * z)), p = 6.283185307179586 * u2;
  (void)uc;
  s->wi = check_vec3_make(r * cos(p), r * sin(p), z);
  s->f = iso(c, o, s->wi); s->pdf = s->f; s->weight = 1.0; s->delta = 0;
  return 1; }

int check_tu2_lossless(void)
{
    check_model m = check_model_make("isotropic", NULL, 0, iso, iso, iso_sample);
    check_furnace_result r;
    m.eta = 1.0;           /* the optional fields, set after make */
    m.eval_is_estimate = 0;
    m.sigma = NULL;
    return check_furnace(&m, check_vec3_make(0, 0, 1), 1000, 9, &r) == 0 && r.albedo == 1.0 &&
           r.se == 0.0 && r.n == 1000;
}
