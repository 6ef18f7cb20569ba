/*
** A figure written from C: a cubic Bézier curve with its control polygon
** and labelled control points, as an SVG and a PDF.
**   cc figure.c $(pkg-config --cflags --libs curvefig-render)
** Usage: figure [OUTPUT-BASENAME]   (default: bezier-from-c)
*/
#include <stdio.h>

#include <curvefig/curvefig.h>
#include <curvefig/figure.h>

int
main(int argc, char **argv)
{
    static const double P[] = { 0, 0, 1, 2, 3, 2, 4, 0 };
    const char *base = argc > 1 ? argv[1] : "bezier-from-c";
    cf_figure_t *fig = NULL;
    cf_bezier_t *c = NULL;
    cf_style_t red;
    cf_diag_t diag;
    int rc = 1;

    cf_diag_clear(&diag);
    cf_style_init(&red);
    red.set = CF_STYLE_COLOR;
    if (cf_color_parse("red", &red.color, &diag) != CF_STATUS_OK
        || cf_bezier_create(2, 3, P, NULL, &c, &diag) != CF_STATUS_OK
        || cf_figure_create(8, 5, CF_UNIT_CM, &fig, &diag) != CF_STATUS_OK)
        goto done;
    cf_figure_set_title(fig, "A cubic Bézier curve");
    cf_figure_add_polygon(fig, P, 4, NULL);
    cf_figure_add_bezier(fig, c, &red);
    for (int i = 0; i < 4; i++) {
        char text[8];
        cf_style_t place;
        cf_style_init(&place);
        place.set = CF_STYLE_PLACE;
        place.place = P[2 * i + 1] > 1 ? CF_PLACE_N : CF_PLACE_S;
        snprintf(text, sizeof text, "P_%d", i);
        cf_figure_add_label(fig, P[2 * i], P[2 * i + 1], text, &place);
    }
    /* Adding elements records the first error in the figure; it is
    ** reported here and by cf_figure_write. */
    if (cf_figure_status(fig, &diag) != CF_STATUS_OK
        || cf_figure_write_all(fig, base,
                               CF_FORMAT_BIT(CF_FORMAT_SVG)
                                   | CF_FORMAT_BIT(CF_FORMAT_PDF),
                               NULL, &diag) != CF_STATUS_OK)
        goto done;
    printf("wrote %s.svg and %s.pdf\n", base, base);
    rc = 0;
done:
    if (rc != 0)
        fprintf(stderr, "figure: %s\n", diag.msg);
    cf_figure_destroy(fig);
    cf_bezier_destroy(c);
    return rc;
}
