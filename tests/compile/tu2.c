/* Compile check: a second translation unit that includes the header (without
   APPEAR_IMPLEMENTATION) and uses it, to catch duplicate definitions. */
#include "../../appear.h"
int appear_tu2_answer(void);
int appear_tu2_answer(void)
{
    appear_vec3 n = appear_vec3_make(0.0f, 0.0f, 1.0f);
    appear_frame f = appear_frame_from_normal(n);
    return appear_dot(f.z, n) > 0.5f ? appear_version() : -1;
}
