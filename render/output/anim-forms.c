/*
** The files of an animation (anim.h): the animated SVG (svg-anim.c), the
** PDF of one page per frame, and the sinks of anim-sink.h that encode the
** rasters (GIF, APNG, MP4, WebM); each file written whole at the end
** (cf_write_file; the videos by their sinks, through a temporary file
** renamed at finish).
*/
#include <stdio.h>
#include <string.h>

#include "anim-write-private.h"

const char *
cf__anim_extension(unsigned output)
{
    switch (output) {
    case CF__ANIM_OUT_SVG: return "svg";
    case CF__ANIM_OUT_PDF: return "pdf";
    case CF__ANIM_OUT_GIF: return "gif";
    case CF__ANIM_OUT_APNG: return "apng";
    case CF__ANIM_OUT_MP4: return "mp4";
    case CF__ANIM_OUT_WEBM: return "webm";
    default: return "";
    }
}

/* The file of form bit. */
static char *
form_path(const anim_t *a, unsigned bit)
{
    const char *ext = cf__anim_extension(bit);
    char *p = cf_malloc(strlen(a->o->base) + strlen(ext) + 2);
    if (p != NULL)
        sprintf(p, "%s.%s", a->o->base, ext);
    return p;
}

cf_status_t
cf__anim_forms_open(anim_t *a, forms_t *f, cf_diag_t *diag)
{
    unsigned out = a->o->outputs;
    memset(f, 0, sizeof *f);
    if (out & CF__ANIM_OUT_PDF) {
        /* the PDF writer; its fonts tried on first use (the frames are
        ** not kept to be played again) */
        f->pdfw = cf_calloc(1, sizeof *f->pdfw);
        if (f->pdfw == NULL)
            return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                               "out of memory opening the pdf");
        cf__pdf_writer_init(f->pdfw, &f->outliner);
        f->pdfw->probe = true;
    }
    if (out & CF__ANIM_OUT_RASTER) {
        static const unsigned raster_bits[4] = {
            CF__ANIM_OUT_GIF, CF__ANIM_OUT_APNG, CF__ANIM_OUT_MP4,
            CF__ANIM_OUT_WEBM
        };
        double fps = 1.0 / a->src->seconds;
        for (int i = 0; i < 4; i++) {
            char *path = NULL;
            cf_status_t st;
            if (!(out & raster_bits[i]))
                continue;
            if (i >= 2 && (path = form_path(a, raster_bits[i])) == NULL)
                return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                                   "out of memory for a file name");
            st = cf__anim_sink_open((cf__anim_kind_t)i, a->wpx, a->hpx, fps,
                                    a->o->loop, path, &f->sink[i], diag);
            cf_free(path);
            if (st != CF_STATUS_OK)
                return st;
        }
    }
    return CF_STATUS_OK;
}

void
cf__anim_forms_free(forms_t *f)
{
    cf__svg_anim_free(&f->svg);
    if (f->pdfw != NULL) {
        cf__pdfw_fini(f->pdfw);
        cf_free(f->pdfw);
        f->pdfw = NULL;
    }
    cf__glyph_outliner_fini(&f->outliner);
    cf__buf_free(&f->pdf);
    for (int i = 0; i < 4; i++) {
        cf__anim_sink_abort(f->sink[i]);
        f->sink[i] = NULL;
        cf__buf_free(&f->bytes[i]);
    }
}

cf_status_t
cf__anim_vector_frame(anim_t *a, forms_t *f, unsigned k, cf__dl_t *dl,
             cf_diag_t *diag)
{
    unsigned step = 0;
    cf_figure_t *fig;
    cf_status_t st;
    if (!(a->o->outputs & (CF__ANIM_OUT_SVG | CF__ANIM_OUT_PDF)))
        return CF_STATUS_OK;
    st = cf__anim_frame_dl(a, k, dl, &step, &fig, diag);
    if (st == CF_STATUS_OK && (a->o->outputs & CF__ANIM_OUT_SVG))
        st = cf__svg_anim_add(&f->svg, dl, &a->page, step, a->src->seconds,
                              diag);
    if (st == CF_STATUS_OK && (a->o->outputs & CF__ANIM_OUT_PDF)) {
        cf__pdfw_backend.begin_page(f->pdfw, &a->page);
        cf__dl_play_step(dl, &a->page, step, &cf__pdfw_backend, f->pdfw);
        if (cf__pdfw_backend.end_page(f->pdfw) != 0) {
            char what[48];
            snprintf(what, sizeof what, "page %u of the pdf", k + 1);
            st = cf__scopes_diag(&f->pdfw->sc, "PDF", what, diag);
        }
    }
    cf__anim_frame_done(a, k, dl, fig);
    return st;
}

cf_status_t
cf__anim_raster_add(forms_t *f, cairo_surface_t *surf, double seconds,
           cf_diag_t *diag)
{
    for (int i = 0; i < 4; i++)
        if (f->sink[i] != NULL) {
            cf_status_t st = cf__anim_sink_add(f->sink[i], surf, seconds,
                                               diag);
            if (st != CF_STATUS_OK)
                return st;
        }
    return CF_STATUS_OK;
}

cf_status_t
cf__anim_forms_finish(anim_t *a, forms_t *f, cf_diag_t *diag)
{
    unsigned out = a->o->outputs;
    cf_status_t st = CF_STATUS_OK;
    cf__buf_t svg;
    char *path;
    memset(&svg, 0, sizeof svg);
    for (int i = 0; i < 4 && st == CF_STATUS_OK; i++)
        if (f->sink[i] != NULL) {
            st = cf__anim_sink_finish(f->sink[i], i < 2 ? &f->bytes[i] : NULL,
                                      diag);
            f->sink[i] = NULL;
        }
    if (st == CF_STATUS_OK && (out & CF__ANIM_OUT_SVG))
        st = cf__svg_anim_finish(&f->svg, a->src->same_figure
                                              ? a->src->frames - 1 : 0,
                                 a->title, a->caption, &svg, diag);
    if (st == CF_STATUS_OK && f->pdfw != NULL) {
        char date[40];
        int r;
        cf__pdf_date(date, sizeof date);
        r = cf__pdfw_document(f->pdfw, a->title, a->caption, date, &f->pdf);
        if (r == 1)
            st = cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                             "the pdf: a font of the labels could not be "
                             "embedded");
        else if (r != 0)
            st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                             "out of memory writing the pdf");
    }
    for (unsigned bit = 1; bit <= CF__ANIM_OUT_APNG && st == CF_STATUS_OK;
         bit <<= 1) {
        const cf__buf_t *b = bit == CF__ANIM_OUT_SVG ? &svg
                             : bit == CF__ANIM_OUT_PDF ? &f->pdf
                             : bit == CF__ANIM_OUT_GIF ? &f->bytes[0]
                             : &f->bytes[1];
        if (!(out & bit))
            continue;
        path = form_path(a, bit);
        st = path == NULL ? cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                                        "out of memory for a file name")
                          : cf_write_file(path, b->data, b->size, diag);
        cf_free(path);
    }
    cf__buf_free(&svg);
    return st;
}
