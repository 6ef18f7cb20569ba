/*
** Running a figure script (script.h): loading its chunk (text only, line
** by line, so that a syntax error without a position gets the line the
** parser reached), running it with the traceback handler, its message
** kept whole; and what the run left: the figures, their names and places,
** the parameters and the animation it declared.
*/
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lfigure.h"
#include "ltrace.h"
#include "script-private.h"

/* ---- running ------------------------------------------------------------ */

/* The message of a run, its n bytes kept whole: a NUL in it (error("a\0b"))
** is written \0 rather than ending the message there. */
static void
set_error_n(cf_script_t *s, const char *msg, size_t n)
{
    size_t nul = 0, k = 0;
    for (size_t i = 0; i < n; i++)
        nul += msg[i] == '\0';
    free(s->error);
    s->error = malloc(n + nul + 1);
    if (s->error == NULL)
        return;
    for (size_t i = 0; i < n; i++) {
        if (msg[i] == '\0') {
            s->error[k++] = '\\';
            s->error[k++] = '0';
        } else {
            s->error[k++] = msg[i];
        }
    }
    s->error[k] = '\0';
}

static void
set_error(cf_script_t *s, const char *msg)
{
    set_error_n(s, msg, strlen(msg));
}

static cf_status_t
finish(cf_script_t *s, int rc, const char *name)
{
    lua_State *L = s->L;
    if (rc == LUA_OK)
        return CF_STATUS_OK;
    if (s->limit_hit == LIMIT_MEMORY || rc == LUA_ERRMEM) {
        char buf[512], size[40];
        cf__script_format_size(size, s->max_memory);
        if (s->where[0] != '\0')
            snprintf(buf, sizeof buf, "%sscript exceeded the memory limit "
                     "of %s", s->where, size);
        else
            snprintf(buf, sizeof buf, "%s: script exceeded the memory limit "
                     "of %s", name, size);
        set_error(s, buf);
    } else {
        size_t len;
        const char *msg = lua_tolstring(L, -1, &len);
        if (msg != NULL)
            set_error_n(s, msg, len);
        else
            set_error(s, "unknown error");
    }
    lua_settop(L, 0);
    return CF_STATUS_SCRIPT;
}

static cf_status_t
run_loaded(cf_script_t *s, int rc, const char *name)
{
    lua_State *L = s->L;
    cf_allocator_t prev;
    if (rc != LUA_OK)
        return finish(s, rc, name);
    lua_pushcfunction(L, cf__lua_traceback);
    lua_insert(L, -2);
    s->running = 1;
    cf_use_allocator(&s->alloc, &prev);
    rc = lua_pcall(L, 0, 0, -2);
    cf_use_allocator(&prev, NULL);
    s->running = 0;
    return finish(s, rc, name);
}

cf_status_t
cf_script_run_file(cf_script_t *s, const char *path)
{
    FILE *f;
    char *code;
    long len;
    cf_status_t st;
    if (s == NULL || path == NULL)
        return CF_STATUS_INVALID_ARG;
    f = fopen(path, "rb");
    if (f == NULL) {
        char buf[512];
        snprintf(buf, sizeof buf, "cannot open %s", path);
        set_error(s, buf);
        return CF_STATUS_IO;
    }
    if (fseek(f, 0, SEEK_END) != 0 || (len = ftell(f)) < 0 ||
        fseek(f, 0, SEEK_SET) != 0 ||
        (code = malloc((size_t)len + 1)) == NULL) {
        char buf[512];
        fclose(f);
        snprintf(buf, sizeof buf, "cannot read %s", path);
        set_error(s, buf);
        return CF_STATUS_IO;
    }
    if (fread(code, 1, (size_t)len, f) != (size_t)len) {
        char buf[512];
        fclose(f);
        free(code);
        snprintf(buf, sizeof buf, "cannot read %s", path);
        set_error(s, buf);
        return CF_STATUS_IO;
    }
    fclose(f);
    code[len] = '\0';
    st = cf_script_run_string(s, code, path);
    free(code);
    return st;
}

/* The chunk is handed to the parser one line at a time, so that the
** reader knows which line the parser has reached when it fails. */
typedef struct line_reader {
    const char *p;
    size_t left;
    int line;            /* lines handed out so far */
} line_reader;

static const char *
read_line(lua_State *L, void *ud, size_t *size)
{
    line_reader *rd = ud;
    const char *nl, *p = rd->p;
    (void)L;
    if (rd->left == 0) {
        *size = 0;
        return NULL;
    }
    nl = memchr(p, '\n', rd->left);
    *size = nl != NULL ? (size_t)(nl - p) + 1 : rd->left;
    rd->p += *size;
    rd->left -= *size;
    if (rd->line < INT_MAX)
        rd->line++;
    return p;
}

/* A load error at the top of the stack, below it the chunk name "@name":
** the parser's "C stack overflow" (source nested too deeply) carries no
** position; give it the chunk's short name (as the other syntax errors
** have it) and the line the parser had reached. */
static void
place_load_error(lua_State *L, int line)
{
    const char *msg = lua_tostring(L, -1);
    const char *src = "?";
    lua_Debug ar;
    if (msg == NULL)
        return;
    /* the short name of the chunk, the way Lua prints it: from an empty
    ** chunk loaded under the same name */
    if (luaL_loadbufferx(L, "", 0, lua_tostring(L, -2), "t") == LUA_OK) {
        lua_pushvalue(L, -1);
        if (lua_getinfo(L, ">S", &ar))
            src = ar.short_src;
    }
    /* stack: ..., name, msg, chunk or error */
    if (strncmp(msg, src, strlen(src)) != 0 || msg[strlen(src)] != ':') {
        if (strcmp(msg, "C stack overflow") == 0)
            lua_pushfstring(L, "%s:%d: C stack overflow (the script nests "
                            "too deeply)", src, line);
        else
            lua_pushfstring(L, "%s:%d: %s", src, line, msg);
        lua_replace(L, -3);
    }
    lua_pop(L, 1);
}

cf_status_t
cf_script_run_string(cf_script_t *s, const char *code, const char *name)
{
    lua_State *L;
    int rc;
    line_reader rd;
    if (s == NULL || code == NULL || name == NULL)
        return CF_STATUS_INVALID_ARG;
    L = s->L;
    if (code[0] == LUA_SIGNATURE[0]) {
        char buf[512];
        snprintf(buf, sizeof buf, "%s: binary (bytecode) chunks are not "
                 "allowed; give the script's source", name);
        set_error(s, buf);
        return CF_STATUS_SCRIPT;
    }
    /* A first line starting with '#' (#!/usr/bin/env curvefig) is skipped
    ** like lua.c does; its newline is kept so line numbers stay right. */
    if (code[0] == '#') {
        const char *nl = strchr(code, '\n');
        code = nl != NULL ? nl : "";
    }
    rd.p = code;
    rd.left = strlen(code);
    rd.line = 0;
    lua_pushfstring(L, "@%s", name);
    rc = lua_load(L, read_line, &rd, lua_tostring(L, -1), "t");
    if (rc != LUA_OK && rc != LUA_ERRMEM && s->limit_hit == LIMIT_NONE)
        place_load_error(L, rd.line > 0 ? rd.line : 1);
    lua_remove(L, -2);
    return run_loaded(s, rc, name);
}

const char *
cf_script_error(const cf_script_t *s)
{
    if (s == NULL || s->error == NULL)
        return "";
    return s->error;
}

/* ---- the figures -------------------------------------------------------- */

size_t
cf_script_figure_count(const cf_script_t *s)
{
    return s != NULL ? cf__lua_figure_count(s->L) : 0;
}

cf_figure_t *
cf_script_figure(const cf_script_t *s, size_t i)
{
    return s != NULL ? cf__lua_figure_at(s->L, i) : NULL;
}

const char *
cf_script_figure_name(const cf_script_t *s, size_t i)
{
    return s != NULL ? cf__lua_figure_string(s->L, i, 1) : "";
}

const char *
cf_script_figure_caption(const cf_script_t *s, size_t i)
{
    return s != NULL ? cf__lua_figure_string(s->L, i, 2) : "";
}

const char *
cf_script_figure_where(const cf_script_t *s, size_t i)
{
    return s != NULL ? cf__lua_figure_string(s->L, i, 3) : "";
}

const cf__anim_spec_t *
cf_script_animation(const cf_script_t *s)
{
    return s != NULL && s->animated ? &s->anim : NULL;
}

cf__params_t *
cf_script_params(const cf_script_t *s)
{
    return s != NULL ? s->params : NULL;
}
