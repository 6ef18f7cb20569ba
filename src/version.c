/*
** The library's version at run time (curvefig/version.h).
*/
#include "curvefig/version.h"

int
cf_version(void)
{
    return CF_VERSION;
}

const char *
cf_version_string(void)
{
    return CF_VERSION_STRING;
}
