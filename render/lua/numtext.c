/*
** The shortest text of a number that reads back as it (numtext.h), for
** the figure language's messages.  The core's messages have the same rule
** in src/domain.c: each library hides its internals from the other.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "numtext.h"

const char *
cf__num_text(double x, char buf[CF__NUM_TEXT])
{
    int prec = 1;
    if (!isfinite(x)) {
        snprintf(buf, CF__NUM_TEXT, "%g", x);
        return buf;
    }
    for (; prec < 17; prec++) {
        snprintf(buf, CF__NUM_TEXT, "%.*g", prec, x);
        if (strtod(buf, NULL) == x)
            break;
    }
    if (fabs(x) >= 1.0 && fabs(x) < 1e17) {
        int digits = (int)floor(log10(fabs(x))) + 1;
        prec = digits > prec ? digits : prec;
    }
    snprintf(buf, CF__NUM_TEXT, "%.*g", prec, x);
    return buf;
}
