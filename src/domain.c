/*
** The message of the domain rule (domain-private.h).
*/
#include "domain-private.h"
#include "numtext-private.h"

cf_status_t
cf__param_check(double a, double b, double *u, cf_diag_t *diag)
{
    cf_status_t st = cf__param_clamp(a, b, u);
    if (st == CF_STATUS_OK)
        return st;
    if (st == CF_STATUS_NOT_FINITE)
        return cf__error(diag, st, -1, "parameter is %s", CF__NUM(*u));
    return cf__error(diag, st, -1, "parameter %s is outside the domain "
                     "[%s, %s]", CF__NUM(*u), CF__NUM(a), CF__NUM(b));
}
