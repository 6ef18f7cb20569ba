/*
** curvefig figure scripts: a sandboxed Lua 5.4 state that runs one script
** and collects the figures it defines.  Used by the `curvefig` tool.
**
** The sandbox opens base (without dofile, loadfile and binary chunks;
** setmetatable refuses __gc, whose finaliser would run unhooked), math, string (without string.dump), table and utf8; no io, os, package,
** debug or coroutine.  Memory (Lua's and the library's) and the number of
** Lua instructions (the steps of pattern searches included, counted before
** each search runs inside its C call) are capped; exceeding a cap stops the script with
** "script exceeded the memory limit of N MiB" or "script exceeded the
** instruction limit of N instructions", and pcall cannot catch either.
*/
#ifndef CURVEFIG_RENDER_LUA_SCRIPT_H
#define CURVEFIG_RENDER_LUA_SCRIPT_H

#include <stdbool.h>
#include <stdio.h>

#include "curvefig/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cf_script cf_script_t;

/* max_memory is never exceeded: 1/16 of it (at most 1 MiB) is held back
** to report the limit; a budget too small for the sandbox itself makes
** cf_script_create fail with CF_STATUS_NO_MEMORY.  Messages give it in
** MiB, KiB or bytes, whichever divides it. */
typedef struct cf_script_limits {
    size_t max_memory;                 /* bytes; 0 = default (256 MiB) */
    unsigned long long max_instructions; /* 0 = default (500 million) */
} cf_script_limits_t;

#define CF_SCRIPT_DEFAULT_MEMORY ((size_t)256 << 20)
#define CF_SCRIPT_DEFAULT_INSTRUCTIONS 500000000ull
/* What print may write in one script run, in bytes (then print fails with
** "print: the script's output reached its limit of 16 MiB"). */
#define CF_SCRIPT_MAX_PRINT ((size_t)16 << 20)

/* A fresh sandbox; `out` receives what the script prints (NULL: stdout).
** limits may be NULL (defaults).  The script's memory budget is the curve
** library's current allocator of the calling thread while the script runs
** (cf_use_allocator), so the curves it makes count against its own limit;
** scripts are independent: several may be alive in one process, created
** and destroyed in any order. */
cf_status_t cf_script_create(const cf_script_limits_t *limits, FILE *out,
                             cf_script_t **script, cf_diag_t *diag);
void cf_script_destroy(cf_script_t *script);

/* Leave out every label (labels, tick and axis labels) of the figures the
** script defines from now on: the label-free layer of the pixel tests. */
void cf_script_set_labels(cf_script_t *script, bool enabled);

/* The fonts of every figure the script makes (family "serif", "sans" or
** a Pango list, NULL: the script's; size_bp 0: the script's), over the
** script's theme{} calls but not over a figure's own font and font_size
** (render/lua/ltheme.c). */
void cf_script_set_fonts(cf_script_t *script, const char *family,
                         double size_bp);

/* The page of every figure the script makes (the tool's --width and
** --height), in bp, over its figure{} width and height; 0: the script's
** (one alone keeps the proportions the script asks for). */
void cf_script_set_page(cf_script_t *script, double width_bp,
                        double height_bp);

/* The seed of math.random (the tool's --seed): every script starts from
** CF_SCRIPT_DEFAULT_SEED, so that a script that draws random numbers
** renders the same twice; math.randomseed() without an argument takes
** this seed too, not the clock. */
#define CF_SCRIPT_DEFAULT_SEED 0
void cf_script_set_seed(cf_script_t *script, long long seed);

/* Load and run the file at path.  CF_STATUS_SCRIPT (or NO_MEMORY, IO) on
** failure; the full message (file, line, what went wrong, the Lua frames
** that led there) is then cf_script_error(). */
cf_status_t cf_script_run_file(cf_script_t *script, const char *path);
/* The same for a chunk in memory; name is used in messages. */
cf_status_t cf_script_run_string(cf_script_t *script, const char *code,
                                 const char *name);
const char *cf_script_error(const cf_script_t *script);

/* Rendering inside the script's memory budget: between
** cf_script_budget_begin and cf_script_budget_end the calling thread
** allocates from the script's budget (cf_use_allocator), so what the
** renderer allocates for the script's figures -- display list, layout,
** label runs, rasters and image surfaces, output buffers -- counts against
** the same max_memory as the script's own memory (which stays allocated).
** A rendering that fails for want of memory then fails with
** CF_STATUS_NO_MEMORY; cf_script_budget_end restores the allocator and
** says whether the budget refused an allocation in between (then msg
** holds "rendering exceeded the memory limit of N MiB ..."). */
typedef struct cf_script_scope {
    cf_allocator_t prev;
    unsigned long refused;
} cf_script_scope_t;
void cf_script_budget_begin(const cf_script_t *script, cf_script_scope_t *scope);
bool cf_script_budget_end(const cf_script_t *script, cf_script_scope_t *scope,
                          char *msg, size_t size);

/* The figures the script defined, in the order of definition. */
size_t cf_script_figure_count(const cf_script_t *script);
struct cf_figure *cf_script_figure(const cf_script_t *script, size_t i);
const char *cf_script_figure_name(const cf_script_t *script, size_t i);
const char *cf_script_figure_caption(const cf_script_t *script, size_t i);
/* Where the script made figure i: "FILE:LINE:" of its figure{} call. */
const char *cf_script_figure_where(const cf_script_t *script, size_t i);

/* The sliders and draggable points of the script (render/lua/params.h):
** give values before cf_script_run_*, read the declarations after. */
struct cf__params;
struct cf__anim_spec;
/* The script's animate{} (render/lua/anim-spec.h), NULL when it made
** none. */
const struct cf__anim_spec *cf_script_animation(const cf_script_t *script);
struct cf__params *cf_script_params(const cf_script_t *script);

#ifdef __cplusplus
}
#endif

#endif
