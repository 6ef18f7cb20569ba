/*
** Lua binding of figures (include/curvefig/figure.h): figure{...} and its
** drawing methods.  Every method draws through one cf_figure_add_* call;
** options tables are read into a cf_style_t by read_style.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/bspline.h"
#include "curvefig/figure.h"
#include "lbezier.h"
#include "lbspline.h"
#include "lcommon.h"
#include "lfigure.h"

#define FIGURES_KEY "curvefig.figures"

typedef struct fbox {
    cf_figure_t *fig;
} fbox;

static int
gc(lua_State *L)
{
    fbox *b = luaL_checkudata(L, 1, CF__LUA_FIGURE);
    cf_figure_destroy(b->fig);
    b->fig = NULL;
    return 0;
}

static cf_figure_t *
check_fig(lua_State *L, int idx)
{
    fbox *b = luaL_checkudata(L, idx, CF__LUA_FIGURE);
    if (b->fig == NULL)
        luaL_error(L, "figure: the figure was closed");
    return b->fig;
}

static int
tostring(lua_State *L)
{
    luaL_checkudata(L, 1, CF__LUA_FIGURE);
    lua_getiuservalue(L, 1, 1);
    lua_pushfstring(L, "figure %s", lua_tostring(L, -1));
    return 1;
}

/* False under `curvefig render --no-labels` (the label-free layer of the
** pixel tests): every label, tick label and axis label is left out. */
static bool
labels_on(lua_State *L)
{
    bool off;
    lua_getfield(L, LUA_REGISTRYINDEX, CF__LUA_NO_LABELS);
    off = lua_toboolean(L, -1);
    lua_pop(L, 1);
    return !off;
}

/* Raise an error for a failed call: the message of diag if it has one,
** otherwise the figure's (the figure functions keep their message in the
** figure, like cairo). */
static int
check_(lua_State *L, const char *fn, const cf_figure_t *fig, cf_status_t st,
       const cf_diag_t *diag)
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

#define check(L, fn, call, diag) check_((L), (fn), fig, (call), (diag))

/* ---- options ------------------------------------------------------------ */

static const char *const style_keys[] = {
    "color", "fill", "width", "dash", "opacity", "marker", "marker_size",
    "marker_color", "font_size", "place", "anchor", "offset", "arrow_size",
    NULL,
};

static bool
in_list(const char *key, const char *const *list)
{
    for (; list != NULL && *list != NULL; list++)
        if (strcmp(key, *list) == 0)
            return true;
    return false;
}

/* Every key of the options table must be a style key or one of extra. */
static void
check_keys(lua_State *L, int idx, const char *fn, const char *const *extra)
{
    if (lua_isnoneornil(L, idx))
        return;
    if (!lua_istable(L, idx))
        luaL_error(L, "%s: options must be a table, got %s", fn,
                   luaL_typename(L, idx));
    lua_pushnil(L);
    while (lua_next(L, idx) != 0) {
        const char *key;
        lua_pop(L, 1);
        if (lua_type(L, -1) != LUA_TSTRING)
            luaL_error(L, "%s: option names must be strings", fn);
        key = lua_tostring(L, -1);
        if (!in_list(key, style_keys) && !in_list(key, extra))
            luaL_error(L, "%s: unknown option '%s'", fn, key);
    }
}

static cf_color_t
read_color(lua_State *L, int idx, const char *fn, const char *what,
           const cf_figure_t *fig)
{
    cf_color_t c = { 0, 0, 0, 1 };
    cf_diag_t diag;
    if (lua_isinteger(L, idx) && fig != NULL) {
        cf_theme_t th;
        lua_Integer k = lua_tointeger(L, idx);
        cf_figure_get_theme(fig, &th);
        if (k < 1 || th.palette_size == 0)
            luaL_error(L, "%s: %s %d: palette colours count from 1", fn, what,
                       (int)k);
        return th.palette[(size_t)(k - 1) % th.palette_size];
    }
    if (lua_istable(L, idx)) {
        double v[4] = { 0, 0, 0, 1 };
        size_t n = (size_t)luaL_len(L, idx);
        if (n < 3 || n > 4)
            luaL_error(L, "%s: %s as a table is {r, g, b} or {r, g, b, a}",
                       fn, what);
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
    if (lua_type(L, idx) != LUA_TSTRING)
        luaL_error(L, "%s: %s must be a colour name, \"#rrggbb\", {r, g, b} "
                   "or a palette number", fn, what);
    cf_diag_clear(&diag);
    if (cf_color_parse(lua_tostring(L, idx), &c, &diag) != CF_STATUS_OK)
        luaL_error(L, "%s: %s: %s", fn, what, diag.msg);
    return c;
}

static double
opt_number(lua_State *L, int idx, const char *key, const char *fn,
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

static void
read_dash(lua_State *L, int idx, const char *fn, cf_style_t *s)
{
    if (lua_type(L, idx) == LUA_TSTRING) {
        const char *d = lua_tostring(L, idx);
        if (strcmp(d, "dashed") == 0) {
            s->dash[0] = 4;
            s->dash[1] = 2.5;
            s->dash_count = 2;
        } else if (strcmp(d, "dotted") == 0) {
            s->dash[0] = 0.8;
            s->dash[1] = 1.6;
            s->dash_count = 2;
        } else if (strcmp(d, "dashdot") == 0) {
            s->dash[0] = 4;
            s->dash[1] = 1.6;
            s->dash[2] = 0.8;
            s->dash[3] = 1.6;
            s->dash_count = 4;
        } else if (strcmp(d, "solid") == 0) {
            s->dash_count = 0;
        } else {
            luaL_error(L, "%s: dash \"%s\": use \"solid\", \"dashed\", "
                       "\"dotted\", \"dashdot\" or {on, off, ...} in bp", fn,
                       d);
        }
    } else {
        size_t n;
        double *v = cf__lua_check_numbers(L, idx, fn, "dash length", &n);
        if (n > CF_STYLE_DASH_MAX)
            luaL_error(L, "%s: at most %d dash lengths", fn,
                       CF_STYLE_DASH_MAX);
        memcpy(s->dash, v, n * sizeof *v);
        s->dash_count = n;
        lua_pop(L, 1);
    }
    s->set |= CF_STYLE_DASH;
}

/* Read the style fields of the options table at idx (may be nil). */
static void
read_style(lua_State *L, int idx, const char *fn, const cf_figure_t *fig,
           cf_style_t *s)
{
    bool given;
    cf_diag_t diag;
    cf_style_init(s);
    if (!lua_istable(L, idx))
        return;
    if (cf__lua_field(L, idx, "color") != LUA_TNIL) {
        s->color = read_color(L, -1, fn, "color", fig);
        s->set |= CF_STYLE_COLOR;
    }
    lua_pop(L, 1);
    if (cf__lua_field(L, idx, "fill") != LUA_TNIL) {
        s->fill = read_color(L, -1, fn, "fill", fig);
        s->set |= CF_STYLE_FILL;
    }
    lua_pop(L, 1);
    if (cf__lua_field(L, idx, "marker_color") != LUA_TNIL) {
        s->marker_color = read_color(L, -1, fn, "marker_color", fig);
        s->set |= CF_STYLE_MARKER_COLOR;
    }
    lua_pop(L, 1);
    if (cf__lua_field(L, idx, "dash") != LUA_TNIL)
        read_dash(L, lua_gettop(L), fn, s);
    lua_pop(L, 1);
    s->width = opt_number(L, idx, "width", fn, 0, &given);
    s->set |= given ? CF_STYLE_WIDTH : 0;
    s->opacity = opt_number(L, idx, "opacity", fn, 0, &given);
    s->set |= given ? CF_STYLE_OPACITY : 0;
    s->marker_size = opt_number(L, idx, "marker_size", fn, 0, &given);
    s->set |= given ? CF_STYLE_MARKER_SIZE : 0;
    s->font_size = opt_number(L, idx, "font_size", fn, 0, &given);
    s->set |= given ? CF_STYLE_FONT_SIZE : 0;
    s->offset = opt_number(L, idx, "offset", fn, 0, &given);
    s->set |= given ? CF_STYLE_OFFSET : 0;
    s->arrow_size = opt_number(L, idx, "arrow_size", fn, 0, &given);
    s->set |= given ? CF_STYLE_ARROW_SIZE : 0;
    if (cf__lua_field(L, idx, "marker") != LUA_TNIL) {
        cf_diag_clear(&diag);
        if (cf_marker_from_name(luaL_checkstring(L, -1), &s->marker, &diag))
            luaL_error(L, "%s: marker: %s", fn, diag.msg);
        s->set |= CF_STYLE_MARKER;
    }
    lua_pop(L, 1);
    if (cf__lua_field(L, idx, "place") != LUA_TNIL ||
        (lua_pop(L, 1), cf__lua_field(L, idx, "anchor")) != LUA_TNIL) {
        cf_diag_clear(&diag);
        if (cf_place_from_name(luaL_checkstring(L, -1), &s->place, &diag))
            luaL_error(L, "%s: place: %s", fn, diag.msg);
        s->set |= CF_STYLE_PLACE;
    }
    lua_pop(L, 1);
}

/* A sub-table of options (e.g. point = {...}) read as a style. */
static bool
read_sub_style(lua_State *L, int idx, const char *key, const char *fn,
               const cf_figure_t *fig, cf_style_t *s)
{
    bool present = false;
    cf_style_init(s);
    if (cf__lua_field(L, idx, key) != LUA_TNIL) {
        present = lua_toboolean(L, -1);
        if (lua_istable(L, -1)) {
            check_keys(L, lua_gettop(L), fn, NULL);
            read_style(L, lua_gettop(L), fn, fig, s);
        }
    }
    lua_pop(L, 1);
    return present;
}

/* ---- points ------------------------------------------------------------- */

/* Points given as a curve (its control points), a list of points or one
** point; pushes a buffer of 2D points (projected if needed). */
static double *
check_points2d(lua_State *L, cf_figure_t *fig, int idx, const char *fn,
               size_t *count)
{
    size_t n, dim;
    double *p, *out;
    cf_bezier_t *bz = cf__lua_to_bezier(L, idx);
    cf_bspline_t *bs = cf__lua_to_bspline(L, idx);
    if (bz != NULL) {
        dim = cf_bezier_dim(bz);
        n = (size_t)cf_bezier_degree(bz) + 1;
        p = cf__lua_buffer(L, n * dim);
        cf_bezier_get_points(bz, p);
    } else if (bs != NULL) {
        dim = cf_bspline_dim(bs);
        n = cf_bspline_count(bs);
        p = cf__lua_buffer(L, n * dim);
        cf_bspline_get_points(bs, p);
    } else {
        int first = LUA_TNIL;
        if (lua_istable(L, idx)) {
            first = lua_geti(L, idx, 1);
            lua_pop(L, 1);
        }
        dim = 0;
        if (first == LUA_TNUMBER) {
            p = cf__lua_check_point(L, idx, fn, "point", &dim);
            n = 1;
        } else {
            p = cf__lua_check_points(L, idx, fn, "point", 1, &n, &dim);
        }
    }
    if (dim < 2)
        luaL_error(L, "%s: points in R^1 cannot be drawn; give {x, y}", fn);
    out = cf__lua_buffer(L, 2 * n);
    check(L, fn, cf_figure_project(fig, p, n, dim, out), NULL);
    *count = n;
    return out;
}

/* Call string.format(fmt, ...) with the given integers; pushes the text. */
static const char *
format_label(lua_State *L, const char *fmt, const lua_Integer *args,
             int nargs)
{
    lua_getfield(L, LUA_REGISTRYINDEX, "curvefig.format");
    lua_pushstring(L, fmt);
    for (int k = 0; k < nargs; k++)
        lua_pushinteger(L, args[k]);
    lua_call(L, nargs + 1, 1);
    return lua_tostring(L, -1);
}

/* The label of item i from opts.labels: a format ("P_%d", applied to
** i + label_start and extra args), a table of strings (false skips) or a
** function(i, ...) returning a string or nil.  Pushes it (or nil). */
static const char *
item_label(lua_State *L, int opts, size_t i, const lua_Integer *args,
           int nargs)
{
    int t = cf__lua_field(L, opts, "labels");
    const char *s = NULL;
    if (t == LUA_TSTRING) {
        const char *fmt = lua_tostring(L, -1);
        s = format_label(L, fmt, args, nargs);
        lua_remove(L, -2);
        return s;
    }
    if (t == LUA_TTABLE) {
        lua_geti(L, -1, (lua_Integer)i + 1);
        lua_remove(L, -2);
    } else if (t == LUA_TFUNCTION) {
        for (int k = 0; k < nargs; k++)
            lua_pushinteger(L, args[k]);
        lua_call(L, nargs, 1);
    } else if (t != LUA_TNIL && t != LUA_TBOOLEAN) {
        luaL_error(L, "labels must be a format string, a table of strings "
                   "or a function");
    }
    if (lua_type(L, -1) == LUA_TSTRING || lua_type(L, -1) == LUA_TNUMBER)
        s = lua_tostring(L, -1);
    else if (!lua_isnil(L, -1) && !lua_isboolean(L, -1))
        luaL_error(L, "label %d is a %s, not a string", (int)i,
                   luaL_typename(L, -1));
    return s;
}

/* Labels for n points at pts (2D) from opts (labels, label_start,
** label_place: one place or a table of places, label_style). */
static void
label_points(lua_State *L, cf_figure_t *fig, int opts, const double *pts,
             size_t n, const char *fn)
{
    cf_style_t base;
    lua_Integer start;
    cf_diag_t diag;
    int top = lua_gettop(L);
    if (!labels_on(L))
        return;
    if (cf__lua_field(L, opts, "labels") == LUA_TNIL ||
        (lua_isboolean(L, -1) && !lua_toboolean(L, -1))) {
        lua_settop(L, top);
        return;
    }
    lua_settop(L, top);
    read_sub_style(L, opts, "label_style", fn, fig, &base);
    start = (lua_Integer)opt_number(L, opts, "label_start", fn, 0, NULL);
    for (size_t i = 0; i < n; i++) {
        lua_Integer arg = start + (lua_Integer)i;
        cf_style_t ls = base;
        const char *text = item_label(L, opts, i, &arg, 1);
        /* label_place: one place for all, a table with one per point, or
        ** a function(i, x, y) of the label's index (as labels gets it)
        ** and point returning a place or nil */
        int t = cf__lua_field(L, opts, "label_place");
        if (t == LUA_TTABLE) {
            t = lua_geti(L, -1, (lua_Integer)i + 1);
        } else if (t == LUA_TFUNCTION) {
            lua_pushinteger(L, start + (lua_Integer)i);
            lua_pushnumber(L, pts[2 * i]);
            lua_pushnumber(L, pts[2 * i + 1]);
            lua_call(L, 3, 1);
            t = lua_type(L, -1);
        }
        if (t == LUA_TSTRING) {
            cf_diag_clear(&diag);
            if (cf_place_from_name(lua_tostring(L, -1), &ls.place, &diag))
                luaL_error(L, "%s: label_place: %s", fn, diag.msg);
            ls.set |= CF_STYLE_PLACE;
        } else if (t != LUA_TNIL) {
            luaL_error(L, "%s: label_place is a place (\"ne\"), a table "
                       "of places, one per point, or a function(i, x, y) "
                       "returning a place (label %d got a %s)", fn,
                       (int)(start + (lua_Integer)i), lua_typename(L, t));
        }
        if (text != NULL) {
            cf_diag_clear(&diag);
            check(L, fn, cf_figure_add_label(fig, pts[2 * i], pts[2 * i + 1],
                                             text, &ls), &diag);
        }
        lua_settop(L, top);
    }
}

/* ---- figure{...} -------------------------------------------------------- */

static double
read_length(lua_State *L, int idx, const char *fn, const char *what,
            double def_bp)
{
    const char *s;
    char *end;
    double v;
    cf_unit_t unit;
    if (lua_isnoneornil(L, idx))
        return def_bp;
    if (lua_type(L, idx) == LUA_TNUMBER)
        return cf__lua_check_finite(L, idx, fn, what);
    s = luaL_checkstring(L, idx);
    v = strtod(s, &end);
    while (*end == ' ')
        end++;
    if (end == s || cf_unit_from_name(*end ? end : "bp", &unit, NULL))
        return luaL_error(L, "%s: %s \"%s\": give a number and a unit (bp, "
                          "pt, texpt, mm, cm, in), e.g. \"8cm\"", fn, what,
                          s);
    return cf_length_to_bp(v, unit);
}

static void
check_name(lua_State *L, const char *name)
{
    size_t n = strlen(name);
    if (n == 0 || n > 100 || name[0] == '.')
        luaL_error(L, "figure: name \"%s\" must be 1 to 100 characters and "
                   "not start with '.'", name);
    for (size_t i = 0; i < n; i++) {
        char c = name[i];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
              (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.'))
            luaL_error(L, "figure: name \"%s\": only letters, digits, '-', "
                       "'_' and '.' are allowed (it becomes a file name)",
                       name);
    }
    lua_getfield(L, LUA_REGISTRYINDEX, FIGURES_KEY);
    for (lua_Integer i = 1; i <= (lua_Integer)lua_rawlen(L, -1); i++) {
        lua_rawgeti(L, -1, i);
        lua_getiuservalue(L, -1, 1);
        if (strcmp(lua_tostring(L, -1), name) == 0)
            luaL_error(L, "figure: a figure named \"%s\" is already defined",
                       name);
        lua_pop(L, 2);
    }
    lua_pop(L, 1);
}

/* projection = {{row 1}, {row 2}} or view = {azimuth, elevation}. */
static void
read_projection(lua_State *L, cf_figure_t *fig)
{
    cf_diag_t diag;
    if (cf__lua_field(L, 1, "projection") != LUA_TNIL) {
        size_t rows, dim;
        double *m = cf__lua_check_points(L, -1, "figure", "projection row", 2,
                                         &rows, &dim);
        if (rows != 2)
            luaL_error(L, "figure: projection has %d rows; give 2",
                       (int)rows);
        cf_diag_clear(&diag);
        check(L, "figure", cf_figure_set_projection(fig, dim, m), &diag);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (cf__lua_field(L, 1, "view") != LUA_TNIL) {
        size_t n;
        double *v = cf__lua_check_numbers(L, -1, "figure", "view angle", &n);
        double az, el, m[6];
        if (n != 2)
            luaL_error(L, "figure: view is {azimuth, elevation} in degrees");
        az = v[0] * 3.14159265358979323846 / 180.0;
        el = v[1] * 3.14159265358979323846 / 180.0;
        m[0] = -sin(az);
        m[1] = cos(az);
        m[2] = 0.0;
        m[3] = -cos(az) * sin(el);
        m[4] = -sin(az) * sin(el);
        m[5] = cos(el);
        cf_diag_clear(&diag);
        check(L, "figure", cf_figure_set_projection(fig, 3, m), &diag);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
}

static void
read_frame(lua_State *L, cf_figure_t *fig)
{
    cf_diag_t diag;
    bool aspect = true, given;
    double margin;
    if (cf__lua_field(L, 1, "theme") != LUA_TNIL) {
        cf_theme_t th;
        cf_diag_clear(&diag);
        if (cf_theme_get(luaL_checkstring(L, -1), &th, &diag))
            luaL_error(L, "figure: theme: %s", diag.msg);
        if (cf_figure_set_theme(fig, &th) != CF_STATUS_OK) {
            cf_figure_status(fig, &diag);
            luaL_error(L, "figure: theme: %s", diag.msg);
        }
    }
    lua_pop(L, 1);
    if (cf__lua_field(L, 1, "window") != LUA_TNIL) {
        size_t n;
        double *w = cf__lua_check_numbers(L, -1, "figure", "window", &n);
        if (n != 4)
            luaL_error(L, "figure: window is {xmin, xmax, ymin, ymax}");
        cf_diag_clear(&diag);
        check(L, "figure", cf_figure_set_window(fig, w[0], w[1], w[2], w[3]),
              &diag);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (cf__lua_field(L, 1, "aspect") != LUA_TNIL)
        aspect = lua_toboolean(L, -1);
    lua_pop(L, 1);
    cf__lua_field(L, 1, "margin");
    margin = read_length(L, -1, "figure", "margin", 14.0);
    lua_pop(L, 1);
    check(L, "figure", cf_figure_set_fit(fig, margin, aspect), NULL);
    opt_number(L, 1, "tolerance", "figure", 0.01, &given);
    if (given)
        check(L, "figure",
              cf_figure_set_tolerance(
                  fig, opt_number(L, 1, "tolerance", "figure", 0.01, NULL)),
              NULL);
}

static const char *const figure_keys[] = {
    "name", "caption", "title", "width", "height", "window", "margin",
    "aspect", "theme", "tolerance", "projection", "view", NULL,
};

/* figure{ name = "markova-2.17", caption = "...", width = "8cm", ... } */
static int
l_figure(lua_State *L)
{
    fbox *b;
    const char *name, *caption, *title;
    double w, h;
    cf_diag_t diag;
    luaL_checktype(L, 1, LUA_TTABLE);
    check_keys(L, 1, "figure", figure_keys);
    if (cf__lua_field(L, 1, "name") != LUA_TSTRING)
        return luaL_error(L, "figure: name = \"...\" is required (it names "
                          "the files)");
    name = lua_tostring(L, -1);
    check_name(L, name);
    cf__lua_field(L, 1, "caption");
    caption = luaL_optstring(L, -1, "");
    cf__lua_field(L, 1, "width");
    w = read_length(L, -1, "figure", "width", cf_length_to_bp(8, CF_UNIT_CM));
    cf__lua_field(L, 1, "height");
    h = read_length(L, -1, "figure", "height", cf_length_to_bp(6, CF_UNIT_CM));
    lua_pop(L, 2);
    b = lua_newuserdatauv(L, sizeof *b, 3);
    b->fig = NULL;
    luaL_setmetatable(L, CF__LUA_FIGURE);
    lua_pushvalue(L, 2);
    lua_setiuservalue(L, -2, 1);
    lua_pushvalue(L, 3);
    lua_setiuservalue(L, -2, 2);
    /* where the figure was made ("file:line:"), for errors found only
    ** when it is written */
    luaL_where(L, 1);
    lua_setiuservalue(L, -2, 3);
    cf_diag_clear(&diag);
    check_(L, "figure", NULL,
           cf_figure_create(w, h, CF_UNIT_BP, &b->fig, &diag), &diag);
    cf__lua_field(L, 1, "title");
    title = luaL_optstring(L, -1, name);
    check_(L, "figure", b->fig, cf_figure_set_title(b->fig, title), NULL);
    lua_pop(L, 1);
    check_(L, "figure", b->fig, cf_figure_set_caption(b->fig, caption), NULL);
    read_frame(L, b->fig);
    read_projection(L, b->fig);
    lua_getfield(L, LUA_REGISTRYINDEX, FIGURES_KEY);
    lua_pushvalue(L, -2);
    lua_rawseti(L, -2, (lua_Integer)lua_rawlen(L, -2) + 1);
    lua_pop(L, 1);
    return 1;
}

/* ---- drawing methods ---------------------------------------------------- */

static const char *const range_keys[] = { "range", NULL };

/* f:curve(c, {range = {a, b}, style...}); c a Bézier, a B-spline or a list
** of them. */
static int
m_curve(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 3);
    double a = 0.0, b = 0.0;
    cf_style_t st;
    cf_diag_t diag;
    int top;
    check_keys(L, 3, "curve", range_keys);
    read_style(L, 3, "curve", fig, &st);
    if (cf__lua_field(L, 3, "range") != LUA_TNIL) {
        size_t n;
        double *r = cf__lua_check_numbers(L, -1, "curve", "range", &n);
        if (n != 2)
            return luaL_error(L, "curve: range is {a, b}");
        a = r[0];
        b = r[1];
    }
    if (!cf__lua_to_bezier(L, 2) && !cf__lua_to_bspline(L, 2) &&
        lua_istable(L, 2)) {
        /* a list of curves */
        top = lua_gettop(L);
        for (lua_Integer i = 1; i <= luaL_len(L, 2); i++) {
            lua_pushcfunction(L, m_curve);
            lua_pushvalue(L, 1);
            lua_geti(L, 2, i);
            lua_pushvalue(L, 3);
            lua_call(L, 3, 0);
        }
        lua_settop(L, top);
        lua_settop(L, 1);
        return 1;
    }
    cf_diag_clear(&diag);
    if (cf__lua_to_bspline(L, 2) != NULL) {
        check(L, "curve", cf_figure_add_bspline(fig, cf__lua_to_bspline(L, 2),
                                                a, b, &st), &diag);
    } else if (a != 0.0 || b != 0.0) {
        check(L, "curve", cf_figure_add_bezier_range(
                              fig, cf__lua_check_bezier(L, 2), a, b, &st),
              &diag);
    } else {
        check(L, "curve", cf_figure_add_bezier(fig, cf__lua_check_bezier(L, 2),
                                               &st), &diag);
    }
    lua_settop(L, 1);
    return 1;
}

static const char *const label_keys[] = {
    "labels", "label_start", "label_place", "label_style", "closed", NULL,
};

typedef cf_status_t (*pts_fn)(cf_figure_t *, const double *, size_t,
                              const cf_style_t *);

static int
draw_points(lua_State *L, const char *fn, pts_fn add)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 3);
    size_t n;
    double *p;
    cf_style_t st;
    cf_diag_t diag;
    check_keys(L, 3, fn, label_keys);
    read_style(L, 3, fn, fig, &st);
    p = check_points2d(L, fig, 2, fn, &n);
    cf_diag_clear(&diag);
    check(L, fn, add(fig, p, n, &st), &diag);
    label_points(L, fig, 3, p, n, fn);
    lua_settop(L, 1);
    return 1;
}

static int
m_polygon(lua_State *L)
{
    return draw_points(L, "polygon", cf_figure_add_polygon);
}

static int
m_points(lua_State *L)
{
    return draw_points(L, "points", cf_figure_add_points);
}

static int
m_hull(lua_State *L)
{
    return draw_points(L, "hull", cf_figure_add_hull);
}

static int
m_fill(lua_State *L)
{
    return draw_points(L, "fill", cf_figure_add_fill);
}

/* f:polyline(points, {closed = false, ...}) */
static int
m_polyline(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 3);
    size_t n;
    double *p;
    bool closed;
    cf_style_t st;
    cf_diag_t diag;
    check_keys(L, 3, "polyline", label_keys);
    read_style(L, 3, "polyline", fig, &st);
    cf__lua_field(L, 3, "closed");
    closed = lua_toboolean(L, -1);
    p = check_points2d(L, fig, 2, "polyline", &n);
    cf_diag_clear(&diag);
    check(L, "polyline", cf_figure_add_polyline(fig, p, n, closed, &st),
          &diag);
    label_points(L, fig, 3, p, n, "polyline");
    lua_settop(L, 1);
    return 1;
}

/* f:line(p, q, {...}): the segment pq */
static int
m_line(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 4);
    double *p, *q, pq[4];
    size_t n;
    cf_style_t st;
    cf_diag_t diag;
    check_keys(L, 4, "line", NULL);
    read_style(L, 4, "line", fig, &st);
    p = check_points2d(L, fig, 2, "line", &n);
    q = check_points2d(L, fig, 3, "line", &n);
    memcpy(pq, p, 2 * sizeof *p);
    memcpy(pq + 2, q, 2 * sizeof *q);
    cf_diag_clear(&diag);
    check(L, "line", cf_figure_add_polyline(fig, pq, 2, false, &st), &diag);
    lua_settop(L, 1);
    return 1;
}

/* f:label(p, text, {place = "ne", ...}) */
static int
m_label(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 4);
    size_t n;
    double *p = check_points2d(L, fig, 2, "label", &n);
    const char *text = luaL_checkstring(L, 3);
    cf_style_t st;
    cf_diag_t diag;
    check_keys(L, 4, "label", NULL);
    read_style(L, 4, "label", fig, &st);
    if (!labels_on(L)) {
        lua_settop(L, 1);
        return 1;
    }
    cf_diag_clear(&diag);
    check(L, "label", cf_figure_add_label(fig, p[0], p[1], text, &st), &diag);
    lua_settop(L, 1);
    return 1;
}

static const char *const arrow_keys[] = { "label", "scale", NULL };

static void
arrow_label(lua_State *L, cf_figure_t *fig, int opts, double x, double y,
            const char *fn)
{
    cf_style_t ls;
    cf_diag_t diag;
    if (cf__lua_field(L, opts, "label") == LUA_TSTRING && labels_on(L)) {
        cf_style_init(&ls);
        cf_diag_clear(&diag);
        check(L, fn, cf_figure_add_label(fig, x, y, lua_tostring(L, -1), &ls),
              &diag);
    }
    lua_pop(L, 1);
}

/* f:arrow(p, v, {label = "v", ...}): from p to p + v; arrow_to(p, q) */
static int
arrow(lua_State *L, bool to)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 4);
    const char *fn = to ? "arrow_to" : "arrow";
    size_t n;
    double *p, *v, dx, dy;
    cf_style_t st;
    cf_diag_t diag;
    check_keys(L, 4, fn, arrow_keys);
    read_style(L, 4, fn, fig, &st);
    p = check_points2d(L, fig, 2, fn, &n);
    v = check_points2d(L, fig, 3, fn, &n);
    dx = to ? v[0] - p[0] : v[0];
    dy = to ? v[1] - p[1] : v[1];
    cf_diag_clear(&diag);
    check(L, fn, cf_figure_add_arrow(fig, p[0], p[1], dx, dy, &st), &diag);
    arrow_label(L, fig, 4, p[0] + dx, p[1] + dy, fn);
    lua_settop(L, 1);
    return 1;
}

static int
m_arrow(lua_State *L)
{
    return arrow(L, false);
}

static int
m_arrow_to(lua_State *L)
{
    return arrow(L, true);
}

/* f:tangent(c, t, {scale = 1/degree, label = ...}): the arrow c(t) ->
** c(t) + scale * c'(t) (scale 1/n: a Bézier's end legs). */
static int
m_tangent(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 4);
    double t = cf__lua_check_finite(L, 3, "tangent", "t"), d[2 * 64], pd[4];
    cf_bezier_t *bz = cf__lua_to_bezier(L, 2);
    size_t dim;
    int deg;
    cf_status_t rc;
    cf_style_t st;
    cf_diag_t diag;
    double scale;
    check_keys(L, 4, "tangent", arrow_keys);
    read_style(L, 4, "tangent", fig, &st);
    if (bz != NULL) {
        dim = cf_bezier_dim(bz);
        deg = cf_bezier_degree(bz);
        rc = cf_bezier_eval_derivs(bz, t, 1, d);
    } else {
        cf_bspline_t *bs = cf__lua_check_bspline(L, 2);
        dim = cf_bspline_dim(bs);
        deg = cf_bspline_degree(bs);
        rc = cf_bspline_eval_derivs(bs, t, 1, d);
    }
    if (rc != CF_STATUS_OK)
        return cf__lua_error(L, "tangent: t = %g is outside the domain", t);
    scale = opt_number(L, 4, "scale", "tangent", deg > 0 ? 1.0 / deg : 1.0,
                       NULL);
    for (size_t k = 0; k < dim; k++)
        d[dim + k] = d[k] + scale * d[dim + k];
    check(L, "tangent", cf_figure_project(fig, d, 2, dim, pd), NULL);
    cf_diag_clear(&diag);
    check(L, "tangent", cf_figure_add_arrow(fig, pd[0], pd[1], pd[2] - pd[0],
                                            pd[3] - pd[1], &st), &diag);
    arrow_label(L, fig, 4, pd[2], pd[3], "tangent");
    lua_settop(L, 1);
    return 1;
}

/* f:knots(s, {labels = "u_%d", ...}): marks at C(u_i) for the distinct
** knots in the domain; labels get the index of the knot's first copy. */
static int
m_knots(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 3);
    cf_bspline_t *s = cf__lua_check_bspline(L, 2);
    const double *u = cf_bspline_knots(s);
    size_t m = cf_bspline_nknots(s), dim = cf_bspline_dim(s), n = 0;
    double a, b, *pts, *p2;
    cf_style_t st;
    cf_diag_t diag;
    int top;
    check_keys(L, 3, "knots", label_keys);
    read_style(L, 3, "knots", fig, &st);
    cf_diag_clear(&diag);
    check(L, "knots", cf_figure_add_bspline_knots(fig, s, &st), &diag);
    cf_bspline_domain(s, &a, &b);
    pts = cf__lua_buffer(L, m * dim);
    p2 = cf__lua_buffer(L, 2 * m);
    top = lua_gettop(L);
    for (size_t i = 0; i < m; i++) {
        lua_Integer arg = (lua_Integer)i;
        const char *text;
        if (u[i] < a || u[i] > b || (i > 0 && u[i] == u[i - 1]))
            continue;
        if (cf_bspline_eval(s, u[i], pts + n * dim) != CF_STATUS_OK)
            continue;
        check(L, "knots", cf_figure_project(fig, pts + n * dim, 1, dim,
                                            p2 + 2 * n), NULL);
        if (lua_istable(L, 3) && labels_on(L) &&
            (text = item_label(L, 3, n, &arg, 1))) {
            cf_style_t ls;
            read_sub_style(L, 3, "label_style", "knots", fig, &ls);
            cf_diag_clear(&diag);
            check(L, "knots", cf_figure_add_label(fig, p2[2 * n],
                                                  p2[2 * n + 1], text, &ls),
                  &diag);
        }
        lua_settop(L, top);
        n++;
    }
    lua_settop(L, 1);
    return 1;
}

static const char *const net_keys[] = {
    "colors", "labels", "point", "levels", "label_style", NULL,
};

/* Draw a net (levels of counts[j] points, dim-D, in pts): colours from
** opts.colors, labels from opts.labels called with (index, level), the
** final point from opts.point (a style table or true). */
static void
draw_net(lua_State *L, cf_figure_t *fig, const double *pts,
         const size_t *counts, size_t levels, size_t dim,
         const size_t *first_index, const char *fn)
{
    size_t total = 0, k = 0;
    double *p2;
    cf_color_t *colors = NULL;
    cf_style_t st, ps;
    cf_diag_t diag;
    int top;
    read_style(L, 4, fn, fig, &st);
    if (cf__lua_field(L, 4, "levels") != LUA_TNIL) {
        int lv = cf__lua_check_int(L, -1, fn, "levels", 1, (int)levels);
        levels = (size_t)lv;
    }
    lua_pop(L, 1);
    for (size_t j = 0; j < levels; j++)
        total += counts[j];
    p2 = cf__lua_buffer(L, 2 * total);
    check(L, fn, cf_figure_project(fig, pts, total, dim, p2), NULL);
    if (cf__lua_field(L, 4, "colors") == LUA_TTABLE) {
        if ((size_t)luaL_len(L, -1) < levels)
            luaL_error(L, "%s: %d colours for %d levels", fn,
                       (int)luaL_len(L, -1), (int)levels);
        colors = lua_newuserdatauv(L, levels * sizeof *colors, 0);
        for (size_t j = 0; j < levels; j++) {
            lua_geti(L, -2, (lua_Integer)j + 1);
            colors[j] = read_color(L, -1, fn, "colors", fig);
            lua_pop(L, 1);
        }
    }
    cf_diag_clear(&diag);
    check(L, fn, cf_figure_add_net(fig, p2, counts, levels, colors, &st),
          &diag);
    top = lua_gettop(L);
    for (size_t j = 0; j < levels; j++) {
        for (size_t i = 0; i < counts[j]; i++, k++) {
            lua_Integer args[2];
            const char *text;
            args[0] = (lua_Integer)(first_index[j] + i);
            args[1] = (lua_Integer)j;
            if (!lua_istable(L, 4) || !labels_on(L) ||
                (text = item_label(L, 4, k, args, 2)) == NULL) {
                lua_settop(L, top);
                continue;
            }
            read_sub_style(L, 4, "label_style", fn, fig, &ps);
            check(L, fn, cf_figure_add_label(fig, p2[2 * k], p2[2 * k + 1],
                                             text, &ps), &diag);
            lua_settop(L, top);
        }
    }
    if (read_sub_style(L, 4, "point", fn, fig, &ps))
        check(L, fn, cf_figure_add_points(fig, p2 + 2 * (total - 1), 1, &ps),
              &diag);
}

/* f:decasteljau(c, t, {colors = {...}, labels = "P_{%d,%d}", point =
** {marker = "star"}}); labels get (i, j): point i of level j. */
static int
m_decasteljau(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 4);
    cf_bezier_t *c = cf__lua_check_bezier(L, 2);
    double t = cf__lua_check_finite(L, 3, "decasteljau", "t"), *pts;
    size_t n = (size_t)cf_bezier_degree(c) + 1, *counts, *first;
    check_keys(L, 4, "decasteljau", net_keys);
    pts = cf__lua_buffer(L, cf_bezier_decasteljau_size(c));
    if (cf_bezier_decasteljau(c, t, pts) != CF_STATUS_OK)
        return cf__lua_error(L, "decasteljau: t = %g is outside [0, 1]", t);
    counts = lua_newuserdatauv(L, 2 * n * sizeof *counts, 0);
    first = counts + n;
    for (size_t j = 0; j < n; j++) {
        counts[j] = n - j;
        first[j] = 0;
    }
    draw_net(L, fig, pts, counts, n, cf_bezier_dim(c), first, "decasteljau");
    lua_settop(L, 1);
    return 1;
}

/* f:deboor(s, u, {...}): the de Boor net; labels get (i, j) with i the
** index of P_{i,j} as in the thesis. */
static int
m_deboor(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 4);
    cf_bspline_t *s = cf__lua_check_bspline(L, 2);
    double u = cf__lua_check_finite(L, 3, "deboor", "u"), *pts;
    size_t p = (size_t)cf_bspline_degree(s), span, *counts, *first;
    int mult;
    check_keys(L, 4, "deboor", net_keys);
    pts = cf__lua_buffer(L, cf_bspline_deboor_size(s));
    if (cf_bspline_deboor(s, u, pts, &span, &mult) != CF_STATUS_OK)
        return cf__lua_error(L, "deboor: u = %g is outside the domain", u);
    counts = lua_newuserdatauv(L, 2 * (p + 1) * sizeof *counts, 0);
    first = counts + p + 1;
    for (size_t j = 0; j <= p; j++) {
        counts[j] = p + 1 - j;
        first[j] = span - p + j;
    }
    draw_net(L, fig, pts, counts, p + 1, cf_bspline_dim(s), first, "deboor");
    lua_settop(L, 1);
    return 1;
}

/* ---- function plots ----------------------------------------------------- */

/* Tick positions (a number: step; a table: positions) and labels. */
static void
read_ticks(lua_State *L, const char *key, const char *labels_key,
           const double **ticks, size_t *count, const char *const **labels,
           double *step)
{
    int t = cf__lua_field(L, 2, key);
    if (t == LUA_TNUMBER) {
        /* a step <= 0 would mean automatic or no ticks to the library */
        *step = cf__lua_check_finite(L, -1, "plot", key);
        if (!(*step > 0))
            luaL_error(L, "plot: %s step %s must be positive (or false for "
                       "none)", key, lua_tostring(L, -1));
    } else if (t == LUA_TBOOLEAN && !lua_toboolean(L, -1)) {
        *step = -1;
    } else if (t == LUA_TTABLE) {
        *ticks = cf__lua_check_numbers(L, -1, "plot", key, count);
        if (*count == 0)
            *step = -1;
    } else if (t != LUA_TNIL) {
        luaL_error(L, "plot: %s is a step, a list of positions or false",
                   key);
    }
    if (cf__lua_field(L, 2, labels_key) == LUA_TTABLE) {
        size_t n = (size_t)luaL_len(L, -1);
        const char **l;
        if (n != *count)
            luaL_error(L, "plot: %d %s for %d %s", (int)n, labels_key,
                       (int)*count, key);
        l = lua_newuserdatauv(L, (n ? n : 1) * sizeof *l, 0);
        for (size_t i = 0; i < n; i++) {
            lua_geti(L, -2, (lua_Integer)i + 1);
            l[i] = luaL_checkstring(L, -1);
            lua_pop(L, 1); /* the string stays in the labels table */
        }
        *labels = l;
    }
}

static void
read_range(lua_State *L, const char *key, double *lo, double *hi)
{
    size_t n;
    double *r;
    if (cf__lua_field(L, 2, key) == LUA_TNIL)
        luaL_error(L, "plot: %s = {min, max} is required", key);
    r = cf__lua_check_numbers(L, -1, "plot", key, &n);
    if (n != 2)
        luaL_error(L, "plot: %s = {min, max}", key);
    *lo = r[0];
    *hi = r[1];
}

static const char *const plot_keys[] = {
    "x", "y", "xticks", "yticks", "xtick_labels", "ytick_labels", "xlabel",
    "ylabel", "knots", "knot_labels", "arrows", "grid", "box", NULL,
};

static bool
opt_bool(lua_State *L, int idx, const char *key, bool def)
{
    bool v = def;
    if (cf__lua_field(L, idx, key) != LUA_TNIL)
        v = lua_toboolean(L, -1);
    lua_pop(L, 1);
    return v;
}

/* Labels of the knots on a plot's axis from the knot_labels value at idx
** (true: "u_%d"); the strings are kept in a table left on the stack. */
static const char *const *
knot_labels(lua_State *L, int idx, size_t count)
{
    const char **kl;
    int opts, keep;
    if (lua_isboolean(L, idx)) {
        lua_pushliteral(L, "u_%d");
        lua_replace(L, idx);
    }
    lua_newtable(L);
    lua_pushvalue(L, idx);
    lua_setfield(L, -2, "labels");
    opts = lua_gettop(L);
    kl = lua_newuserdatauv(L, (count ? count : 1) * sizeof *kl, 0);
    lua_newtable(L);
    keep = lua_gettop(L);
    for (size_t i = 0; i < count; i++) {
        lua_Integer arg = (lua_Integer)i;
        const char *text = item_label(L, opts, i, &arg, 1);
        kl[i] = text != NULL ? text : "";
        lua_rawseti(L, keep, (lua_Integer)i + 1);
    }
    return kl;
}

/* f:plot{ x = {0, 10}, y = {0, 1}, knots = {...}, knot_labels = "u_%d",
** xlabel = "u", ... }: axes of a function plot (the window is no longer
** kept to aspect 1). */
static int
m_plot(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 2);
    cf_axes_t ax;
    cf_style_t st;
    cf_diag_t diag;
    int top = lua_gettop(L);
    luaL_checktype(L, 2, LUA_TTABLE);
    check_keys(L, 2, "plot", plot_keys);
    read_style(L, 2, "plot", fig, &st);
    cf_axes_init(&ax);
    read_range(L, "x", &ax.xmin, &ax.xmax);
    read_range(L, "y", &ax.ymin, &ax.ymax);
    read_ticks(L, "xticks", "xtick_labels", &ax.xticks, &ax.xtick_count,
               &ax.xtick_labels, &ax.xtick_step);
    read_ticks(L, "yticks", "ytick_labels", &ax.yticks, &ax.ytick_count,
               &ax.ytick_labels, &ax.ytick_step);
    if (cf__lua_field(L, 2, "xlabel") != LUA_TNIL)
        ax.xlabel = luaL_checkstring(L, -1);
    if (cf__lua_field(L, 2, "ylabel") != LUA_TNIL)
        ax.ylabel = luaL_checkstring(L, -1);
    if (cf__lua_field(L, 2, "knots") != LUA_TNIL) {
        ax.knots = cf__lua_check_numbers(L, -1, "plot", "knot",
                                         &ax.knot_count);
        if (cf__lua_field(L, 2, "knot_labels") != LUA_TNIL &&
            lua_toboolean(L, -1))
            ax.knot_labels = knot_labels(L, lua_gettop(L), ax.knot_count);
    }
    if (!labels_on(L)) {
        ax.xtick_step = ax.ytick_step = -1;
        ax.xtick_count = ax.ytick_count = 0;
        ax.xtick_labels = ax.ytick_labels = ax.knot_labels = NULL;
        ax.xlabel = ax.ylabel = NULL;
    }
    ax.arrows = opt_bool(L, 2, "arrows", true);
    ax.grid = opt_bool(L, 2, "grid", false);
    ax.box = opt_bool(L, 2, "box", false);
    cf_diag_clear(&diag);
    check(L, "plot", cf_figure_add_axes(fig, &ax, &st), &diag);
    check(L, "plot", cf_figure_set_fit(fig, 14.0, false), NULL);
    lua_settop(L, top);
    lua_settop(L, 1);
    return 1;
}

typedef struct func_ctx {
    lua_State *L;
    int fn;
    int failed;
} func_ctx;

/* Called by the library: the Lua function runs protected, and an error is
** raised again only after the library has returned. */
static int
call_func(void *closure, double x, double *y)
{
    func_ctx *c = closure;
    lua_State *L = c->L;
    int isnum;
    lua_pushvalue(L, c->fn);
    lua_pushnumber(L, x);
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
        c->failed = 1;
        return 1;
    }
    *y = (double)lua_tonumberx(L, -1, &isnum);
    lua_pop(L, 1);
    if (!isnum) {
        lua_pushfstring(L, "func: the function returned %s at x = %f, not a "
                        "number", luaL_typename(L, -1), x);
        c->failed = 1;
        return 1;
    }
    return 0;
}

/* f:func(fn, a, b, {...}): the graph of y = fn(x) on [a, b] */
static int
m_func(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 5);
    double a, b;
    func_ctx c;
    cf_style_t st;
    cf_status_t rc;
    luaL_checktype(L, 2, LUA_TFUNCTION);
    a = cf__lua_check_finite(L, 3, "func", "a");
    b = cf__lua_check_finite(L, 4, "func", "b");
    check_keys(L, 5, "func", NULL);
    read_style(L, 5, "func", fig, &st);
    lua_settop(L, 5);
    c.L = L;
    c.fn = 2;
    c.failed = 0;
    rc = cf_figure_add_function(fig, call_func, &c, a, b, &st);
    if (c.failed)
        return lua_error(L);
    if (rc != CF_STATUS_OK) {
        cf_diag_t diag;
        cf_diag_clear(&diag);
        cf_figure_status(fig, &diag);
        return cf__lua_fail(L, "func", rc, &diag);
    }
    lua_settop(L, 1);
    return 1;
}

/* f:graph(x, {...}): x a 1D Bézier on [0, 1], a 1D B-spline over its
** domain, or a list of 1D Béziers with ranges {curve, a, b}. */
static void
free_list(void *p)
{
    cf_bezier_list_destroy(p);
}

static void
graph_bspline(lua_State *L, cf_figure_t *fig, cf_bspline_t *s,
              const cf_style_t *st, const char *fn)
{
    void **slot = cf__lua_holder(L, free_list);
    cf_bezier_list_t *list = NULL;
    cf_diag_t diag;
    cf_status_t rc;
    cf_diag_clear(&diag);
    rc = cf_bspline_to_beziers(s, &list, &diag);
    *slot = list;
    check(L, fn, rc, &diag);
    check(L, fn, cf_figure_add_graph_list(fig, list, st), &diag);
    cf__lua_holder_release(L, -1);
}

static int
m_graph(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 3);
    cf_bezier_t *bz = cf__lua_to_bezier(L, 2);
    cf_bspline_t *bs = cf__lua_to_bspline(L, 2);
    cf_style_t st;
    cf_diag_t diag;
    check_keys(L, 3, "graph", NULL);
    read_style(L, 3, "graph", fig, &st);
    cf_diag_clear(&diag);
    if (bz != NULL) {
        const cf_bezier_t *pieces[1];
        double breaks[2] = { 0.0, 1.0 };
        pieces[0] = bz;
        check(L, "graph", cf_figure_add_graph(fig, pieces, breaks, 1, &st),
              &diag);
    } else if (bs != NULL) {
        graph_bspline(L, fig, bs, &st, "graph");
    } else {
        return luaL_error(L, "graph: give a 1D bezier or bspline (use func "
                          "for a Lua function)");
    }
    lua_settop(L, 1);
    return 1;
}

/* f:basis(U, i, p, {...}): the graph of N_i^p over the knots U (any
** length >= i + p + 2) on [u_0, u_m]; U may be a B-spline (p = its
** degree when omitted).  cf_figure_add_basis. */
static int
m_basis(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 5);
    cf_bspline_t *src = cf__lua_to_bspline(L, 2);
    size_t m;
    const double *u;
    int i, p, opts = 5;
    cf_style_t st;
    cf_diag_t diag;
    if (src != NULL) {
        u = cf_bspline_knots(src);
        m = cf_bspline_nknots(src);
    } else {
        u = cf__lua_check_numbers(L, 2, "basis", "knot", &m);
    }
    i = cf__lua_check_int(L, 3, "basis", "i", 0, 1 << 20);
    if (src != NULL && lua_isnoneornil(L, 4))
        p = cf_bspline_degree(src);
    else
        p = cf__lua_check_int(L, 4, "basis", "p", 0, CF_BSPLINE_MAX_DEGREE);
    check_keys(L, opts, "basis", NULL);
    read_style(L, opts, "basis", fig, &st);
    cf_diag_clear(&diag);
    check(L, "basis", cf_figure_add_basis(fig, u, m, i, p, &st), &diag);
    lua_settop(L, 1);
    return 1;
}

/* f:bernstein(n, i, {...}): the graph of B_i^n on [0, 1] */
static int
m_bernstein(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 4);
    int n = cf__lua_check_int(L, 2, "bernstein", "n", 0, CF_BEZIER_MAX_DEGREE);
    int i = cf__lua_check_int(L, 3, "bernstein", "i", 0, n);
    double *e = cf__lua_buffer(L, (size_t)n + 1), breaks[2] = { 0.0, 1.0 };
    cf_bezier_t **c;
    const cf_bezier_t *pieces[1];
    cf_style_t st;
    cf_diag_t diag;
    check_keys(L, 4, "bernstein", NULL);
    read_style(L, 4, "bernstein", fig, &st);
    memset(e, 0, ((size_t)n + 1) * sizeof *e);
    e[i] = 1.0;
    c = cf__lua_new_bezier(L);
    cf_diag_clear(&diag);
    check(L, "bernstein", cf_bezier_create(1, n, e, NULL, c, &diag), &diag);
    pieces[0] = *c;
    check(L, "bernstein", cf_figure_add_graph(fig, pieces, breaks, 1, &st),
          &diag);
    lua_settop(L, 1);
    return 1;
}

/* ---- frame -------------------------------------------------------------- */

/* f:window(xmin, xmax, ymin, ymax) or f:window() for the fitted window */
static int
m_window(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 5);
    cf_diag_t diag;
    cf_diag_clear(&diag);
    if (lua_isnoneornil(L, 2)) {
        check(L, "window", cf_figure_set_window_auto(fig), &diag);
    } else {
        double w[4];
        for (int k = 0; k < 4; k++)
            w[k] = cf__lua_check_finite(L, 2 + k, "window", "bound");
        check(L, "window", cf_figure_set_window(fig, w[0], w[1], w[2], w[3]),
              &diag);
    }
    lua_settop(L, 1);
    return 1;
}

/* f:project(points) -> the 2D points as drawn (for labels of 3D figures) */
static int
m_project(lua_State *L)
{
    cf_figure_t *fig = check_fig(L, 1);
    lua_settop(L, 2);
    size_t n;
    double *p = check_points2d(L, fig, 2, "project", &n);
    cf__lua_push_points(L, p, n, 2);
    return 1;
}

static int
m_name(lua_State *L)
{
    check_fig(L, 1);
    lua_getiuservalue(L, 1, 1);
    return 1;
}

static const luaL_Reg methods[] = {
    { "curve", m_curve },
    { "polygon", m_polygon },
    { "points", m_points },
    { "polyline", m_polyline },
    { "line", m_line },
    { "hull", m_hull },
    { "fill", m_fill },
    { "label", m_label },
    { "arrow", m_arrow },
    { "arrow_to", m_arrow_to },
    { "tangent", m_tangent },
    { "knots", m_knots },
    { "decasteljau", m_decasteljau },
    { "deboor", m_deboor },
    { "plot", m_plot },
    { "func", m_func },
    { "graph", m_graph },
    { "basis", m_basis },
    { "bernstein", m_bernstein },
    { "window", m_window },
    { "project", m_project },
    { "name", m_name },
    { NULL, NULL },
};

void
cf__lua_open_figure(lua_State *L)
{
    cf__lua_new_class(L, CF__LUA_FIGURE, methods, gc, tostring);
    lua_pushcfunction(L, l_figure);
    lua_setglobal(L, "figure");
    lua_getglobal(L, "string");
    lua_getfield(L, -1, "format");
    lua_setfield(L, LUA_REGISTRYINDEX, "curvefig.format");
    lua_pop(L, 1);
    lua_newtable(L);
    lua_setfield(L, LUA_REGISTRYINDEX, FIGURES_KEY);
}

/* ---- access for the tool ------------------------------------------------ */

static int
push_figure(lua_State *L, size_t i)
{
    lua_getfield(L, LUA_REGISTRYINDEX, FIGURES_KEY);
    if (lua_rawgeti(L, -1, (lua_Integer)i + 1) != LUA_TUSERDATA) {
        lua_pop(L, 2);
        return 0;
    }
    lua_remove(L, -2);
    return 1;
}

size_t
cf__lua_figure_count(lua_State *L)
{
    size_t n;
    lua_getfield(L, LUA_REGISTRYINDEX, FIGURES_KEY);
    n = (size_t)lua_rawlen(L, -1);
    lua_pop(L, 1);
    return n;
}

cf_figure_t *
cf__lua_figure_at(lua_State *L, size_t i)
{
    fbox *b;
    if (!push_figure(L, i))
        return NULL;
    b = lua_touserdata(L, -1);
    lua_pop(L, 1);
    return b->fig;
}

/* The strings stay alive: the figure (in the registry) holds them. */
const char *
cf__lua_figure_string(lua_State *L, size_t i, int which)
{
    const char *s;
    if (!push_figure(L, i))
        return "";
    lua_getiuservalue(L, -1, which);
    s = lua_tostring(L, -1);
    lua_pop(L, 2);
    return s != NULL ? s : "";
}
