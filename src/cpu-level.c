/*
** The x86-64 level of the processor (core-private.h, CF__CLONED), from
** the features the C library found at start: x86-64-v2, v3 and v4 as the
** x86-64 psABI defines them, each feature usable (enabled by the system
** too), as GCC's target_clones checked them.
*/
#include "core-private.h"

#ifdef CF__LEVELS
#include <sys/platform/x86.h>
#endif

int
cf__cpu_level(void)
{
#ifdef CF__LEVELS
    bool v2 = CPU_FEATURE_ACTIVE(CMPXCHG16B) &&
              CPU_FEATURE_ACTIVE(LAHF64_SAHF64) &&
              CPU_FEATURE_ACTIVE(POPCNT) &&
              CPU_FEATURE_ACTIVE(SSE3) && CPU_FEATURE_ACTIVE(SSE4_1) &&
              CPU_FEATURE_ACTIVE(SSE4_2) && CPU_FEATURE_ACTIVE(SSSE3);
    bool v3 = v2 && CPU_FEATURE_ACTIVE(AVX) && CPU_FEATURE_ACTIVE(AVX2) &&
              CPU_FEATURE_ACTIVE(BMI1) && CPU_FEATURE_ACTIVE(BMI2) &&
              CPU_FEATURE_ACTIVE(F16C) && CPU_FEATURE_ACTIVE(FMA) &&
              CPU_FEATURE_ACTIVE(LZCNT) && CPU_FEATURE_ACTIVE(MOVBE) &&
              CPU_FEATURE_ACTIVE(OSXSAVE);
    bool v4 = v3 && CPU_FEATURE_ACTIVE(AVX512F) &&
              CPU_FEATURE_ACTIVE(AVX512BW) && CPU_FEATURE_ACTIVE(AVX512CD) &&
              CPU_FEATURE_ACTIVE(AVX512DQ) && CPU_FEATURE_ACTIVE(AVX512VL);
    return v4 ? 4 : v3 ? 3 : v2 ? 2 : 1;
#else
    return 1;
#endif
}
