/*
** Colours as people with a colour vision deficiency, or a greyscale
** print, show them, and the distance between two colours (docs/
** accessibility.md, "Colour").
**
** Simulation: Machado, Oliveira and Fernandes, "A Physiologically-based
** Model for Simulation of Color Vision Deficiency", IEEE TVCG 15(6),
** 2009: protanopia, deuteranopia and tritanopia at severity 1.0, their
** 3x3 matrices applied to linear RGB (sRGB decoded), the result clipped to
** [0, 1].  Greyscale: the luminance Y of linear RGB (Rec. 709 weights), as
** a greyscale print or a monochrome display renders it.  Distance: CIEDE2000
** (Sharma, Wu and Dalal 2005) between the CIELAB colours (D65 white).
*/
#ifndef CURVEFIG_RENDER_COLOUR_VISION_H
#define CURVEFIG_RENDER_COLOUR_VISION_H

#include "curvefig/style.h"

typedef enum cf__vision {
    CF__VISION_NORMAL = 0,
    CF__VISION_PROTAN,       /* no L cones */
    CF__VISION_DEUTAN,       /* no M cones */
    CF__VISION_TRITAN,       /* no S cones */
    CF__VISION_GREY,         /* a greyscale print */
    CF__VISION_LAST_
} cf__vision_t;

/* The least CIEDE2000 distance of two colours that must be told apart, in
** every vision (docs/accessibility.md gives the reasons): about ten
** just-noticeable differences of large patches, since a figure's colours
** are thin lines and small marks. */
#define CF__COLOUR_MIN_DE 10.0

/* "protanopia", "deuteranopia", "tritanopia", "greyscale", "normal" */
const char *cf__vision_name(cf__vision_t v);

/* sRGB component (0..1) to linear light. */
double cf__srgb_to_linear(double c);

/* The linear RGB that vision v sees for sRGB colour rgb (0..1 each). */
void cf__vision_simulate(cf__vision_t v, const double rgb[3], double out[3]);

/* CIELAB (D65) of a linear RGB colour. */
void cf__lab_from_linear(const double lin[3], double lab[3]);

/* CIEDE2000 distance of two CIELAB colours. */
double cf__ciede2000(const double lab1[3], const double lab2[3]);

/* The CIEDE2000 distance of sRGB colours a and b (alpha ignored) as
** vision v sees them. */
double cf__colour_distance(cf__vision_t v, cf_color_t a, cf_color_t b);

#endif
