/*
** Units, colours, markers, label places, styles and themes.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "label-private.h"
#include "model.h"

/* ---- units -------------------------------------------------------------- */

double
cf_length_to_bp(double value, cf_unit_t unit)
{
    switch (unit) {
    case CF_UNIT_BP:
        return value;
    case CF_UNIT_TEXPT:
        return value * 72.0 / 72.27;
    case CF_UNIT_MM:
        return value * 72.0 / 25.4;
    case CF_UNIT_CM:
        return value * 720.0 / 25.4;
    case CF_UNIT_IN:
        return value * 72.0;
    default:
        return NAN;
    }
}

static int
name_index(const char *name, const char *const *names, size_t count)
{
    size_t i;
    for (i = 0; i < count; i++)
        if (names[i] != NULL && strcmp(name, names[i]) == 0)
            return (int)i;
    return -1;
}

cf_status_t
cf_unit_from_name(const char *name, cf_unit_t *out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    static const char *const names[] = { "bp", "pt", "texpt", "mm", "cm",
                                         "in" };
    static const cf_unit_t units[] = { CF_UNIT_BP, CF_UNIT_PT, CF_UNIT_TEXPT,
                                       CF_UNIT_MM, CF_UNIT_CM, CF_UNIT_IN };
    int i;
    if (name == NULL || out == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "unit name or output is NULL");
    i = name_index(name, names, sizeof names / sizeof names[0]);
    if (i < 0)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "unknown unit \"%s\" (use bp, pt, texpt, mm, cm "
                           "or in)", name);
    *out = units[i];
    return CF_STATUS_OK;
}

/* ---- colours ------------------------------------------------------------ */

typedef struct named_color {
    const char *name;
    unsigned rgb;
} named_color_t;

static const named_color_t named_colors[] = {
    { "black", 0x000000 },     { "white", 0xffffff },
    { "grey", 0x808080 },      { "gray", 0x808080 },
    { "red", 0xd62728 },       { "green", 0x2ca02c },
    { "blue", 0x1f5fbf },      { "orange", 0xf28e1c },
    { "yellow", 0xf2c500 },    { "purple", 0x8e44ad },
    { "brown", 0x8c564b },     { "cyan", 0x17becf },
    { "magenta", 0xcc3399 },   { "darkblue", 0x14306e },
    { "darkred", 0x8b1a1a },   { "darkgreen", 0x1d6b2c },
    { "lightgrey", 0xd0d0d0 }, { "lightgray", 0xd0d0d0 },
};

static int
hex_digit(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

static cf_color_t
rgb_color(unsigned rgb, double a)
{
    cf_color_t c;
    c.r = ((rgb >> 16) & 0xff) / 255.0;
    c.g = ((rgb >> 8) & 0xff) / 255.0;
    c.b = (rgb & 0xff) / 255.0;
    c.a = a;
    return c;
}

cf_status_t
cf_color_parse(const char *text, cf_color_t *out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    size_t i, len;
    if (text == NULL || out == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "colour text or output is NULL");
    len = strlen(text);
    if (text[0] == '#' && (len == 7 || len == 9)) {
        unsigned v[4] = { 0, 0, 0, 255 };
        for (i = 0; i < (len - 1) / 2; i++) {
            int hi = hex_digit(text[1 + 2 * i]);
            int lo = hex_digit(text[2 + 2 * i]);
            if (hi < 0 || lo < 0)
                return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                                   "colour \"%s\" is not #rrggbb or "
                                   "#rrggbbaa", text);
            v[i] = (unsigned)(hi * 16 + lo);
        }
        *out = rgb_color((v[0] << 16) | (v[1] << 8) | v[2], v[3] / 255.0);
        return CF_STATUS_OK;
    }
    if (strcmp(text, "none") == 0) {
        *out = rgb_color(0, 0.0);
        return CF_STATUS_OK;
    }
    for (i = 0; i < sizeof named_colors / sizeof named_colors[0]; i++) {
        if (strcmp(text, named_colors[i].name) == 0) {
            *out = rgb_color(named_colors[i].rgb, 1.0);
            return CF_STATUS_OK;
        }
    }
    return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                       "unknown colour \"%s\" (use #rrggbb, #rrggbbaa, none "
                       "or a colour name such as black, grey, blue)", text);
}

/* ---- markers and places ------------------------------------------------- */

cf_status_t
cf_marker_from_name(const char *name, cf_marker_t *out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    static const char *const names[CF_MARKER_LAST_] = {
        "none", "dot", "circle", "square", "diamond", "triangle", "cross",
        "plus", "star", "tick"
    };
    int i;
    if (name == NULL || out == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "marker name or output is NULL");
    i = name_index(name, names, CF_MARKER_LAST_);
    if (i < 0)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "unknown marker \"%s\" (use none, dot, circle, "
                           "square, diamond, triangle, cross, plus, star or "
                           "tick)", name);
    *out = (cf_marker_t)i;
    return CF_STATUS_OK;
}

cf_status_t
cf_place_from_name(const char *name, cf_place_t *out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    static const char *const names[] = {
        "center", "n", "ne", "e", "se", "s", "sw", "w", "nw",
        "centre", "above", "right", "below", "left", "auto"
    };
    static const cf_place_t places[] = {
        CF_PLACE_CENTER, CF_PLACE_N, CF_PLACE_NE, CF_PLACE_E, CF_PLACE_SE,
        CF_PLACE_S, CF_PLACE_SW, CF_PLACE_W, CF_PLACE_NW,
        CF_PLACE_CENTER, CF_PLACE_N, CF_PLACE_E, CF_PLACE_S, CF_PLACE_W,
        CF_PLACE_AUTO
    };
    int i;
    if (name == NULL || out == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "place name or output is NULL");
    i = name_index(name, names, sizeof names / sizeof names[0]);
    if (i < 0)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "unknown label place \"%s\" (use center, n, ne, "
                           "e, se, s, sw, w, nw, above, below, left, right "
                           "or auto)",
                           name);
    *out = places[i];
    return CF_STATUS_OK;
}

/* ---- styles ------------------------------------------------------------- */

void
cf_style_init(cf_style_t *style)
{
    if (style == NULL)
        return;
    memset(style, 0, sizeof *style);
}

static bool
color_ok(const cf_color_t *c)
{
    return isfinite(c->r) && isfinite(c->g) && isfinite(c->b)
        && isfinite(c->a) && c->r >= 0 && c->r <= 1 && c->g >= 0
        && c->g <= 1 && c->b >= 0 && c->b <= 1 && c->a >= 0 && c->a <= 1;
}

cf_status_t
cf__style_check(const cf_style_t *s, cf_diag_t *diag)
{
    size_t i;
    if (s == NULL)
        return CF_STATUS_OK;
    if (s->set & ~(unsigned)CF_STYLE_ALL_)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "style: unknown bits 0x%x in set",
                           s->set & ~(unsigned)CF_STYLE_ALL_);
    if ((s->set & CF_STYLE_COLOR) && !color_ok(&s->color))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "style: colour components must lie in [0, 1]");
    if ((s->set & CF_STYLE_FILL) && !color_ok(&s->fill))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "style: fill components must lie in [0, 1]");
    if ((s->set & CF_STYLE_MARKER_COLOR) && !color_ok(&s->marker_color))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "style: marker colour components must lie in "
                           "[0, 1]");
    if ((s->set & CF_STYLE_WIDTH) && !(isfinite(s->width) && s->width > 0))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "style: line width %g must be finite and positive",
                           s->width);
    if (s->set & CF_STYLE_DASH) {
        double sum = 0;
        if (s->dash_count > CF_STYLE_DASH_MAX)
            return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                               "style: %zu dash lengths (at most %d)",
                               s->dash_count, CF_STYLE_DASH_MAX);
        for (i = 0; i < s->dash_count; i++) {
            if (!(isfinite(s->dash[i]) && s->dash[i] >= 0))
                return cf_diag_set(diag, CF_STATUS_INVALID_ARG, (long)i,
                                   "style: dash length %zu (%g) must be "
                                   "finite and >= 0", i, s->dash[i]);
            sum += s->dash[i];
        }
        if (s->dash_count > 0 && !(sum > 0))
            return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                               "style: dash lengths are all zero");
    }
    if ((s->set & CF_STYLE_OPACITY)
        && !(isfinite(s->opacity) && s->opacity >= 0 && s->opacity <= 1))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "style: opacity %g must lie in [0, 1]", s->opacity);
    if ((s->set & CF_STYLE_MARKER)
        && ((unsigned)s->marker >= CF_MARKER_LAST_))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "style: unknown marker %d", (int)s->marker);
    if ((s->set & CF_STYLE_MARKER_SIZE)
        && !(isfinite(s->marker_size) && s->marker_size >= 0))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "style: marker size %g must be finite and >= 0",
                           s->marker_size);
    if ((s->set & CF_STYLE_FONT_SIZE)
        && !(isfinite(s->font_size) && s->font_size > 0
             && s->font_size <= 1000))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "style: font size %g must lie in (0, 1000] bp",
                           s->font_size);
    if ((s->set & CF_STYLE_PLACE) && ((unsigned)s->place >= CF_PLACE_LAST_))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "style: unknown label place %d", (int)s->place);
    if ((s->set & CF_STYLE_OFFSET) && !isfinite(s->offset))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "style: label offset is not finite");
    if ((s->set & CF_STYLE_HALO)
        && !(isfinite(s->halo) && s->halo >= 0 && s->halo <= 100))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "style: halo %g must lie in [0, 100] bp", s->halo);
    if ((s->set & CF_STYLE_ARROW_SIZE)
        && !(isfinite(s->arrow_size) && s->arrow_size >= 0))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "style: arrow size %g must be finite and >= 0",
                           s->arrow_size);
    return CF_STATUS_OK;
}

void
cf__style_resolve(const cf_theme_t *theme, cf_role_t role,
                  const cf_style_t *over, cf_style_t *out)
{
    size_t i;
    *out = theme->role[role];
    out->set = CF_STYLE_ALL_;
    if (over == NULL)
        return;
    if (over->set & CF_STYLE_COLOR)
        out->color = over->color;
    if (over->set & CF_STYLE_FILL)
        out->fill = over->fill;
    if (over->set & CF_STYLE_WIDTH)
        out->width = over->width;
    if (over->set & CF_STYLE_DASH) {
        out->dash_count = over->dash_count;
        for (i = 0; i < over->dash_count && i < CF_STYLE_DASH_MAX; i++)
            out->dash[i] = over->dash[i];
    }
    if (over->set & CF_STYLE_OPACITY)
        out->opacity = over->opacity;
    if (over->set & CF_STYLE_MARKER)
        out->marker = over->marker;
    if (over->set & CF_STYLE_MARKER_SIZE)
        out->marker_size = over->marker_size;
    if (over->set & CF_STYLE_MARKER_COLOR)
        out->marker_color = over->marker_color;
    else if (over->set & CF_STYLE_COLOR)
        /* a colour given for a point set colours its markers too */
        out->marker_color = over->color;
    if (over->set & CF_STYLE_FONT_SIZE)
        out->font_size = over->font_size;
    if (over->set & CF_STYLE_PLACE)
        out->place = over->place;
    if (over->set & CF_STYLE_OFFSET)
        out->offset = over->offset;
    if (over->set & CF_STYLE_ARROW_SIZE)
        out->arrow_size = over->arrow_size;
    if (over->set & CF_STYLE_HALO)
        out->halo = over->halo;
}

/* ---- themes ------------------------------------------------------------- */

static cf_style_t
role_style(unsigned rgb, double width, cf_marker_t marker, double msize,
           unsigned marker_rgb)
{
    cf_style_t s;
    memset(&s, 0, sizeof s);
    s.set = CF_STYLE_ALL_;
    s.color = rgb_color(rgb, 1.0);
    s.fill = rgb_color(0xffffff, 1.0);   /* ring interiors */
    s.width = width;
    s.opacity = 1.0;
    s.marker = marker;
    s.marker_size = msize;
    s.marker_color = rgb_color(marker_rgb, 1.0);
    s.font_size = 10.0 * 72.0 / 72.27;   /* 10 pt TeX */
    s.place = CF_PLACE_NE;
    s.offset = 2.5;
    s.arrow_size = 0.0;
    return s;
}

/* ---- palettes ----------------------------------------------------------- */

typedef struct palette {
    const char *name;
    size_t size;
    unsigned rgb[CF_PALETTE_MAX];
} palette_t;

static const palette_t palettes[] = {
    /* apart by a CIEDE2000 of 10 or more under protanopia, deuteranopia
    ** and tritanopia (Machado et al. 2009), every two of them and each
    ** from the polygon's grey (level 0 of a net); the first three (a
    ** cubic's de Casteljau levels) and that grey also in greyscale
    ** (docs/accessibility.md) */
    { "default", 8, { 0x2b3a8c,     /* dark blue */
                      0xe69f00,     /* orange */
                      0xa0522d,     /* sienna */
                      0x01665e,     /* dark teal */
                      0xd55e00,     /* vermillion */
                      0x6699cc,     /* mid blue */
                      0x0072b2,     /* blue */
                      0x92c5de } }, /* pale blue */
    /* M. Okabe and K. Ito, "Color Universal Design" (2002, 2008): orange,
    ** sky blue, bluish green, yellow, blue, vermillion, reddish purple,
    ** black */
    { "okabe-ito", 8, { 0xe69f00, 0x56b4e9, 0x009e73, 0xf0e442, 0x0072b2,
                        0xd55e00, 0xcc79a7, 0x000000 } },
    /* greys apart from each other and from the polygon's (0x8c8c8c) */
    { "greyscale", 3, { 0x1a1a1a, 0x5c5c5c, 0xb4b4b4 } },
};

#define PALETTE_COUNT (sizeof palettes / sizeof palettes[0])

static void
use_palette(cf_theme_t *t, const palette_t *p)
{
    size_t i;
    for (i = 0; i < p->size; i++)
        t->palette[i] = rgb_color(p->rgb[i], 1.0);
    t->palette_size = p->size;
}

cf_status_t
cf_theme_set_palette(cf_theme_t *theme, const char *name, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    const char *names[PALETTE_COUNT], *near;
    size_t i;
    if (theme == NULL || name == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "theme or palette name is NULL");
    for (i = 0; i < PALETTE_COUNT; i++) {
        names[i] = palettes[i].name;
        if (strcmp(name, palettes[i].name) == 0) {
            use_palette(theme, &palettes[i]);
            return CF_STATUS_OK;
        }
    }
    near = cf_nearest_name(name, names, PALETTE_COUNT);
    if (near != NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "unknown palette \"%s\" (did you mean \"%s\"?)",
                           name, near);
    return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                       "unknown palette \"%s\" (use default, okabe-ito or "
                       "greyscale)", name);
}

static void
theme_default(cf_theme_t *t)
{
    memset(t, 0, sizeof *t);
    t->role[CF_ROLE_CURVE] = role_style(0x14306e, 1.5, CF_MARKER_NONE, 0,
                                        0x14306e);
    t->role[CF_ROLE_POLYGON] = role_style(0x8c8c8c, 0.6, CF_MARKER_DOT, 3.6,
                                          0x3a3a3a);
    t->role[CF_ROLE_POLYLINE] = role_style(0x5a5a5a, 0.8, CF_MARKER_NONE,
                                           3.6, 0x3a3a3a);
    t->role[CF_ROLE_POINTS] = role_style(0x1a1a1a, 0.6, CF_MARKER_DOT, 4.0,
                                         0x1a1a1a);
    t->role[CF_ROLE_HULL] = role_style(0x6f95c9, 0.5, CF_MARKER_NONE, 3.6,
                                       0x3a3a3a);
    t->role[CF_ROLE_HULL].fill = rgb_color(0x9db8e0, 0.35);
    t->role[CF_ROLE_FILL] = role_style(0x6f95c9, 0.0, CF_MARKER_NONE, 3.6,
                                       0x3a3a3a);
    t->role[CF_ROLE_FILL].width = 0.5;
    t->role[CF_ROLE_FILL].color = rgb_color(0, 0.0);
    t->role[CF_ROLE_FILL].fill = rgb_color(0x9db8e0, 0.35);
    t->role[CF_ROLE_LABEL] = role_style(0x000000, 0.5, CF_MARKER_NONE, 0,
                                        0x000000);
    t->role[CF_ROLE_LABEL].offset = 4.0;   /* clear of a 3.6 bp dot */
    t->role[CF_ROLE_LABEL].place = CF_PLACE_AUTO;
    t->role[CF_ROLE_ARROW] = role_style(0xb22222, 0.9, CF_MARKER_NONE, 0,
                                        0xb22222);
    t->role[CF_ROLE_ARROW].arrow_size = 6.0;
    t->role[CF_ROLE_KNOTS] = role_style(0xb22222, 0.8, CF_MARKER_TICK, 6.0,
                                        0xb22222);
    t->role[CF_ROLE_AXES] = role_style(0x000000, 0.5, CF_MARKER_DOT, 3.2,
                                       0x000000);
    t->role[CF_ROLE_AXES].font_size = 8.0 * 72.0 / 72.27;
    t->role[CF_ROLE_AXES].arrow_size = 5.0;
    t->role[CF_ROLE_AXES].offset = 3.0;
    t->role[CF_ROLE_AXES].fill = rgb_color(0xdadada, 1.0);  /* grid */
    t->role[CF_ROLE_GRAPH] = role_style(0x14306e, 1.2, CF_MARKER_NONE, 0,
                                        0x14306e);
    t->role[CF_ROLE_NET] = role_style(0x000000, 0.8, CF_MARKER_DOT, 3.4,
                                      0x000000);
    use_palette(t, &palettes[0]);
    t->background = rgb_color(0xffffff, 1.0);
    snprintf(t->font_family, sizeof t->font_family, "%s",
             CF__DEFAULT_FAMILY);
    t->tick_size = 3.0;
}

static void
theme_mono(cf_theme_t *t)
{
    static const unsigned greys[] = { 0x000000, 0x707070, 0x404040,
                                      0xa0a0a0, 0x202020, 0x888888 };
    size_t i;
    theme_default(t);
    for (i = 0; i < CF_ROLE_LAST_; i++) {
        cf_color_t *c = &t->role[i].color;
        double y = 0.299 * c->r + 0.587 * c->g + 0.114 * c->b;
        c->r = c->g = c->b = y;
        c = &t->role[i].marker_color;
        y = 0.299 * c->r + 0.587 * c->g + 0.114 * c->b;
        c->r = c->g = c->b = y;
        c = &t->role[i].fill;
        y = 0.299 * c->r + 0.587 * c->g + 0.114 * c->b;
        c->r = c->g = c->b = y;
    }
    t->role[CF_ROLE_CURVE].color = rgb_color(0, 1.0);
    t->role[CF_ROLE_GRAPH].color = rgb_color(0, 1.0);
    for (i = 0; i < sizeof greys / sizeof greys[0]; i++)
        t->palette[i] = rgb_color(greys[i], 1.0);
    t->palette_size = sizeof greys / sizeof greys[0];
}

cf_status_t
cf_theme_get(const char *name, cf_theme_t *out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    if (name == NULL || out == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "theme name or output is NULL");
    if (strcmp(name, "default") == 0)
        theme_default(out);
    else if (strcmp(name, "mono") == 0)
        theme_mono(out);
    else
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "unknown theme \"%s\" (use default or mono)", name);
    return CF_STATUS_OK;
}

cf_status_t
cf_theme_set_fonts(cf_theme_t *theme, const char *family, double size_bp,
                   cf_diag_t *diag)
{
    cf_diag_clear(diag);
    const char *list = family;
    double k;
    size_t i;
    if (theme == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "theme is NULL");
    if (family != NULL && strcmp(family, "serif") == 0)
        list = CF__DEFAULT_FAMILY;
    else if (family != NULL && strcmp(family, "sans") == 0)
        list = CF__SANS_FAMILY;
    if (list != NULL && (list[0] == '\0'
                         || strlen(list) >= CF_FONT_FAMILY_MAX))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "font family \"%s\": give serif, sans or a "
                           "family list of 1 to %d bytes", list,
                           CF_FONT_FAMILY_MAX - 1);
    if (!(isfinite(size_bp) && size_bp >= 0 && size_bp <= 1000))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "font size %g bp must lie in (0, 1000]", size_bp);
    if (list != NULL)
        snprintf(theme->font_family, sizeof theme->font_family, "%s", list);
    if (size_bp > 0) {
        k = size_bp / theme->role[CF_ROLE_LABEL].font_size;
        for (i = 0; i < CF_ROLE_LAST_; i++)
            theme->role[i].font_size *= k;
    }
    return CF_STATUS_OK;
}

/* The style of the hidden pieces of a line in space (surface-lines.h). */
cf_style_t
cf__hidden_style(const cf_style_t *s)
{
    cf_style_t h = *s;
    h.width = 0.7 * s->width;
    h.dash_count = 2;
    h.dash[0] = fmax(4 * h.width, 1.5);
    h.dash[1] = fmax(3 * h.width, 1.2);
    return h;
}
