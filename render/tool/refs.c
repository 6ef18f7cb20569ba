/*
** The reference images `curvefig test --update` writes; see refs.h.
*/
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "refs.h"
#include "imgfile.h"
#include "tool.h"

/* Copy from to `to` through a temporary name. */
static int
copy_atomic(const char *from, const char *to)
{
    char buf[65536];
    size_t n;
    FILE *in = fopen(from, "rb");
    cf__tool_out out;
    if (in == NULL)
        return -1;
    if (cf__tool_open_atomic(&out, to) != 0) {
        fclose(in);
        return -1;
    }
    while ((n = fread(buf, 1, sizeof buf, in)) > 0)
        if (fwrite(buf, 1, n, out.f) != n)
            break;
    if (ferror(in) || n > 0) {
        fclose(in);
        cf__tool_discard_atomic(&out);
        errno = EIO;
        return -1;
    }
    fclose(in);
    return cf__tool_close_atomic(&out);
}

/* What the old reference at ref_path is to the new image png. */
static cf__tool_ref_state
classify(cf__image *png, const char *ref_path,
         const cf__imgcmp_options *opt, double dpi, char *verdict,
         size_t size)
{
    struct stat sb;
    char err[1024];
    cf__image *ref;
    cf__imgcmp_result res;
    cf__tool_ref_state state = CF__TOOL_REF_CHANGED;
    if (stat(ref_path, &sb) != 0)
        return CF__TOOL_REF_ADDED;
    ref = cf__tool_image_read(ref_path, dpi, err, sizeof err);
    if (ref == NULL) {
        snprintf(verdict, size, "the old reference was unreadable");
        return CF__TOOL_REF_CHANGED;
    }
    if (cf__tool_image_compare(png, ref, opt, &res, NULL) != 0)
        snprintf(verdict, size, "the size changed from %dx%d to %dx%d "
                 "pixels", ref->width, ref->height,
                 png->width, png->height);
    else if (res.identical)
        state = CF__TOOL_REF_UNCHANGED;
    else
        cf__tool_image_verdict(verdict, size, &res, opt,
                               (long)ref->width * ref->height);
    cf__image_destroy(ref);
    return state;
}

cf__tool_ref_state
cf__tool_ref_update(const char *png_path, cf__image *png,
                    const char *ref_path, const cf__imgcmp_options *opt,
                    double dpi, char *verdict, size_t size)
{
    cf__tool_ref_state state;
    verdict[0] = '\0';
    state = classify(png, ref_path, opt, dpi, verdict, size);
    if (state != CF__TOOL_REF_UNCHANGED &&
        copy_atomic(png_path, ref_path) != 0) {
        fprintf(stderr, "curvefig: test: cannot write the reference %s: "
                "%s\n", ref_path, strerror(errno));
        return CF__TOOL_REF_FAILED;
    }
    return state;
}
