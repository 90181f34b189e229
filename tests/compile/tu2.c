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

/* APPEAR_HAS_<PART> follows APPEAR_NO_<PART> (the matrix builds with all parts
   and with none) */
#if defined(APPEAR_NO_LAMBERT) == defined(APPEAR_HAS_LAMBERT) || \
    defined(APPEAR_NO_PHASE) == defined(APPEAR_HAS_PHASE) || defined(APPEAR_NO_WARD) == defined(APPEAR_HAS_WARD) || \
    defined(APPEAR_NO_MICROFACET) == defined(APPEAR_HAS_MICROFACET) || \
    defined(APPEAR_NO_MEDIA) == defined(APPEAR_HAS_MEDIA) || defined(APPEAR_NO_FLAKES) == defined(APPEAR_HAS_FLAKES) || \
    defined(APPEAR_NO_PHASE_EXTRA) == defined(APPEAR_HAS_PHASE_EXTRA) || \
    defined(APPEAR_NO_THINFILM) == defined(APPEAR_HAS_THINFILM) || \
    (defined(APPEAR_NO_MULTISCATTER) || defined(APPEAR_NO_MICROFACET)) == defined(APPEAR_HAS_MULTISCATTER)
#error "APPEAR_HAS_<PART> disagrees with APPEAR_NO_<PART>"
#endif
