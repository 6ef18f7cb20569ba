/*
** Unicode properties from the generated table (render/fontfile/uprops.h):
** runs of code points with one general category and one script, each
** from its start to the next run's; a run of category 0xFF is outside the
** table.
*/
#include <stddef.h>

#include "uprops.h"

typedef struct uprops_run {
    uint32_t start;
    uint8_t gc;        /* 0xFF: not in the table */
    uint8_t script;    /* an index in uprops_scripts */
} uprops_run_t;

#include "uprops-table.h"

bool
cf__uprops(uint32_t c, unsigned *gc, uint32_t *script)
{
    size_t lo = 0, hi = sizeof uprops_runs / sizeof uprops_runs[0];
    /* the last run whose start is <= c */
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (uprops_runs[mid].start <= c)
            lo = mid;
        else
            hi = mid;
    }
    if (c < uprops_runs[lo].start || uprops_runs[lo].gc == 0xFF)
        return false;
    *gc = uprops_runs[lo].gc;
    *script = uprops_scripts[uprops_runs[lo].script];
    return true;
}

bool
cf__uprops_simple(uint32_t c)
{
    unsigned gc;
    uint32_t script;
    return cf__uprops(c, &gc, &script) && gc != CF__GC_SPACING_MARK
           && gc != CF__GC_ENCLOSING_MARK && gc != CF__GC_NON_SPACING_MARK
           && c != 0x2044;
}
