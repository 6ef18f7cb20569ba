/*
** Colour vision deficiencies simulated, CIELAB and CIEDE2000
** (colour-vision.h).
*/
#include <math.h>

#include "colour-vision.h"

#define CF__PI 3.14159265358979323846

/* Machado et al. 2009, Table 1 (severity 1.0), rows: the simulated linear
** R, G, B from the linear R, G, B. */
static const double machado[3][3][3] = {
    { { 0.152286, 1.052583, -0.204868 },     /* protanopia */
      { 0.114503, 0.786281, 0.099216 },
      { -0.003882, -0.048116, 1.051998 } },
    { { 0.367322, 0.860646, -0.227968 },     /* deuteranopia */
      { 0.280085, 0.672501, 0.047413 },
      { -0.011820, 0.042940, 0.968881 } },
    { { 1.255528, -0.076749, -0.178779 },    /* tritanopia */
      { -0.078411, 0.930809, 0.147602 },
      { 0.004733, 0.691367, 0.303900 } },
};

const char *
cf__vision_name(cf__vision_t v)
{
    static const char *const names[CF__VISION_LAST_] = {
        "normal", "protanopia", "deuteranopia", "tritanopia", "greyscale"
    };
    return (unsigned)v < CF__VISION_LAST_ ? names[v] : "?";
}

double
cf__srgb_to_linear(double c)
{
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

static double
clamp01(double x)
{
    return x < 0 ? 0 : x > 1 ? 1 : x;
}

void
cf__vision_simulate(cf__vision_t v, const double rgb[3], double out[3])
{
    double lin[3];
    int i;
    for (i = 0; i < 3; i++)
        lin[i] = cf__srgb_to_linear(clamp01(rgb[i]));
    if (v == CF__VISION_GREY) {
        double y = 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2];
        out[0] = out[1] = out[2] = y;
        return;
    }
    if (v < CF__VISION_PROTAN || v > CF__VISION_TRITAN) {
        for (i = 0; i < 3; i++)
            out[i] = lin[i];
        return;
    }
    for (i = 0; i < 3; i++) {
        const double *m = machado[v - CF__VISION_PROTAN][i];
        out[i] = clamp01(m[0] * lin[0] + m[1] * lin[1] + m[2] * lin[2]);
    }
}

static double
lab_f(double t)
{
    const double eps = 216.0 / 24389.0, kappa = 24389.0 / 27.0;
    return t > eps ? cbrt(t) : (kappa * t + 16.0) / 116.0;
}

void
cf__lab_from_linear(const double lin[3], double lab[3])
{
    /* sRGB (D65) to XYZ, IEC 61966-2-1; the white of D65 */
    double x = 0.4124564 * lin[0] + 0.3575761 * lin[1] + 0.1804375 * lin[2];
    double y = 0.2126729 * lin[0] + 0.7151522 * lin[1] + 0.0721750 * lin[2];
    double z = 0.0193339 * lin[0] + 0.1191920 * lin[1] + 0.9503041 * lin[2];
    double fx = lab_f(x / 0.95047), fy = lab_f(y), fz = lab_f(z / 1.08883);
    lab[0] = 116.0 * fy - 16.0;
    lab[1] = 500.0 * (fx - fy);
    lab[2] = 200.0 * (fy - fz);
}

static double
deg(double rad)
{
    return rad * 180.0 / CF__PI;
}

static double
rad(double d)
{
    return d * CF__PI / 180.0;
}

/* hue angle in degrees, 0..360 (0 for a grey) */
static double
hue(double b, double ap)
{
    double h;
    if (b == 0 && ap == 0)
        return 0;
    h = deg(atan2(b, ap));
    return h < 0 ? h + 360.0 : h;
}

double
cf__ciede2000(const double lab1[3], const double lab2[3])
{
    const double p25_7 = 6103515625.0;   /* 25^7 */
    double c1 = hypot(lab1[1], lab1[2]), c2 = hypot(lab2[1], lab2[2]);
    double cb7 = pow((c1 + c2) / 2.0, 7);
    double g = 0.5 * (1.0 - sqrt(cb7 / (cb7 + p25_7)));
    double a1 = (1.0 + g) * lab1[1], a2 = (1.0 + g) * lab2[1];
    double c1p = hypot(a1, lab1[2]), c2p = hypot(a2, lab2[2]);
    double h1 = hue(lab1[2], a1), h2 = hue(lab2[2], a2);
    double dl = lab2[0] - lab1[0], dc = c2p - c1p, dh = 0, hb;
    double lb = (lab1[0] + lab2[0]) / 2.0, cbp = (c1p + c2p) / 2.0;
    double t, dtheta, rc, sl, sc, sh, rt, cbp7;
    if (c1p * c2p != 0) {
        dh = h2 - h1;
        if (dh > 180)
            dh -= 360;
        else if (dh < -180)
            dh += 360;
    }
    dh = 2.0 * sqrt(c1p * c2p) * sin(rad(dh / 2.0));
    if (c1p * c2p == 0)
        hb = h1 + h2;
    else if (fabs(h1 - h2) <= 180)
        hb = (h1 + h2) / 2.0;
    else if (h1 + h2 < 360)
        hb = (h1 + h2 + 360.0) / 2.0;
    else
        hb = (h1 + h2 - 360.0) / 2.0;
    t = 1.0 - 0.17 * cos(rad(hb - 30)) + 0.24 * cos(rad(2 * hb))
        + 0.32 * cos(rad(3 * hb + 6)) - 0.20 * cos(rad(4 * hb - 63));
    dtheta = 30.0 * exp(-((hb - 275.0) / 25.0) * ((hb - 275.0) / 25.0));
    cbp7 = pow(cbp, 7);
    rc = 2.0 * sqrt(cbp7 / (cbp7 + p25_7));
    sl = 1.0 + 0.015 * (lb - 50) * (lb - 50) / sqrt(20 + (lb - 50) * (lb - 50));
    sc = 1.0 + 0.045 * cbp;
    sh = 1.0 + 0.015 * cbp * t;
    rt = -sin(rad(2 * dtheta)) * rc;
    return sqrt((dl / sl) * (dl / sl) + (dc / sc) * (dc / sc)
                + (dh / sh) * (dh / sh) + rt * (dc / sc) * (dh / sh));
}

double
cf__colour_distance(cf__vision_t v, cf_color_t a, cf_color_t b)
{
    double ra[3] = { a.r, a.g, a.b }, rb[3] = { b.r, b.g, b.b };
    double la[3], lb[3], xa[3], xb[3];
    cf__vision_simulate(v, ra, la);
    cf__vision_simulate(v, rb, lb);
    cf__lab_from_linear(la, xa);
    cf__lab_from_linear(lb, xb);
    return cf__ciede2000(xa, xb);
}
