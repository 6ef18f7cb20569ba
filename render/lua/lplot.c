/*
** The plot methods of figures: axes of a function plot (f:plot), graphs of
** Lua functions (f:func), of 1D curves (f:graph), of B-spline basis
** functions (f:basis) and of Bernstein polynomials (f:bernstein).
*/
#include <string.h>

#include "curvefig/bspline.h"
#include "curvefig/figure.h"
#include "lbezier.h"
#include "lbspline.h"
#include "lcommon.h"
#include "ldraw.h"
#include "llabels.h"
#include "lschema.h"
#include "lstyle.h"

#define check(L, fn, call, diag) cf__lua_fig_check((L), (fn), fig, (call), \
                                                   (diag))

/* The labels of count ticks from opts[labels_key] (NULL: none given); the
** strings stay in the table, left on the stack. */
static const char *const *
tick_labels(lua_State *L, const char *key, const char *labels_key,
            size_t count)
{
    int t = cf__lua_field(L, 2, labels_key);
    size_t n;
    const char **l;
    if (t == LUA_TNIL)
        return NULL;
    if (t != LUA_TTABLE)
        luaL_error(L, "plot: %s is a list of strings, one per tick",
                   labels_key);
    n = (size_t)luaL_len(L, -1);
    if (n != count)
        luaL_error(L, "plot: %d %s for %d %s", (int)n, labels_key, (int)count,
                   key);
    l = lua_newuserdatauv(L, (n ? n : 1) * sizeof *l, 0);
    for (size_t i = 0; i < n; i++) {
        lua_geti(L, -2, (lua_Integer)i + 1);
        l[i] = cf__lua_opt_text(L, -1, "plot", labels_key, NULL);
        lua_pop(L, 1);
    }
    return l;
}

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
    *labels = tick_labels(L, key, labels_key, *count);
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

/* Labels of the knots on a plot's axis from the knot_labels value at idx
** (true: "u_%d"), each given (i, multiplicity in the list); the strings
** are kept in a table left on the stack. */
static const char *const *
knot_labels(lua_State *L, int idx, const double *knots, size_t count)
{
    const char **kl;
    int keep;
    if (lua_isboolean(L, idx)) {
        lua_pushliteral(L, "u_%d");
        lua_replace(L, idx);
    }
    kl = lua_newuserdatauv(L, (count ? count : 1) * sizeof *kl, 0);
    lua_newtable(L);
    keep = lua_gettop(L);
    for (size_t i = 0; i < count; i++) {
        lua_Integer args[2] = { (lua_Integer)i, 0 };
        const char *text;
        for (size_t j = 0; j < count; j++)
            args[1] += knots[j] == knots[i];
        text = cf__lua_item_label(L, idx, i, args, 2, "plot");
        kl[i] = text != NULL ? text : "";
        lua_rawseti(L, keep, (lua_Integer)i + 1);
    }
    return kl;
}

/* The axes described by the options at 2 (strings and lists stay on the
** stack). */
static void
read_axes(lua_State *L, cf_axes_t *ax)
{
    cf_axes_init(ax);
    read_range(L, "x", &ax->xmin, &ax->xmax);
    read_range(L, "y", &ax->ymin, &ax->ymax);
    read_ticks(L, "xticks", "xtick_labels", &ax->xticks, &ax->xtick_count,
               &ax->xtick_labels, &ax->xtick_step);
    read_ticks(L, "yticks", "ytick_labels", &ax->yticks, &ax->ytick_count,
               &ax->ytick_labels, &ax->ytick_step);
    if (cf__lua_field(L, 2, "xlabel") != LUA_TNIL)
        ax->xlabel = cf__lua_opt_text(L, -1, "plot", "xlabel", NULL);
    if (cf__lua_field(L, 2, "ylabel") != LUA_TNIL)
        ax->ylabel = cf__lua_opt_text(L, -1, "plot", "ylabel", NULL);
    if (cf__lua_field(L, 2, "knots") != LUA_TNIL) {
        ax->knots = cf__lua_check_numbers(L, -1, "plot", "knot",
                                          &ax->knot_count);
        if (cf__lua_field(L, 2, "knot_labels") != LUA_TNIL &&
            lua_toboolean(L, -1))
            ax->knot_labels = knot_labels(L, lua_gettop(L), ax->knots,
                                          ax->knot_count);
    }
    if (!cf__lua_labels_on(L)) {
        ax->xtick_step = ax->ytick_step = -1;
        ax->xtick_count = ax->ytick_count = 0;
        ax->xtick_labels = ax->ytick_labels = ax->knot_labels = NULL;
        ax->xlabel = ax->ylabel = NULL;
    }
    ax->arrows = cf__lua_opt_bool(L, 2, "arrows", "plot", true);
    ax->grid = cf__lua_opt_bool(L, 2, "grid", "plot", false);
    ax->box = cf__lua_opt_bool(L, 2, "box", "plot", false);
}

/* f:plot{ x = {0, 10}, y = {0, 1}, knots = {...}, knot_labels = "u_%d",
** xlabel = "u", ... }: axes of a function plot (the window is no longer
** kept to aspect 1). */
static int
m_plot(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    cf_axes_t ax;
    cf_style_t st;
    cf_diag_t diag;
    lua_settop(L, 2);
    luaL_checktype(L, 2, LUA_TTABLE);
    cf__lua_check_table(L, 2, CF__KEYS_PLOT);
    cf__lua_read_style(L, 2, "plot", fig, &st);
    read_axes(L, &ax);
    cf_diag_clear(&diag);
    check(L, "plot", cf_figure_add_axes(fig, &ax, &st), &diag);
    {
        /* a function plot keeps no aspect ratio; the figure's margin */
        double margin = 0;
        cf_figure_get_fit(fig, &margin, NULL);
        check(L, "plot", cf_figure_set_fit(fig, margin, false), NULL);
    }
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
    cf_figure_t *fig = cf__lua_check_figure(L);
    lua_settop(L, 5);
    double a, b;
    func_ctx c;
    cf_style_t st;
    cf_status_t rc;
    luaL_checktype(L, 2, LUA_TFUNCTION);
    a = cf__lua_check_finite(L, 3, "func", "a");
    b = cf__lua_check_finite(L, 4, "func", "b");
    cf__lua_check_table(L, 5, CF__KEYS_FUNC);
    cf__lua_read_style(L, 5, "func", fig, &st);
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
    cf_figure_t *fig = cf__lua_check_figure(L);
    lua_settop(L, 3);
    cf_bezier_t *bz = cf__lua_to_bezier(L, 2);
    cf_bspline_t *bs = cf__lua_to_bspline(L, 2);
    cf_style_t st;
    cf_diag_t diag;
    cf__lua_check_table(L, 3, CF__KEYS_GRAPH);
    cf__lua_read_style(L, 3, "graph", fig, &st);
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
    cf_figure_t *fig = cf__lua_check_figure(L);
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
    cf__lua_check_table(L, opts, CF__KEYS_BASIS);
    cf__lua_read_style(L, opts, "basis", fig, &st);
    cf_diag_clear(&diag);
    check(L, "basis", cf_figure_add_basis(fig, u, m, i, p, &st), &diag);
    lua_settop(L, 1);
    return 1;
}

/* f:bernstein(n, i, {...}): the graph of B_i^n on [0, 1] */
static int
m_bernstein(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    lua_settop(L, 4);
    int n = cf__lua_check_int(L, 2, "bernstein", "n", 0, CF_BEZIER_MAX_DEGREE);
    int i = cf__lua_check_int(L, 3, "bernstein", "i", 0, n);
    double *e = cf__lua_buffer(L, (size_t)n + 1), breaks[2] = { 0.0, 1.0 };
    cf_bezier_t **c;
    const cf_bezier_t *pieces[1];
    cf_style_t st;
    cf_diag_t diag;
    cf__lua_check_table(L, 4, CF__KEYS_BERNSTEIN);
    cf__lua_read_style(L, 4, "bernstein", fig, &st);
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


const luaL_Reg cf__lua_plot_methods[] = {
    { "plot", m_plot },
    { "func", m_func },
    { "graph", m_graph },
    { "basis", m_basis },
    { "bernstein", m_bernstein },
    { NULL, NULL },
};
