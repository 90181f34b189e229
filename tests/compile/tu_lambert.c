/* Compile check: a translation unit that uses Lambert alone carries none of
   the header's tables, even at -O0 (they are function-local statics behind
   accessors; `make check-compile` measures this object's size). */
#include "../../appear.h"
float tu_lambert_only(appear_vec3 wo, appear_vec3 wi);
float tu_lambert_only(appear_vec3 wo, appear_vec3 wi)
{
    appear_lambert l = appear_lambert_make(appear_spectrum_splat(0.5f));
    return appear_lambert_eval(&l, wo, wi).v[0] + appear_lambert_pdf(&l, wo, wi);
}
