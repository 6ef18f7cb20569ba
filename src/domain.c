/*
** The message of the domain rule (domain-private.h).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "domain-private.h"

/* x with the fewest significant digits that read back as x, and at least
** its integer digits (1000000, not 1e+06). */
static void
shortest(double x, char *buf, size_t size)
{
    int prec = 1;
    while (prec < 17) {
        snprintf(buf, size, "%.*g", prec, x);
        if (strtod(buf, NULL) == x)
            break;
        prec++;
    }
    if (fabs(x) >= 1.0 && fabs(x) < 1e17) {
        int digits = (int)floor(log10(fabs(x))) + 1;
        prec = digits > prec ? digits : prec;
    }
    snprintf(buf, size, "%.*g", prec, x);
}

cf_status_t
cf__param_check(double a, double b, double *u, cf_diag_t *diag)
{
    char su[32], sa[32], sb[32];
    cf_status_t st = cf__param_clamp(a, b, u);
    if (st == CF_STATUS_OK)
        return st;
    if (st == CF_STATUS_NOT_FINITE)
        return cf__error(diag, st, -1, "parameter is %g", *u);
    shortest(*u, su, sizeof su);
    shortest(a, sa, sizeof sa);
    shortest(b, sb, sizeof sb);
    return cf__error(diag, st, -1, "parameter %s is outside the domain "
                     "[%s, %s]", su, sa, sb);
}
