/* examples/openpbr_presets.c - see openpbr_presets.h. Values as the files write them;
   OpenPBR = github.com/AcademySoftwareFoundation/OpenPBR examples/ (v1.1.1, ACEScg colours),
   MaterialX = github.com/AcademySoftwareFoundation/MaterialX
   resources/Materials/Examples/OpenPbr/ (lin_rec709 colours). */
#include "openpbr_presets.h"

#if defined(APPEAR_HAS_OPENPBR)

/* ACES AP1 (D60) to Rec. 709 (D65) through XYZ with the Bradford adaptation: the primaries of
   SMPTE ST 2065-1 / S-2014-004 and IEC 61966-2-1; rows sum to 1 (white stays white). */
appear_spectrum openpbr_acescg(float r, float g, float b)
{
    static const float m[3][3] = { { 1.705051f, -0.621792f, -0.083259f },
                                   { -0.130256f, 1.140805f, -0.010548f },
                                   { -0.024003f, -0.128969f, 1.152972f } };
    float c[3];
    int i;
    for (i = 0; i < 3; ++i) {
        c[i] = m[i][0] * r + m[i][1] * g + m[i][2] * b;
        c[i] = c[i] > 0.0f ? c[i] : 0.0f; /* out of the sRGB gamut */
    }
    return appear_spectrum_rgb(c[0], c[1], c[2]);
}

/* OpenPBR open_pbr_carpaint.mtlx (and MaterialX's, the same numbers): a rough blue dielectric
   base under a smooth clear coat. The spec's paint is these two layers: no flakes, no thin film. */
appear_openpbr_params openpbr_car_paint(void)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    p.base_color = openpbr_acescg(0.1f, 0.6f, 0.9f);
    p.specular_ior = 1.6f;
    p.specular_roughness = 0.3f;
    p.coat_weight = 1.0f;
    p.coat_roughness = 0.02f;
    p.coat_ior = 1.6f;
    return p;
}

/* OpenPBR open_pbr_aluminum_brushed.mtlx: an F82 metal, roughness 0.2 stretched 10:1 along the
   tangent (anisotropy 0.9: alpha_t 0.056, alpha_b 0.0056). */
appear_openpbr_params openpbr_brushed_aluminium(void)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    p.base_color = openpbr_acescg(0.918f, 0.922f, 0.923f);
    p.base_metalness = 1.0f;
    p.specular_color = openpbr_acescg(0.921f, 0.934f, 0.955f);
    p.specular_roughness = 0.2f;
    p.specular_roughness_anisotropy = 0.9f;
    return p;
}

/* OpenPBR open_pbr_glass.mtlx: a smooth clear glass, n 1.52, transmission 1 (depth 0: no
   interior medium). Its dispersion (scale 1, Abbe number 64) is read and not used in RGB. */
appear_openpbr_params openpbr_glass(void)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    p.specular_roughness = 0.0f;
    p.specular_ior = 1.52f;
    p.transmission_weight = 1.0f;
    p.transmission_dispersion_scale = 1.0f;
    p.transmission_dispersion_abbe_number = 64.0f;
    return p;
}

/* OpenPBR open_pbr_velvet.mtlx: a dark violet EON base (diffuse roughness 1, specular roughness
   1) under a half-weight fuzz (the LTC sheen, roughness 0.5). */
appear_openpbr_params openpbr_velvet(void)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    p.base_color = openpbr_acescg(0.062f, 0.01f, 0.269f);
    p.base_diffuse_roughness = 1.0f;
    p.specular_roughness = 1.0f;
    p.fuzz_weight = 0.5f;
    p.fuzz_color = openpbr_acescg(0.315f, 0.237f, 0.465f);
    p.fuzz_roughness = 0.5f;
    return p;
}

/* Ours (the spec has no ceramic): a glaze as the spec's coat ("a coat of colored varnish or
   lacquer", [OpenPBR11] "Coat") over a white glossy-diffuse body: a smooth clear coat of n 1.5
   over the default specular layer at roughness 0.5 and a warm white base. */
appear_openpbr_params openpbr_ceramic(void)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    p.base_color = appear_spectrum_rgb(0.85f, 0.83f, 0.78f);
    p.specular_roughness = 0.5f;
    p.coat_weight = 1.0f;
    p.coat_roughness = 0.0f;
    p.coat_ior = 1.5f;
    return p;
}

/* OpenPBR open_pbr_tire.mtlx: rubber, a near-black rough dielectric (base 0.023, roughness 0.7,
   the default n 1.5). */
appear_openpbr_params openpbr_rubber(void)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    p.base_color = openpbr_acescg(0.023f, 0.023f, 0.023f);
    p.specular_roughness = 0.7f;
    return p;
}

/* OpenPBR open_pbr_skin_iii.mtlx: a skin-like subsurface boundary (subsurface weight 1, n 1.40,
   roughness 0.5). appear.h renders subsurface as its dense limit, an EON diffuse of
   subsurface_color under the specular layer: the radius scale (0.482, 0.169, 0.109) is read and
   not used (no light bleeds across the surface). */
appear_openpbr_params openpbr_skin(void)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    p.specular_roughness = 0.5f;
    p.specular_ior = 1.40f;
    p.subsurface_weight = 1.0f;
    p.subsurface_color = openpbr_acescg(0.545f, 0.445f, 0.359f);
    p.subsurface_radius_scale = openpbr_acescg(0.482f, 0.169f, 0.109f);
    return p;
}

/* OpenPBR open_pbr_default.mtlx, every parameter at the spec's default (a rough grey dielectric:
   base 0.8, roughness 0.3, n 1.5: what a plastic is), with a red base colour (ours). */
appear_openpbr_params openpbr_plastic(void)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    p.base_color = appear_spectrum_rgb(0.7f, 0.06f, 0.05f);
    return p;
}

/* OpenPBR open_pbr_gold.mtlx: an F82 metal, base colour F0, specular colour the F82 tint,
   roughness 0.02 (a polished gold). */
appear_openpbr_params openpbr_gold(void)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    p.base_color = openpbr_acescg(0.929f, 0.788f, 0.374f);
    p.base_metalness = 1.0f;
    p.specular_color = openpbr_acescg(0.987f, 1.013f, 0.997f);
    p.specular_roughness = 0.02f;
    return p;
}

/* MaterialX open_pbr_honey.mtlx (lin_rec709): a smooth glass, n 1.504, around an interior
   medium (transmission_depth 2 scene units: transmission_color (0.83, 0.4, 0.04) after 2 units,
   scatter 0.9, isotropic; appear_openpbr_medium). */
appear_openpbr_params openpbr_honey(void)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    p.specular_roughness = 0.0f;
    p.specular_ior = 1.504f;
    p.transmission_weight = 1.0f;
    p.transmission_color = appear_spectrum_rgb(0.83f, 0.4f, 0.04f);
    p.transmission_depth = 2.0f;
    p.transmission_scatter = appear_spectrum_splat(0.9f);
    return p;
}

/* OpenPBR open_pbr_soapbubble.mtlx: a thin-walled sheet of index 1 (no reflection of its own)
   that transmits everything, under a thin film 0.5 um thick of index 1.40: the film's colours
   reflected, their complement straight through ("Thin-film iridescence"). After the first ten:
   the gallery scene shows those. */
appear_openpbr_params openpbr_soap_bubble(void)
{
    appear_openpbr_params p = appear_openpbr_params_default();
    p.specular_roughness = 0.0f;
    p.specular_ior = 1.0f;
    p.transmission_weight = 1.0f;
    p.thin_film_weight = 1.0f;
    p.thin_film_thickness = 0.5f;
    p.thin_film_ior = 1.40f;
    p.geometry_thin_walled = 1;
    return p;
}

const openpbr_preset openpbr_presets[] = {
    { "car paint", "OpenPBR open_pbr_carpaint.mtlx", "", openpbr_car_paint, 0 },
    { "brushed aluminium", "OpenPBR open_pbr_aluminum_brushed.mtlx", "",
      openpbr_brushed_aluminium, 1 },
    { "glass", "OpenPBR open_pbr_glass.mtlx", "dispersion (one IOR in RGB)", openpbr_glass, 0 },
    { "velvet", "OpenPBR open_pbr_velvet.mtlx", "", openpbr_velvet, 0 },
    { "ceramic", "ours: a clear glaze (coat) over a white body", "", openpbr_ceramic, 0 },
    { "rubber", "OpenPBR open_pbr_tire.mtlx", "", openpbr_rubber, 0 },
    { "skin", "OpenPBR open_pbr_skin_iii.mtlx",
      "subsurface radius (the dense limit: no bleeding)", openpbr_skin, 0 },
    { "plastic", "OpenPBR open_pbr_default.mtlx, red base (ours)", "", openpbr_plastic, 0 },
    { "gold", "OpenPBR open_pbr_gold.mtlx", "", openpbr_gold, 0 },
    { "honey", "MaterialX open_pbr_honey.mtlx", "", openpbr_honey, 0 },
    { "soap bubble", "OpenPBR open_pbr_soapbubble.mtlx", "", openpbr_soap_bubble, 0 },
};
const int openpbr_n_presets = (int)(sizeof openpbr_presets / sizeof openpbr_presets[0]);

#else
typedef int openpbr_presets_empty; /* ISO C: a translation unit declares something */
#endif
