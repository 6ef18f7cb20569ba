/*
** Reading structured values out of a fuzzer's byte string.  Every reader
** returns something when the input is exhausted (0 or a small default), so a
** target never has to check lengths; the fuzzer learns which bytes steer
** which choice.  Doubles are drawn either from a table of special values
** (NaN, +-Inf, 0, -0, 1e300, 1e-300, DBL_MAX, the smallest subnormal, ...),
** from small multiples of 1/16, or taken raw from 8 input bytes.
*/
#ifndef CURVEFIG_FUZZ_INPUT_H
#define CURVEFIG_FUZZ_INPUT_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

typedef struct fz_input {
    const uint8_t *p;
    size_t n;
} fz_input;

static inline unsigned
fz_byte(fz_input *in)
{
    unsigned b;
    if (in->n == 0)
        return 0;
    b = in->p[0];
    in->p++;
    in->n--;
    return b;
}

static inline unsigned
fz_u16(fz_input *in)
{
    unsigned lo = fz_byte(in);
    return lo | (fz_byte(in) << 8);
}

/* A value in [0, 1]: byte / 255. */
static inline double
fz_unit(fz_input *in)
{
    return fz_byte(in) / 255.0;
}

static inline double
fz_raw_double(fz_input *in)
{
    uint8_t b[8] = { 0 };
    double d;
    size_t k = in->n < 8 ? in->n : 8;
    memcpy(b, in->p, k);
    in->p += k;
    in->n -= k;
    memcpy(&d, b, sizeof d);
    return d;
}

/* Any double, special values favoured. */
static inline double
fz_double(fz_input *in)
{
    static const double special[] = {
        0.0, -0.0, 1.0, -1.0, 0.5, 1e300, -1e300, 1e-300, DBL_MAX, -DBL_MAX,
        DBL_MIN, 4.9406564584124654e-324, 1e16, 1e-16, 2.0, 3.0,
    };
    unsigned sel = fz_byte(in);
    if (sel < 16)
        return special[sel];
    if (sel == 16)
        return NAN;
    if (sel == 17)
        return INFINITY;
    if (sel == 18)
        return -INFINITY;
    if (sel < 40)
        return fz_raw_double(in);
    /* small grid: (b - 128) / 16 for the next byte b */
    return ((double)fz_byte(in) - 128.0) / 16.0;
}

/* A double that is finite and of moderate size (|x| <= 2^12). */
static inline double
fz_finite(fz_input *in)
{
    return ((double)fz_u16(in) - 32768.0) / 8.0;
}

/* A degree or count: mostly small, sometimes negative or huge. */
static inline int
fz_int(fz_input *in, int small_max)
{
    static const int special[] = { -1, -2, 1000, 1024, 1025, 32, 33, 2147483647,
                                   -2147483647 - 1, 0 };
    unsigned sel = fz_byte(in);
    if (sel >= 246)
        return special[sel - 246];
    return (int)(sel % (unsigned)(small_max + 1));
}

#endif
