/*
** Reading a figure method's arguments (lstyle.h).
*/
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/bspline.h"
#include "curvefig/figure3d.h"
#include "lbezier.h"
#include "lbspline.h"
#include "lcommon.h"
#include "lschema.h"
#include "lstyle.h"

cf_figure_t *
cf__lua_check_figure(lua_State *L)
{
    cf__lua_fbox_t *b = cf__lua_check_self(L, CF__LUA_FIGURE, "figure");
    lua_Debug ar;
    if (b->fig == NULL)
        luaL_error(L, "figure: the figure was closed");
    /* the elements this method adds name the line that called it */
    cf_figure_set_line(b->fig, lua_getstack(L, 1, &ar)
                                       && lua_getinfo(L, "l", &ar)
                                   ? ar.currentline
                                   : 0);
    return b->fig;
}

bool
cf__lua_labels_on(lua_State *L)
{
    bool off;
    lua_getfield(L, LUA_REGISTRYINDEX, CF__LUA_NO_LABELS);
    off = lua_toboolean(L, -1);
    lua_pop(L, 1);
    return !off;
}

int
cf__lua_fig_check(lua_State *L, const char *fn, const cf_figure_t *fig,
                  cf_status_t st, const cf_diag_t *diag)
{
    cf_diag_t fd;
    if (st == CF_STATUS_OK)
        return 0;
    if (diag != NULL && diag->status != CF_STATUS_OK && diag->msg[0] != '\0')
        return cf__lua_fail(L, fn, st, diag);
    cf_diag_clear(&fd);
    if (fig != NULL)
        cf_figure_status(fig, &fd);
    return cf__lua_fail(L, fn, st, &fd);
}

/* Palette colour k (from 1) of fig's theme. */
static cf_color_t
palette_color(lua_State *L, lua_Integer k, const char *fn, const char *what,
              const cf_figure_t *fig)
{
    cf_theme_t th;
    cf_figure_get_theme(fig, &th);
    if (k < 1 || th.palette_size == 0)
        luaL_error(L, "%s: %s %d: palette colours count from 1", fn, what,
                   (int)k);
    return th.palette[(size_t)(k - 1) % th.palette_size];
}

/* {r, g, b} or {r, g, b, a} in 0..1 */
static cf_color_t
table_color(lua_State *L, int idx, const char *fn, const char *what)
{
    double v[4] = { 0, 0, 0, 1 };
    size_t n = (size_t)luaL_len(L, idx);
    cf_color_t c;
    if (n < 3 || n > 4)
        luaL_error(L, "%s: %s as a table is {r, g, b} or {r, g, b, a}", fn,
                   what);
    for (size_t k = 0; k < n; k++) {
        lua_geti(L, idx, (lua_Integer)k + 1);
        v[k] = cf__lua_check_finite(L, -1, fn, what);
        lua_pop(L, 1);
    }
    c.r = v[0];
    c.g = v[1];
    c.b = v[2];
    c.a = v[3];
    return c;
}

cf_color_t
cf__lua_read_color(lua_State *L, int idx, const char *fn, const char *what,
                   const cf_figure_t *fig)
{
    cf_color_t c = { 0, 0, 0, 1 };
    cf_diag_t diag;
    if (lua_isinteger(L, idx) && fig != NULL)
        return palette_color(L, lua_tointeger(L, idx), fn, what, fig);
    if (lua_istable(L, idx))
        return table_color(L, idx, fn, what);
    if (lua_type(L, idx) != LUA_TSTRING)
        luaL_error(L, "%s: %s must be a colour name, \"#rrggbb\", {r, g, b} "
                   "or a palette number", fn, what);
    cf_diag_clear(&diag);
    if (cf_color_parse(lua_tostring(L, idx), &c, &diag) != CF_STATUS_OK)
        luaL_error(L, "%s: %s: %s", fn, what, diag.msg);
    return c;
}

double
cf__lua_opt_number(lua_State *L, int idx, const char *key, const char *fn,
                   double def, bool *given)
{
    double v = def;
    if (given != NULL)
        *given = false;
    if (cf__lua_field(L, idx, key) != LUA_TNIL) {
        v = cf__lua_check_finite(L, -1, fn, key);
        if (given != NULL)
            *given = true;
    }
    lua_pop(L, 1);
    return v;
}

/* The named dash patterns (on, off, ... in bp). */
static const struct named_dash {
    const char *name;
    size_t count;
    double dash[4];
} named_dashes[] = {
    { "solid", 0, { 0, 0, 0, 0 } },
    { "dashed", 2, { 4, 2.5, 0, 0 } },
    { "dotted", 2, { 0.8, 1.6, 0, 0 } },
    { "dashdot", 4, { 4, 1.6, 0.8, 1.6 } },
};

static void
read_dash(lua_State *L, int idx, const char *fn, cf_style_t *s)
{
    size_t n;
    double *v;
    s->set |= CF_STYLE_DASH;
    if (lua_type(L, idx) == LUA_TSTRING) {
        const char *d = lua_tostring(L, idx);
        for (size_t i = 0; i < sizeof named_dashes / sizeof *named_dashes;
             i++) {
            if (strcmp(d, named_dashes[i].name) == 0) {
                s->dash_count = named_dashes[i].count;
                memcpy(s->dash, named_dashes[i].dash, sizeof s->dash[0] * 4);
                return;
            }
        }
        luaL_error(L, "%s: dash \"%s\": use \"solid\", \"dashed\", "
                   "\"dotted\", \"dashdot\" or {on, off, ...} in bp", fn, d);
    }
    v = cf__lua_check_numbers(L, idx, fn, "dash length", &n);
    if (n > CF_STYLE_DASH_MAX)
        luaL_error(L, "%s: at most %d dash lengths", fn, CF_STYLE_DASH_MAX);
    memcpy(s->dash, v, n * sizeof *v);
    s->dash_count = n;
    lua_pop(L, 1);
}

/* The colour and number fields of a style. */
static const struct style_field {
    const char *key;
    unsigned bit;
    size_t off;
    bool color;
} style_fields[] = {
    { "color", CF_STYLE_COLOR, offsetof(cf_style_t, color), true },
    { "fill", CF_STYLE_FILL, offsetof(cf_style_t, fill), true },
    { "marker_color", CF_STYLE_MARKER_COLOR,
      offsetof(cf_style_t, marker_color), true },
    { "width", CF_STYLE_WIDTH, offsetof(cf_style_t, width), false },
    { "opacity", CF_STYLE_OPACITY, offsetof(cf_style_t, opacity), false },
    { "marker_size", CF_STYLE_MARKER_SIZE, offsetof(cf_style_t, marker_size),
      false },
    { "font_size", CF_STYLE_FONT_SIZE, offsetof(cf_style_t, font_size),
      false },
    { "offset", CF_STYLE_OFFSET, offsetof(cf_style_t, offset), false },
    { "arrow_size", CF_STYLE_ARROW_SIZE, offsetof(cf_style_t, arrow_size),
      false },
    { "halo", CF_STYLE_HALO, offsetof(cf_style_t, halo), false },
};

/* An enumerated field (marker, place) through its parser. */
static bool
read_name(lua_State *L, int idx, const char *key, const char *fn,
          cf_status_t (*parse)(const char *, void *, cf_diag_t *), void *out)
{
    cf_diag_t diag;
    bool given = cf__lua_field(L, idx, key) != LUA_TNIL;
    cf_diag_clear(&diag);
    if (given && parse(cf__lua_opt_text(L, -1, fn, key, NULL), out, &diag))
        luaL_error(L, "%s: %s: %s", fn, key, diag.msg);
    lua_pop(L, 1);
    return given;
}

static cf_status_t
parse_marker(const char *name, void *out, cf_diag_t *diag)
{
    return cf_marker_from_name(name, out, diag);
}

static cf_status_t
parse_place(const char *name, void *out, cf_diag_t *diag)
{
    return cf_place_from_name(name, out, diag);
}

/* Read the style fields of the options table at idx (may be nil). */
static void
read_fields(lua_State *L, int idx, const char *fn, const cf_figure_t *fig,
            cf_style_t *s)
{
    cf_style_init(s);
    if (!lua_istable(L, idx))
        return;
    for (size_t i = 0; i < sizeof style_fields / sizeof *style_fields; i++) {
        const struct style_field *f = &style_fields[i];
        char *at = (char *)s + f->off;
        if (cf__lua_field(L, idx, f->key) != LUA_TNIL) {
            if (f->color)
                *(cf_color_t *)(void *)at =
                    cf__lua_read_color(L, -1, fn, f->key, fig);
            else
                *(double *)(void *)at =
                    cf__lua_check_finite(L, -1, fn, f->key);
            s->set |= f->bit;
        }
        lua_pop(L, 1);
    }
    if (cf__lua_field(L, idx, "dash") != LUA_TNIL)
        read_dash(L, lua_gettop(L), fn, s);
    lua_pop(L, 1);
    if (read_name(L, idx, "marker", fn, parse_marker, &s->marker))
        s->set |= CF_STYLE_MARKER;
    if (read_name(L, idx, "place", fn, parse_place, &s->place) ||
        read_name(L, idx, "anchor", fn, parse_place, &s->place))
        s->set |= CF_STYLE_PLACE;
}

/* The visible = "2-" option (the key check lets it through only where
** a method draws), set as the figure's overlay for what the method adds
** (curvefig/overlay.h); none given sets none. */
static void
read_overlay(lua_State *L, int idx, const char *fn, cf_figure_t *fig)
{
    const char *spec = NULL;
    cf_diag_t diag;
    int t = LUA_TNIL;
    if (lua_istable(L, idx)) {
        lua_pushliteral(L, "visible");
        t = lua_rawget(L, idx < 0 ? idx - 1 : idx);
        if (t == LUA_TSTRING || (t == LUA_TNUMBER && lua_isinteger(L, -1)))
            spec = lua_tostring(L, -1);
        else if (t != LUA_TNIL)
            luaL_error(L, "%s: visible is an overlay specification, a "
                       "string of steps such as \"2-\" or \"1,3\", not a %s",
                       fn, luaL_typename(L, -1));
    }
    cf_diag_clear(&diag);
    cf__lua_fig_check(L, fn, fig, cf_figure_set_overlay(fig, spec), &diag);
    if (lua_istable(L, idx))
        lua_pop(L, 1);
}

void
cf__lua_read_style(lua_State *L, int idx, const char *fn, cf_figure_t *fig,
                   cf_style_t *s)
{
    read_fields(L, idx, fn, fig, s);
    read_overlay(L, idx, fn, fig);
}

/* A sub-table of options (e.g. point = {...}) read as a style. */
bool
cf__lua_read_sub_style(lua_State *L, int idx, const char *key,
                       const char *fn, const cf_figure_t *fig, cf_style_t *s)
{
    bool present = false;
    cf_style_init(s);
    if (cf__lua_field(L, idx, key) != LUA_TNIL) {
        present = lua_toboolean(L, -1);
        if (lua_istable(L, -1))
            read_fields(L, lua_gettop(L), fn, fig, s);
        else if (!lua_isboolean(L, -1))
            luaL_error(L, "%s: %s is a style table, e.g. { color = \"red\" }, "
                       "got %s", fn, key, luaL_typename(L, -1));
    }
    lua_pop(L, 1);
    return present;
}

/* The units of a length, for the messages. */
#define LENGTH_UNITS "cm, mm, in; bp or pt: the PostScript point, 1/72 in; " \
                     "texpt: TeX's point, 1/72.27 in"

double
cf__lua_read_length(lua_State *L, int idx, const char *fn, const char *what,
                    double def_bp)
{
    const char *s;
    char *end;
    double v;
    cf_unit_t unit;
    if (lua_isnoneornil(L, idx))
        return def_bp;
    if (lua_type(L, idx) == LUA_TNUMBER) {
        /* 8 meant as cm would silently be 8 bp: only 0 needs no unit */
        v = cf__lua_check_finite(L, idx, fn, what);
        if (v != 0)
            return luaL_error(L, "%s: %s = %s: give a unit, e.g. \"%scm\" "
                              "(%s)", fn, what, lua_tostring(L, idx),
                              lua_tostring(L, idx), LENGTH_UNITS);
        return 0;
    }
    s = luaL_checkstring(L, idx);
    v = strtod(s, &end);
    while (*end == ' ')
        end++;
    if (end == s || *end == '\0' || cf_unit_from_name(end, &unit, NULL))
        return luaL_error(L, "%s: %s \"%s\": give a number and a unit, "
                          "e.g. \"8cm\" (%s)", fn, what, s, LENGTH_UNITS);
    return cf_length_to_bp(v, unit);
}


bool
cf__lua_opt_bool(lua_State *L, int idx, const char *key, const char *fn,
                 bool def)
{
    bool v;
    cf__lua_field(L, idx, key);
    v = cf__lua_opt_bool_arg(L, -1, fn, key, def);
    lua_pop(L, 1);
    return v;
}


/* The points at idx, in their own dimension: a curve's control points, a
** list of points or one point; a buffer pushed on the stack. */
static double *
any_points(lua_State *L, int idx, const char *fn, size_t *n, size_t *dim)
{
    cf_bezier_t *bz = cf__lua_to_bezier(L, idx);
    cf_bspline_t *bs = cf__lua_to_bspline(L, idx);
    double *p;
    int first = LUA_TNIL;
    if (bz != NULL) {
        *dim = cf_bezier_dim(bz);
        *n = (size_t)cf_bezier_degree(bz) + 1;
        p = cf__lua_buffer(L, *n * *dim);
        cf_bezier_get_points(bz, p);
        return p;
    }
    if (bs != NULL) {
        *dim = cf_bspline_dim(bs);
        *n = cf_bspline_count(bs);
        p = cf__lua_buffer(L, *n * *dim);
        cf_bspline_get_points(bs, p);
        return p;
    }
    if (lua_istable(L, idx)) {
        first = lua_geti(L, idx, 1);
        lua_pop(L, 1);
    }
    *dim = 0;
    *n = 1;
    if (first == LUA_TNUMBER)
        return cf__lua_check_point(L, idx, fn, "point", dim);
    return cf__lua_check_points(L, idx, fn, "point", 1, n, dim);
}

double *
cf__lua_check_points3d(lua_State *L, cf_figure_t *fig, int idx,
                       const char *fn, size_t *count)
{
    size_t n, dim, top = (size_t)lua_gettop(L);
    double *p;
    if (!cf_figure_get_view(fig, NULL))
        return NULL;
    p = any_points(L, idx, fn, &n, &dim);
    if (dim != 3) {
        lua_settop(L, (int)top);
        return NULL;
    }
    *count = n;
    return p;
}

double *
cf__lua_check_points2d(lua_State *L, cf_figure_t *fig, int idx,
                       const char *fn, size_t *count)
{
    size_t n, dim;
    double *p = any_points(L, idx, fn, &n, &dim), *out;
    if (dim < 2)
        luaL_error(L, "%s: points in R^1 cannot be drawn; give {x, y}", fn);
    out = cf__lua_buffer(L, 2 * n);
    cf__lua_fig_check(L, fn, fig, cf_figure_project(fig, p, n, dim, out),
                      NULL);
    *count = n;
    return out;
}
