/*
** Internals shared by the files of labels: the runs of a laid-out label,
** the font state of the parser, and the character tables.
**   label.c        the public functions, ink box and drawing
**   label-parse.c  the parser, which lays out as it reads
**   label-runs.c   runs of glyphs shaped and measured by the label's
**                  fonts (font.h: HarfBuzz as pango natively, the page's
**                  glyph table in the browser module)
**   label-chars.c  UTF-8 and the tables of commands, spaces and accents
*/
#ifndef CURVEFIG_RENDER_LABEL_IMPL_H
#define CURVEFIG_RENDER_LABEL_IMPL_H

#include <stdbool.h>
#include <stddef.h>

#include "font.h"
#include "label-private.h"

#define SCRIPT_RATIO 0.7       /* 10 pt -> 7 pt */
#define SCRIPT2_RATIO 0.5      /* 10 pt -> 5 pt */
#define MAX_DEPTH 32           /* nesting of groups */

typedef struct run {
    char *text;
    size_t text_len;
    double x, y;              /* baseline origin, y up */
    double size;
    int level;
    cf_label_kind_t kind;
    bool italic, bold;
    bool math;                       /* set in the math font */
    void *shaped;                    /* the fonts' run (font.h); NULL:
                                        not shaped */
    double width, ascent, descent;   /* logical */
    double ink[4];                   /* x0 y0 x1 y1 relative to origin,
                                        y down */
    double baseline;                 /* layout top to baseline */
    int unknown;                     /* characters without a glyph */
    double rule_h;                   /* > 0: a fraction rule of this
                                        thickness, width `width`, its
                                        bottom at y (no text) */
    /* a run extended character by character (label-runs.c): its text
    ** from byte `tail` on measured alone is `tail_w` wide; `stale`: the
    ** layout does not hold the whole text yet (cf__label_runs_finish) */
    size_t tail;
    double tail_w;
    bool stale;
} run_t;

struct cf_label {
    run_t *runs;
    size_t count, cap;
    char *family;
    double size;
    size_t unknown;
    const cf__fonts_t *fonts;
    void *fonts_ctx;
    bool merge_ok;            /* the last atom may be extended */
    bool tex_math;            /* a TeX family: letters of mathematics in
                                 the math font's italic alphabet */
    void *scratch;            /* the fonts' run that measures the tails
                                 of growing runs (font.h) */
    size_t shaped;            /* bytes handed to the fonts to shape */
    cf_label_box_t *boxes;    /* public view of the runs */
    cf__pathb_t outline;      /* cf__label_outline */
    double outline_box[4];    /* its exact box (cf__label_outline_box) */
};

typedef struct font {
    double size;
    int level;
    cf_label_kind_t kind;
    bool italic, bold;
    bool math;            /* glyphs of the math font (CF__MATH_FAMILY) */
    bool boldsymbol;      /* \boldsymbol: letters bold italic */
    bool cal;             /* \mathcal: capitals calligraphic */
    bool bb;              /* \mathbb: capitals and digits double-struck */
    bool text;            /* text mode: upright, no scripts */
} font_t;

/* The math font: TeX's symbols and its math italic alphabet. */
#define CF__MATH_FAMILY "Latin Modern Math"

/* Spacing classes of atoms (TeX's). */
enum { CLS_NONE, CLS_ORD, CLS_OP, CLS_BIN, CLS_REL, CLS_OPEN, CLS_CLOSE,
       CLS_PUNCT, CLS_INNER, CLS_SPACE };

/* ---- label-math.c ------------------------------------------------------- */

/* The class and form of a character typed in math (*cp may become the
** minus sign, the asterisk operator or the prime); *italic for letters. */
int cf__label_math_char(unsigned *cp, bool *italic, const font_t *f);
/* Space in em (18 mu) between atoms of classes a and b at script level
** level (0 text style): TeX's table of rule 20. */
double cf__label_atom_space(int a, int b, int level);

/* Whether s[pos] = '{' opens a group of exactly one character ({P},
** { P }): an accent's argument of one character rather than a group. */
bool cf__label_single_char_group(const char *s, size_t len, size_t pos);

/* ---- label-runs.c ------------------------------------------------------- */

/* Append UTF-8 bytes at (x, y) in font f; merges with the previous run
** when it continues it.  Returns the new pen x, or NAN when out of
** memory. */
double cf__label_put_text(cf_label_t *lab, const font_t *f, double x,
                          double y, const char *s, size_t n);
/* Shape once more the runs put_text extended, each whole (their runs of
** the fonts then hold their text), once the label is parsed; false when
** the fonts failed (out of memory). */
bool cf__label_runs_finish(cf_label_t *lab);
/* TeX's italic correction of one slanted character in font f: how far
** its ink reaches right of its advance width (0 when it does not); NAN
** when the fonts failed (out of memory). */
double cf__label_italic_correction(cf_label_t *lab, const font_t *f,
                                   const char *s, size_t n);

/* The advance width and ink box (y down) of s[0..n) alone in font f,
** without adding a run (false: no layout; for n < 16, the fonts failed,
** out of memory). */
bool cf__label_measure(cf_label_t *lab, const font_t *f, const char *s,
                       size_t n, double *width, double ink[4]);

/* ---- label-chars.c ------------------------------------------------------ */

/* Decode one UTF-8 character at s[pos]; returns its length (0 when
** invalid) and the code point. */
size_t cf__utf8_decode(const char *s, size_t len, size_t pos, unsigned *cp);
/* The label text s (len bytes) around byte at, for a message: at most 24
** bytes on either side, cut between characters, "..." where cut; a byte
** that is not printable UTF-8 written \xHH.  out gets cap bytes at most
** (72 hold any excerpt). */
void cf__label_excerpt(const char *s, size_t len, size_t at, char *out,
                       size_t cap);
/* Encode c into out (4 bytes of room); returns the length. */
size_t cf__utf8_encode(unsigned c, char *out);
/* The symbol a command names: code point, class, italic in math. */
bool cf__label_symbol(const char *name, unsigned *cp, int *cls,
                      bool *italic);
/* A horizontal space command: its width in em. */
bool cf__label_space(const char *name, double *em);
/* Whether text has a `$` (not \\$): then text outside $...$ is text. */
bool cf__label_has_dollar(const char *text);
/* The first symbol command of code point cp (NULL: none). */
const char *cf__label_symbol_name(unsigned cp);
/* An accent command: the code point of its spacing form. */
bool cf__label_accent(const char *name, unsigned *cp);
/* The math italic (bold: bold italic) form of a Latin or Greek letter or
** \partial in Latin Modern Math; 0 for another character. */
unsigned cf__math_italic(unsigned cp, bool bold);
/* The calligraphic form of a capital letter (\mathcal); 0 otherwise. */
unsigned cf__math_cal(unsigned cp);
/* The double-struck form of a capital letter or a digit (\mathbb); 0
** otherwise. */
unsigned cf__math_bb(unsigned cp);
/* The known command nearest to name (fewest edits), for a message. */
const char *cf__label_nearest_command(const char *name);
/* Whether name is a command with an argument (\frac, \mathbf, ...). */
bool cf__label_structure(const char *name);

/* ---- label-parse.c ------------------------------------------------------ */

/* Parse and lay out text into lab (empty, with family, size and context
** set). */
cf_status_t cf__label_parse(cf_label_t *lab, const char *text,
                            cf_diag_t *diag);

/* Extents of a laid-out piece (runs [first, end) of the label). */
typedef struct piece {
    size_t first, end;
    double x0, x1;            /* pen start and end */
    double top, bottom;       /* ink extent above/below the baseline
                                 (top positive up, bottom positive down) */
    int cls;                  /* spacing class of the atom */
    bool group;               /* nucleus was a group or command result */
    double ic;                /* italic correction of a slanted single
                                 character: how far its ink reaches past
                                 its advance (bp, >= 0) */
} piece_t;

/* The parser's state (render/labels/label-parse.c). */
typedef struct parser {
    const char *s;
    size_t pos, len;
    cf_label_t *lab;
    cf_diag_t *diag;
    cf_status_t st;
    bool has_dollar;
    bool in_math;
    int depth;
    /* one atom (character, command or group); a list of atoms up to
    ** stop: '}', '$', ']' (an optional argument), 'R' (a \\right) or 0
    ** (render/labels/label-build.c calls back through these) */
    bool (*atom)(struct parser *p, const font_t *f, double x, double y,
                 piece_t *pc);
    bool (*list)(struct parser *p, const font_t *f, double x, double y,
                 int stop, piece_t *out);
} parser_t;

/* ---- label-pieces.c ----------------------------------------------------- */

/* The parser's pieces, for it and the constructions of label-build.c.
** cf__lp_error records "label ...: what at byte at" (the first error
** wins) and returns the status; cf__lp_nomem the same for memory. */
cf_status_t cf__lp_error(parser_t *p, size_t at, const char *what);
cf_status_t cf__lp_nomem(parser_t *p);
void cf__lp_piece_init(piece_t *pc, cf_label_t *lab, double x);
/* Recompute pc's top and bottom from its runs (baseline y). */
void cf__lp_piece_ink(cf_label_t *lab, piece_t *pc, double y);
/* The font of a script (or a fraction's parts) of f: next level, size
** base times the level's ratio. */
void cf__lp_script_font(const font_t *f, font_t *out, cf_label_kind_t kind,
                        double base);
void cf__lp_move(cf_label_t *lab, size_t first, size_t end, double dx,
                 double dy);
/* A rule of thickness th and width w, its bottom at (x, y). */
bool cf__lp_rule(parser_t *p, const font_t *f, double x, double y, double w,
                 double th);
/* pc becomes one ordinary atom of the runs from first on. */
void cf__lp_over_group(cf_label_t *lab, piece_t *pc, size_t first, double y);

/* ---- label-build.c ------------------------------------------------------ */

/* The constructions after their command at byte at (p->pos after the
** name): \frac (and \frac14), \binom, \sqrt and \sqrt[n], and
** \left ... \right. */
bool cf__label_frac(parser_t *p, const font_t *f, double x, double y,
                    piece_t *pc, size_t at, bool rule);
bool cf__label_sqrt(parser_t *p, const font_t *f, double x, double y,
                    piece_t *pc, size_t at);
bool cf__label_left_right(parser_t *p, const font_t *f, double x, double y,
                          piece_t *pc, size_t at);

#endif
