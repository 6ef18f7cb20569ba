/*
** Figures as Lua values: the figure class, figure{...} and its options
** (name, page, window, theme, projection), the frame methods (f:window,
** f:project, f:name), and the list of figures the tool renders.  The
** drawing and plot methods are in ldraw.c and lplot.c.
*/
#include <math.h>
#include <string.h>

#include "curvefig/figure.h"
#include "lcommon.h"
#include "ldraw.h"
#include "lfigure.h"
#include "llayout.h"
#include "lparams.h"
#include "params.h"
#include "lschema.h"
#include "lstyle.h"
#include "lsurface-draw.h"
#include "ltheme.h"
#include "lview.h"

#define FIGURES_KEY "curvefig.figures"
/* The set of their names: a new name is looked up once, not compared
** with every figure before it (100,000 figure{} calls took 55 s). */
#define NAMES_KEY "curvefig.figure-names"

#define check(L, fn, call, diag) cf__lua_fig_check((L), (fn), fig, (call), \
                                                   (diag))

static int
gc(lua_State *L)
{
    cf__lua_fbox_t *b = luaL_checkudata(L, 1, CF__LUA_FIGURE);
    if (!b->borrowed)
        cf_figure_destroy(b->fig);
    b->fig = NULL;
    return 0;
}

static int
tostring(lua_State *L)
{
    luaL_checkudata(L, 1, CF__LUA_FIGURE);
    lua_getiuservalue(L, 1, 1);
    lua_pushfstring(L, "figure %s", lua_tostring(L, -1));
    return 1;
}


/* ---- figure{...} -------------------------------------------------------- */

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
    lua_getfield(L, LUA_REGISTRYINDEX, NAMES_KEY);
    if (lua_getfield(L, -1, name) != LUA_TNIL) {
        /* where the first one was made: "FILE:LINE:" */
        size_t wlen;
        const char *where;
        lua_getiuservalue(L, -1, 3);
        where = lua_tolstring(L, -1, &wlen);
        while (where != NULL && wlen > 0
               && (where[wlen - 1] == ' ' || where[wlen - 1] == ':'))
            wlen--;
        cf__lua_error(L, "figure: a figure named \"%s\" is already "
                      "defined (at %.*s); the names name the files, so "
                      "they must differ", name, (int)wlen,
                      where != NULL ? where : "?");
    }
    lua_pop(L, 2);
}

/* projection = {{row 1}, {row 2}} (a matrix), or the view (lview.c) of
** the figure whose name is at 2. */
static void
read_projection(lua_State *L, cf_figure_t *fig)
{
    cf_diag_t diag;
    int top = lua_gettop(L);
    int pt = cf__lua_field(L, 1, "projection");
    bool matrix = pt == LUA_TTABLE;
    bool view = cf__lua_field(L, 1, "view") != LUA_TNIL;
    cf_diag_clear(&diag);
    if (pt != LUA_TNIL && pt != LUA_TTABLE && pt != LUA_TSTRING)
        luaL_error(L, "figure: projection is \"orthographic\", "
                   "\"perspective\" or a matrix {{row 1}, {row 2}}, got %s",
                   lua_typename(L, pt));
    if (matrix && view)
        luaL_error(L, "figure: give either a projection matrix or a view, "
                   "not both (projection = \"perspective\" goes with a "
                   "view)");
    if (matrix) {
        size_t rows, dim;
        double *m = cf__lua_check_points(L, top + 1, "figure",
                                         "projection row", 2, &rows, &dim);
        if (rows != 2)
            luaL_error(L, "figure: projection has %d rows; give 2",
                       (int)rows);
        check(L, "figure", cf_figure_set_projection(fig, dim, m), &diag);
    } else {
        cf__lua_read_view(L, fig, lua_tostring(L, 2), 1);
    }
    lua_settop(L, top);
}

static void
read_theme(lua_State *L, cf_figure_t *fig)
{
    cf_diag_t diag;
    cf_theme_t th;
    if (cf__lua_field(L, 1, "theme") != LUA_TNIL) {
        cf_diag_clear(&diag);
        if (cf_theme_get(cf__lua_opt_text(L, -1, "figure", "theme", NULL),
                         &th, &diag))
            luaL_error(L, "figure: theme: %s", diag.msg);
        if (cf_figure_set_theme(fig, &th) != CF_STATUS_OK) {
            cf_figure_status(fig, &diag);
            luaL_error(L, "figure: theme: %s", diag.msg);
        }
    }
    lua_pop(L, 1);
}

/* background = "auto" (PNG white, the other formats transparent),
** "none" or a colour painted in every format */
static void
read_background(lua_State *L, cf_figure_t *fig)
{
    cf_diag_t diag;
    const char *v;
    cf_theme_t th;
    cf__lua_field(L, 1, "background");
    v = cf__lua_opt_text(L, -1, "figure", "background", "auto");
    lua_pop(L, 1);
    if (strcmp(v, "auto") == 0 || strcmp(v, "none") == 0) {
        check(L, "figure", cf_figure_set_background(fig, v[0] == 'a'
                                                    ? CF_BACKGROUND_AUTO
                                                    : CF_BACKGROUND_NONE),
              NULL);
        return;
    }
    cf_figure_get_theme(fig, &th);
    cf_diag_clear(&diag);
    if (cf_color_parse(v, &th.background, &diag) != CF_STATUS_OK)
        luaL_error(L, "figure: background = \"%s\": give \"auto\", "
                   "\"none\" or a colour (%s)", v, diag.msg);
    check(L, "figure", cf_figure_set_theme(fig, &th), NULL);
    check(L, "figure", cf_figure_set_background(fig, CF_BACKGROUND_ALWAYS),
          NULL);
}

/* window, margin, aspect, tolerance, clip; w and h the page in bp */
static void
read_frame(lua_State *L, cf_figure_t *fig, double w, double h)
{
    cf_diag_t diag;
    bool given, aspect, fixed;
    double margin, tol;
    if (cf__lua_field(L, 1, "window") != LUA_TNIL) {
        size_t n;
        double *v = cf__lua_check_numbers(L, -1, "figure", "window", &n);
        if (n != 4)
            luaL_error(L, "figure: window is {xmin, xmax, ymin, ymax}");
        cf_diag_clear(&diag);
        check(L, "figure", cf_figure_set_window(fig, v[0], v[1], v[2], v[3]),
              &diag);
    }
    /* page = "ink" (the default): the page is the ink box plus a margin
    ** of 1 bp; "fixed": width x height, the ink 14 bp inside it */
    cf__lua_field(L, 1, "page");
    fixed = strcmp(cf__lua_opt_text(L, -1, "figure", "page", "ink"),
                   "fixed") == 0;
    check(L, "figure", cf_figure_set_page_mode(fig, fixed ? CF_PAGE_FIXED
                                                          : CF_PAGE_INK),
          NULL);
    cf__lua_field(L, 1, "margin");
    margin = cf__lua_read_length(L, -1, "figure", "margin",
                                 fixed ? 14.0 : 1.0);
    if (margin >= 0 && (2 * margin >= w || 2 * margin >= h))
        cf__lua_error(L, "figure: the page of %g x %g bp leaves no room "
                      "inside the margin of %g bp", w, h, margin);
    aspect = cf__lua_opt_bool(L, 1, "aspect", "figure", true);
    check(L, "figure", cf_figure_set_fit(fig, margin, aspect), NULL);
    check(L, "figure", cf_figure_set_clip(fig, cf__lua_opt_bool(L, 1, "clip",
                                                                "figure",
                                                                false)), NULL);
    tol = cf__lua_opt_number(L, 1, "tolerance", "figure", 0.01, &given);
    /* a draft of an interactive page (params.h): looser */
    if (cf__params_draft(cf__lua_params(L))) {
        tol *= CF__PARAMS_DRAFT_FACTOR;
        given = true;
        check(L, "figure", cf_figure_set_draft(fig, true), NULL);
    }
    if (given)
        check(L, "figure", cf_figure_set_tolerance(fig, tol), NULL);
}

/* The figure value, its strings (1 name, 2 caption, 3 where it was made,
** "file:line:", for errors found only when it is written) and its figure
** of w x h bp; pushed. */
static cf_figure_t *
new_figure(lua_State *L, int name, int caption, double w, double h)
{
    cf__lua_fbox_t *b = lua_newuserdatauv(L, sizeof *b, 3);
    cf_diag_t diag;
    b->fig = NULL;
    b->borrowed = false;
    luaL_setmetatable(L, CF__LUA_FIGURE);
    lua_pushvalue(L, name);
    lua_setiuservalue(L, -2, 1);
    lua_pushvalue(L, caption);
    lua_setiuservalue(L, -2, 2);
    luaL_where(L, 1);
    lua_setiuservalue(L, -2, 3);
    cf_diag_clear(&diag);
    cf__lua_fig_check(L, "figure", NULL,
                      cf_figure_create(w, h, CF_UNIT_BP, &b->fig, &diag),
                      &diag);
    return b->fig;
}

/* The text at idx (def when nil): a string or a number. */
static const char *
opt_text(lua_State *L, int idx, const char *what, const char *def)
{
    if (lua_isnil(L, idx))
        return def;
    return cf__lua_check_text(L, idx, "figure", what);
}

#define TOOL_WIDTH "curvefig.tool_width"
#define TOOL_HEIGHT "curvefig.tool_height"

void
cf__lua_set_tool_page(lua_State *L, double width_bp, double height_bp)
{
    lua_pushnumber(L, width_bp);
    lua_setfield(L, LUA_REGISTRYINDEX, TOOL_WIDTH);
    lua_pushnumber(L, height_bp);
    lua_setfield(L, LUA_REGISTRYINDEX, TOOL_HEIGHT);
}

/* width and height (pushed) in bp: the script's, or the tool's */
static void
read_page(lua_State *L, double *w, double *h)
{
    double tw, th;
    cf__lua_field(L, 1, "width");
    *w = cf__lua_read_length(L, -1, "figure", "width",
                             cf_length_to_bp(8, CF_UNIT_CM));
    cf__lua_field(L, 1, "height");
    *h = cf__lua_read_length(L, -1, "figure", "height",
                             cf_length_to_bp(6, CF_UNIT_CM));
    lua_getfield(L, LUA_REGISTRYINDEX, TOOL_WIDTH);
    tw = lua_tonumber(L, -1);
    lua_getfield(L, LUA_REGISTRYINDEX, TOOL_HEIGHT);
    th = lua_tonumber(L, -1);
    lua_pop(L, 2);
    if ((tw > 0 || th > 0) && *w > 0 && *h > 0) {
        double sw = *w, sh = *h;
        *w = tw > 0 ? tw : sw * th / sh;
        *h = th > 0 ? th : sh * tw / sw;
    }
}

/* Append the figure value at idx to the list the tool renders. */
static void
keep_figure(lua_State *L, int idx)
{
    lua_getfield(L, LUA_REGISTRYINDEX, FIGURES_KEY);
    lua_pushvalue(L, idx);
    lua_rawseti(L, -2, (lua_Integer)lua_rawlen(L, -2) + 1);
    lua_getfield(L, LUA_REGISTRYINDEX, NAMES_KEY);
    lua_getiuservalue(L, idx, 1);
    lua_pushvalue(L, idx);    /* the first figure of its name */
    lua_rawset(L, -3);
    lua_pop(L, 2);
}

/* figure{ name = "markova-2.17", caption = "...", width = "8cm", ... } */
static int
l_figure(lua_State *L)
{
    cf_figure_t *fig;
    double w, h;
    lua_settop(L, 1);
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_FIGURE);
    if (cf__lua_field(L, 1, "name") != LUA_TSTRING)
        return luaL_error(L, "figure: name = \"...\" is required (it names "
                          "the files)");
    check_name(L, cf__lua_check_text(L, 2, "figure", "name"));
    cf__lua_field(L, 1, "caption");
    cf__lua_field(L, 1, "title");
    read_page(L, &w, &h);
    fig = new_figure(L, 2, 3, w, h);
    check(L, "figure", cf_figure_set_title(fig, opt_text(L, 4, "title",
                                           lua_tostring(L, 2))), NULL);
    check(L, "figure", cf_figure_set_caption(fig, opt_text(L, 3, "caption",
                                                           "")), NULL);
    cf__lua_read_access(L, fig);
    read_theme(L, fig);
    cf__lua_apply_fonts(L, 1, fig);
    read_background(L, fig);
    read_frame(L, fig, w, h);
    read_projection(L, fig);
    cf__lua_read_figure_legend(L, fig);
    lua_settop(L, 7);
    keep_figure(L, 7);
    return 1;
}

/* ---- frame -------------------------------------------------------------- */

/* f:window(xmin, xmax, ymin, ymax) or f:window() for the fitted window */
static int
m_window(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
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
    cf_figure_t *fig = cf__lua_check_figure(L);
    lua_settop(L, 2);
    size_t n;
    double *p = cf__lua_check_points2d(L, fig, 2, "project", &n);
    cf__lua_push_points(L, p, n, 2);
    return 1;
}

static int
m_name(lua_State *L)
{
    cf__lua_check_figure(L);
    lua_getiuservalue(L, 1, 1);
    return 1;
}

static const luaL_Reg frame_methods[] = {
    { "window", m_window },
    { "project", m_project },
    { "name", m_name },
    { NULL, NULL },
};

void
cf__lua_open_figure(lua_State *L)
{
    cf__lua_new_class(L, CF__LUA_FIGURE, frame_methods, gc, tostring);
    luaL_getmetatable(L, CF__LUA_FIGURE);
    lua_getfield(L, -1, "__index");
    cf__lua_set_legend_methods(L, cf__lua_draw_methods);
    cf__lua_set_legend_methods(L, cf__lua_plot_methods);
    luaL_setfuncs(L, cf__lua_layout_methods, 0);
    luaL_setfuncs(L, cf__lua_view_methods, 0);
    cf__lua_set_legend_methods(L, cf__lua_surface_draw_methods);
    cf__lua_set_legend_methods(L, cf__lua_surface_scheme_methods);
    lua_pop(L, 2);
    lua_pushcfunction(L, l_figure);
    lua_setglobal(L, "figure");
    lua_getglobal(L, "string");
    lua_getfield(L, -1, "format");
    lua_setfield(L, LUA_REGISTRYINDEX, "curvefig.format");
    lua_pop(L, 1);
    lua_newtable(L);
    lua_setfield(L, LUA_REGISTRYINDEX, FIGURES_KEY);
    lua_newtable(L);
    lua_setfield(L, LUA_REGISTRYINDEX, NAMES_KEY);
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
    cf__lua_fbox_t *b;
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
