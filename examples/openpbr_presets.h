/* examples/openpbr_presets.h - OpenPBR Surface presets that users know: a car paint, brushed
   aluminium, glass, velvet, a glazed ceramic, rubber, a skin-like subsurface boundary, plastic,
   gold, honey and a soap bubble, as appear_openpbr_params (the gallery scene shows the first ten).

   Each preset starts from appear_openpbr_params_default() (the spec's defaults) and sets the values
   of one of the spec's example materials [OpenPBR11]: an open_pbr_NAME.mtlx of the OpenPBR
   repository's examples (v1.1.1) or of MaterialX's resources/Materials/Examples/OpenPbr; the
   ceramic and the plastic's colour are ours (the spec has no ceramic; its plastics are clear
   polymers). Each function's comment names its file and what it sets; `source` and `left_out`
   say the same at run time.

   Colour spaces. The OpenPBR repository's files declare colorspace "acescg" (ACES AP1 primaries,
   D60 white); appear.h's RGB channels are linear sRGB (Rec. 709 primaries, D65), so their colours
   go through openpbr_acescg(): the AP1 to Rec. 709 matrix with the Bradford adaptation from D60
   to D65, negative results set to 0 (car paint's blue leaves the sRGB gamut: its red -0.28).
   appear_openpbr_make clamps the results above 1 (gold's red base 1.063, its green tint 1.017).
   The converted metals agree with appear.h's own spectral integrations (appear_metal_to_rgb):
   gold's F0 (1, 0.774, 0.307) against (1, 0.728, 0.365), aluminium's (0.915, 0.923, 0.923)
   against (0.907, 0.916, 0.922). MaterialX's files declare "lin_rec709": read as they are.

   What appear.h leaves out (appear.h SECTION openpbr, "Deviations"): dispersion is read and not
   used (one IOR in RGB); subsurface is its dense limit (the radius is read and not used); the thin
   film (the soap bubble's) is carried over a rough lobe as an affine map of its Fresnel factor
   (exact on the bubble's smooth sheet). Usage:

       appear_openpbr_params p = openpbr_presets[i].params();
       appear_openpbr m = appear_openpbr_make(&p);
       appear_bsdf b = appear_bsdf_openpbr(&m);   (b refers to m: keep m in place) */
#ifndef APPEAR_OPENPBR_PRESETS_H
#define APPEAR_OPENPBR_PRESETS_H
#include "../appear.h"

#if defined(APPEAR_HAS_OPENPBR)
typedef struct openpbr_preset {
    const char *name;     /* short: "car paint" */
    const char *source;   /* the file its values come from, or "ours: ..." */
    const char *left_out; /* what the source has that appear.h leaves out; "" for nothing */
    appear_openpbr_params (*params)(void);
    int brushed;          /* anisotropic: wants its tangent along the brushing direction */
} openpbr_preset;

extern const openpbr_preset openpbr_presets[];
extern const int openpbr_n_presets;

/* An ACEScg colour in linear sRGB (Rec. 709, D65), negatives set to 0 (see the top). */
appear_spectrum openpbr_acescg(float r, float g, float b);

appear_openpbr_params openpbr_car_paint(void);
appear_openpbr_params openpbr_brushed_aluminium(void);
appear_openpbr_params openpbr_glass(void);
appear_openpbr_params openpbr_velvet(void);
appear_openpbr_params openpbr_ceramic(void);
appear_openpbr_params openpbr_rubber(void);
appear_openpbr_params openpbr_skin(void);
appear_openpbr_params openpbr_plastic(void);
appear_openpbr_params openpbr_gold(void);
appear_openpbr_params openpbr_honey(void);
appear_openpbr_params openpbr_soap_bubble(void);
#endif

#endif
