/*
** The shortest text of a number that reads back as it (numtext-private.h).
*/
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "numtext-private.h"

/* The digits of x rounded to p significant digits (p from 1 to 17), as
** %.*e writes them: into e, which is returned. */
static const char *
digits_e(double x, int p, char e[CF__NUM_TEXT])
{
    snprintf(e, CF__NUM_TEXT, "%.*e", p - 1, x);
    return e;
}

const char *
cf__num_text(double x, char buf[CF__NUM_TEXT])
{
    char e[CF__NUM_TEXT], dig[20];
    const char *s, *mark;
    int p = 1, exp, nd = 0;
    size_t n = 0;
    if (isnan(x))
        return strcpy(buf, "NaN");
    if (isinf(x))
        return strcpy(buf, x < 0 ? "-inf" : "inf");
    /* 17 significant digits always read back (DBL_DECIMAL_DIG) */
    while (p < 17 && strtod(digits_e(x, p, e), NULL) != x)
        p++;
    digits_e(x, p, e);
    mark = strchr(e, 'e');
    exp = atoi(mark + 1);
    /* %g's exponent form below 1e-4 and from 1e17 on: %.*e's text, whose
    ** last digit is not 0 (else one digit fewer would read back) */
    if (exp < -4 || exp > 16)
        return strcpy(buf, e);
    for (s = e; s < mark; s++)
        if (*s >= '0' && *s <= '9')
            dig[nd++] = *s;
    if (signbit(x))
        buf[n++] = '-';
    if (exp < 0) {
        buf[n++] = '0';
        buf[n++] = '.';
        for (int i = -1; i > exp; i--)
            buf[n++] = '0';
        for (int i = 0; i < nd; i++)
            buf[n++] = dig[i];
    } else {
        for (int i = 0; i <= exp; i++)
            buf[n++] = i < nd ? dig[i] : '0';
        if (nd > exp + 1) {
            buf[n++] = '.';
            for (int i = exp + 1; i < nd; i++)
                buf[n++] = dig[i];
        }
    }
    buf[n] = '\0';
    return buf;
}

void
cf__spell_nan(char *msg)
{
    char *p = msg, *q = msg;
    while (*p != '\0') {
        size_t skip = p[0] == '-' ? 1 : 0;
        if (strncmp(p + skip, "nan", 3) == 0
            && (p == msg || !isalnum((unsigned char)p[-1]))
            && !isalnum((unsigned char)p[skip + 3])) {
            memcpy(q, "NaN", 3);
            q += 3;
            p += skip + 3;
        } else {
            *q++ = *p++;
        }
    }
    *q = '\0';
}
