/*
** One run of an interactive figure as JSON (interactive.h): the script in
** a fresh sandbox with the reader's values, its parameters, its figures
** as SVG with the data -> SVG map and the places of the handles, its
** error, and its values as Lua to paste back.
*/
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/figure.h"
#include "curvefig/figure3d.h"
#include "interactive.h"
#include "lcommon.h"
#include "params.h"

/* ---- a growing text ------------------------------------------------------ */

typedef struct text {
    char *s;
    size_t len, cap;
    int failed;
} text_t;

static void
put_n(text_t *t, const char *s, size_t n)
{
    if (t->failed)
        return;
    if (t->len + n + 1 > t->cap) {
        size_t cap = t->cap ? t->cap : 4096;
        char *p;
        while (cap < t->len + n + 1)
            cap *= 2;
        p = realloc(t->s, cap);
        if (p == NULL) {
            t->failed = 1;
            return;
        }
        t->s = p;
        t->cap = cap;
    }
    memcpy(t->s + t->len, s, n);
    t->len += n;
    t->s[t->len] = '\0';
}

static void
put(text_t *t, const char *s)
{
    put_n(t, s, strlen(s));
}

static void
putf(text_t *t, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void
putf(text_t *t, const char *fmt, ...)
{
    char buf[256];
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    if (n > 0)
        put_n(t, buf, (size_t)n < sizeof buf ? (size_t)n : sizeof buf - 1);
}

/* A number that reads back as the same double (JSON and Lua alike). */
static void
put_num(text_t *t, double v)
{
    char buf[40];
    if (!isfinite(v))
        v = 0;
    snprintf(buf, sizeof buf, "%.15g", v);
    if (strtod(buf, NULL) != v)
        snprintf(buf, sizeof buf, "%.17g", v);
    put(t, buf);
}

/* A JSON string of the n bytes at s; a byte that is not part of valid
** UTF-8 (an error message may quote any) becomes U+FFFD. */
static void
put_str_n(text_t *t, const char *s, size_t n)
{
    put(t, "\"");
    for (size_t i = 0; i < n;) {
        unsigned char c = (unsigned char)s[i];
        size_t run = i, k;
        while (run < n && (unsigned char)s[run] >= 0x20 && s[run] != '"' &&
               s[run] != '\\' &&
               (k = cf__utf8_sequence(s + run, n - run)) > 0)
            run += k;
        if (run > i) {
            put_n(t, s + i, run - i);
            i = run;
            continue;
        }
        if (c == '"' || c == '\\')
            putf(t, "\\%c", c);
        else if (c == '\n')
            put(t, "\\n");
        else if (c == '\t')
            put(t, "\\t");
        else if (c < 0x20)
            putf(t, "\\u%04x", c);
        else
            put(t, "\\ufffd");
        i++;
    }
    put(t, "\"");
}

static void
put_str(text_t *t, const char *s)
{
    put_str_n(t, s, strlen(s));
}

static void
put_xy_list(text_t *t, const double *xy, size_t count)
{
    put(t, "[");
    for (size_t i = 0; i < count; i++) {
        put(t, i ? ", [" : "[");
        put_num(t, xy[2 * i]);
        put(t, ", ");
        put_num(t, xy[2 * i + 1]);
        put(t, "]");
    }
    put(t, "]");
}

/* ---- the parts -------------------------------------------------------- */

static void
put_param(text_t *t, const cf__param_t *d)
{
    put(t, "{\"kind\": ");
    put_str(t, d->kind == CF__PARAM_SLIDER ? "slider" : "points");
    put(t, ", \"name\": ");
    put_str(t, d->name);
    if (d->kind == CF__PARAM_SLIDER) {
        put(t, ", \"label\": ");
        put_str(t, d->label[0] ? d->label : d->name);
        put(t, ", \"min\": ");
        put_num(t, d->min);
        put(t, ", \"max\": ");
        put_num(t, d->max);
        put(t, ", \"step\": ");
        put_num(t, d->step);
        put(t, d->log ? ", \"scale\": \"log\"" : ", \"scale\": \"linear\"");
        put(t, ", \"default\": ");
        put_num(t, d->def);
        put(t, ", \"value\": ");
        put_num(t, d->value);
    } else {
        put(t, ", \"figure\": ");
        put_str(t, d->figure);
        put(t, ", \"value\": ");
        put_xy_list(t, d->xy, d->count);
        put(t, ", \"default\": ");
        put_xy_list(t, d->def_xy, d->count);
        put(t, ", \"constrain\": ");
        if (d->constrain == CF__CONSTRAIN_GRID) {
            put(t, "{\"grid\": ");
            put_num(t, d->grid);
            put(t, "}");
        } else if (d->constrain == CF__CONSTRAIN_LINE) {
            put(t, "{\"line\": ");
            put_xy_list(t, d->line, 2);
            put(t, "}");
        } else {
            put(t, "null");
        }
    }
    put(t, "}");
}

static bool
lua_name(const char *s)
{
    static const char *const reserved[] = {
        "and", "break", "do", "else", "elseif", "end", "false", "for",
        "function", "goto", "if", "in", "local", "nil", "not", "or",
        "repeat", "return", "then", "true", "until", "while", NULL,
    };
    if (!(isalpha((unsigned char)s[0]) || s[0] == '_'))
        return false;
    for (const char *p = s; *p; p++)
        if (!(isalnum((unsigned char)*p) || *p == '_'))
            return false;
    for (int i = 0; reserved[i] != NULL; i++)
        if (strcmp(s, reserved[i]) == 0)
            return false;
    return true;
}

/* values = { t = 0.75, P = { {0, 0}, ... } } */
static void
lua_values(text_t *t, const cf__params_t *p)
{
    put(t, "values = {");
    for (size_t i = 0; i < cf__params_count(p); i++) {
        const cf__param_t *d = cf__params_at(p, i);
        put(t, i ? ",\n  " : "\n  ");
        if (lua_name(d->name)) {
            put(t, d->name);
        } else {
            put(t, "[");
            put_str(t, d->name);
            put(t, "]");
        }
        put(t, " = ");
        if (d->kind == CF__PARAM_SLIDER) {
            put_num(t, d->value);
            continue;
        }
        put(t, "{ ");
        for (size_t k = 0; k < d->count; k++) {
            put(t, k ? ", {" : "{");
            put_num(t, d->xy[2 * k]);
            put(t, ", ");
            put_num(t, d->xy[2 * k + 1]);
            put(t, "}");
        }
        put(t, " }");
    }
    put(t, cf__params_count(p) ? "\n}\n" : "}\n");
}

static void
put_handles(text_t *t, const cf__params_t *p, const char *figure,
            const double m[6])
{
    bool first = true;
    put(t, "[");
    for (size_t i = 0; i < cf__params_count(p); i++) {
        const cf__param_t *d = cf__params_at(p, i);
        if (d->kind != CF__PARAM_POINTS ||
            (d->figure[0] != '\0' && strcmp(d->figure, figure) != 0))
            continue;
        for (size_t k = 0; k < d->count; k++) {
            double x = d->xy[2 * k], y = d->xy[2 * k + 1];
            put(t, first ? "\n  {\"param\": " : ",\n  {\"param\": ");
            first = false;
            put_str(t, d->name);
            putf(t, ", \"index\": %zu, \"x\": ", k);
            put_num(t, x);
            put(t, ", \"y\": ");
            put_num(t, y);
            put(t, ", \"sx\": ");
            put_num(t, m[0] * x + m[2] * y + m[4]);
            put(t, ", \"sy\": ");
            put_num(t, m[1] * x + m[3] * y + m[5]);
            put(t, "}");
        }
    }
    put(t, "]");
}

/* [azimuth, elevation] of a 3D figure's view (as the run used it: the
** page's when it rotated the figure), null for a 2D figure. */
static void
put_view(text_t *t, const cf_figure_t *fig)
{
    cf_view_t v;
    if (!cf_figure_get_view(fig, &v)) {
        put(t, "null");
        return;
    }
    put(t, "[");
    put_num(t, v.azimuth);
    put(t, ", ");
    put_num(t, v.elevation);
    put(t, "]");
}

/* The line of "name:LINE: ..." (0 when the message has none). */
static int
error_line(const char *msg, const char *name)
{
    size_t n = strlen(name);
    const char *p = msg;
    if (strncmp(p, name, n) == 0 && p[n] == ':')
        p += n + 1;
    else if ((p = strchr(msg, ':')) != NULL)
        p++;
    else
        return 0;
    return isdigit((unsigned char)*p) ? atoi(p) : 0;
}

static void
put_error(text_t *t, const char *msg, int line)
{
    put(t, "{\"message\": ");
    put_str(t, msg);
    putf(t, ", \"line\": %d}", line);
}

/* A figure's entry; a failed figure gives its message in *err. */
static int
put_figure(text_t *t, const cf_script_t *s, size_t i, char *err,
           size_t errlen)
{
    cf_figure_t *fig = cf_script_figure(s, i);
    const char *name = cf_script_figure_name(s, i);
    unsigned char *svg = NULL;
    size_t size = 0;
    double m[6], w, h;
    char *places = NULL;
    size_t places_size = 0;
    cf_diag_t diag;
    cf_script_scope_t scope;
    cf_status_t st;
    char over[200];
    cf_diag_clear(&diag);
    cf_script_budget_begin(s, &scope);
    st = cf_figure_render_places(fig, CF_FORMAT_SVG, NULL, &svg, &size, m,
                                 &places, &places_size, &diag);
    if (cf_script_budget_end(s, &scope, over, sizeof over) &&
        st != CF_STATUS_OK) {
        snprintf(err, errlen, "%sfigure '%s': %s; %s",
                 cf_script_figure_where(s, i), name, over, diag.msg);
        cf_free(svg);
        cf_free(places);
        return -1;
    }
    if (st != CF_STATUS_OK) {
        snprintf(err, errlen, "%sfigure '%s': %s", cf_script_figure_where(s, i),
                 name, diag.msg);
        cf_free(svg);
        return -1;
    }
    cf_figure_get_size(fig, &w, &h);
    put(t, i ? ",\n {\"name\": " : "\n {\"name\": ");
    put_str(t, name);
    put(t, ", \"caption\": ");
    put_str(t, cf_script_figure_caption(s, i));
    put(t, ", \"width\": ");
    put_num(t, w);
    put(t, ", \"height\": ");
    put_num(t, h);
    put(t, ", \"view\": ");
    put_view(t, fig);
    put(t, ",\n  \"to_svg\": [");
    for (int k = 0; k < 6; k++) {
        put(t, k ? ", " : "");
        put_num(t, m[k]);
    }
    put(t, "],\n  \"handles\": ");
    put_handles(t, cf_script_params(s), name, m);
    put(t, ",\n  \"labels\": ");
    put_n(t, places, places_size);
    put(t, ",\n  \"svg\": ");
    put_str_n(t, (const char *)svg, size);
    put(t, "}");
    cf_free(svg);
    cf_free(places);
    return 0;
}

int
cf_interactive_check_figures(const cf_script_t *s, char *err, size_t errlen)
{
    const cf__params_t *p = cf_script_params(s);
    for (size_t i = 0; i < cf__params_count(p); i++) {
        const cf__param_t *d = cf__params_at(p, i);
        size_t nfig = cf_script_figure_count(s), k;
        bool found = d->kind != CF__PARAM_POINTS || d->figure[0] == '\0';
        for (k = 0; !found && k < nfig; k++)
            found = strcmp(cf_script_figure_name(s, k), d->figure) == 0;
        if (!found) {
            const char *names[64], *near;
            size_t n = nfig < 64 ? nfig : 64;
            for (k = 0; k < n; k++)
                names[k] = cf_script_figure_name(s, k);
            near = cf_nearest_name(d->figure, names, n);
            snprintf(err, errlen, "points '%s' (line %d): figure = '%s' "
                     "names no figure of the script%s%s%s", d->name,
                     d->line_no, d->figure, near != NULL ? " (did you mean '"
                     : "", near != NULL ? near : "", near != NULL ? "'?)"
                     : "");
            return d->line_no;
        }
    }
    return -1;
}

static cf_status_t
finish(text_t *t, char **json, size_t *len)
{
    if (t->failed) {
        free(t->s);
        return CF_STATUS_NO_MEMORY;
    }
    *json = t->s;
    *len = t->len;
    return CF_STATUS_OK;
}

cf_status_t
cf_interactive_run(const char *code, const char *name, const char *values,
                   size_t values_len, const cf_script_limits_t *limits,
                   FILE *out, char **json, size_t *len)
{
    return cf_interactive_run_error(code, name, values, values_len, limits,
                                    out, json, len, NULL, 0);
}

cf_status_t
cf_interactive_run_error(const char *code, const char *name,
                         const char *values, size_t values_len,
                         const cf_script_limits_t *limits, FILE *out,
                         char **json, size_t *len, char *error,
                         size_t error_len)
{
    text_t t = { NULL, 0, 0, 0 };
    cf_script_t *s = NULL;
    cf_diag_t diag;
    char err[1024] = "";
    int line = 0;
    cf_status_t st;
    *json = NULL;
    *len = 0;
    if (error != NULL && error_len > 0)
        error[0] = '\0';
    cf_diag_clear(&diag);
    if (cf_script_create(limits, out != NULL ? out : stderr, &s, &diag) !=
        CF_STATUS_OK)
        return CF_STATUS_NO_MEMORY;
    if (values != NULL &&
        cf__params_give_json(cf_script_params(s), values, values_len, err,
                             sizeof err) != 0) {
        cf_script_destroy(s);
        if (error != NULL && error_len > 0)
            snprintf(error, error_len, "%s", err);
        put(&t, "{\"params\": [], \"figures\": [], \"error\": ");
        put_error(&t, err, 0);
        put(&t, ", \"lua\": \"\"}\n");
        return finish(&t, json, len) == CF_STATUS_OK ? CF_STATUS_INVALID_ARG
                                                     : CF_STATUS_NO_MEMORY;
    }
    st = cf_script_run_string(s, code, name);
    if (st != CF_STATUS_OK) {
        snprintf(err, sizeof err, "%s", cf_script_error(s));
        line = error_line(err, name);
    } else if ((line = cf_interactive_check_figures(s, err, sizeof err)) < 0) {
        line = 0;
    }
    put(&t, "{\"params\": [");
    for (size_t i = 0; i < cf__params_count(cf_script_params(s)); i++) {
        put(&t, i ? ",\n " : "\n ");
        put_param(&t, cf__params_at(cf_script_params(s), i));
    }
    put(&t, "],\n\"figures\": [");
    if (err[0] == '\0') {
        size_t mark = t.len;
        for (size_t i = 0; i < cf_script_figure_count(s); i++)
            if (put_figure(&t, s, i, err, sizeof err) != 0) {
                line = error_line(err, name);
                t.len = mark;       /* no figure on an error */
                if (t.s != NULL)
                    t.s[mark] = '\0';
                break;
            }
    }
    put(&t, "],\n\"error\": ");
    if (error != NULL && error_len > 0)
        snprintf(error, error_len, "%s", err);
    if (err[0] != '\0')
        put_error(&t, err, line);
    else
        put(&t, "null");
    put(&t, ",\n\"lua\": ");
    {
        text_t lua = { NULL, 0, 0, 0 };
        lua_values(&lua, cf_script_params(s));
        t.failed |= lua.failed;
        put_str_n(&t, lua.s != NULL ? lua.s : "", lua.len);
        free(lua.s);
    }
    put(&t, "}\n");
    cf_script_destroy(s);
    return finish(&t, json, len);
}
