/*
** curvefig labels: a small TeX-like syntax laid out with pango (library
** curvefig-render; included by curvefig/figure.h).
*/
#ifndef CURVEFIG_LABEL_H
#define CURVEFIG_LABEL_H

#include <stdbool.h>
#include <stddef.h>

#include "curvefig/core.h"
#include "curvefig/export.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- labels ------------------------------------------------------------- */

/*
** Label syntax.  A text without `$` is all math; with `$`, text outside
** $...$ is upright text and inside is math.
**   math: letters in the math italic, as TeX sets them (with the serif
**         family: Latin Modern Math's italic alphabet U+1D434..., h is
**         U+210E; with another family: its italic); digits,
**         punctuation, ( ) [ ] upright; operators and relations from
**         Latin Modern Math (\ge is ≥, not ⩾); `-` is the minus sign.
**         Spaces are ignored; TeX's spaces between atoms apply (The
**         TeXbook, rule 20): thick 5 mu around relations, medium 4 mu
**         around binary operators (none for a unary minus), thin 3 mu
**         after punctuation and around large operators; in scripts only
**         the thin ones; 18 mu = the font's quad (its size).
**   x_i  x_{...}  subscript; x^n  x^{...}  superscript; both (any order)
**         stack at the same x: B_i^n, N_{i}^{p}; scripts nest (size 70 %,
**         then 50 %; Latin Modern's 7 pt and 5 pt designs are used for
**         them, as in TeX).  ' is a prime (U+2032).
**   \alpha ... \omega, \Gamma ... \Omega (also \varepsilon \vartheta
**         \varphi \varrho \varsigma): lowercase italic, uppercase upright.
**   \cdot \times \infty \partial \nabla \pm \leq \geq \neq \to \ldots
**         \dots \sum \prod \int, \, \; \quad spaces, \{ \} \_ \$ \\ escapes.
**   \mathrm{...} \text{...} upright; \mathbf{...} bold; \mathit{...};
**         \boldsymbol{...} bold italic letters; \mathcal{A} capitals;
**         \overline{...} a rule over the group.
**   \frac{num}{den} (script size, centred, rule on the math axis;
**         \frac14: one-token arguments, as in TeX); \binom{n}{k};
**   \sqrt{x}, \sqrt[n]{x}: the radical sign sized to the radicand (TeX's
**         rule 11: Latin Modern Math's sign scaled to the height the
**         radicand, the gap and the rule need), a rule over it;
**   \left( ... \right) with ( ) [ ] | / . \{ \} \langle \rangle \|:
**         delimiters sized to what they enclose (rule 19);
**   \mathbb{R}: double-struck capitals and digits;
**   \hat \bar \tilde \vec \dot \ddot over one character, or centred over
**         a {group} of several (\vec{PQ}), as TeX sets them over a box.
**   Any UTF-8 text (Czech, Russian, Slovene, Chinese): letters outside
**   ASCII are set upright; the family list supplies Cyrillic and CJK.
** Errors (unbalanced braces, unknown command, dangling _ or ^, invalid
** UTF-8) are INVALID_ARG with the byte position in diag->index; the
** message quotes the text around that byte, and an unknown command's
** message names the nearest known one.  A label has at most
** CF_LABEL_MAX_BYTES bytes (each character of a run is laid out with the
** run so far: the work grows with the square of a run's length).
*/
#define CF_LABEL_MAX_BYTES 1000

/* One run of glyphs of a laid-out label. */
typedef enum cf_label_kind {
    CF_LABEL_BASE = 0,  /* at the level's baseline */
    CF_LABEL_SUB,       /* a subscript run */
    CF_LABEL_SUP        /* a superscript run */
} cf_label_kind_t;

typedef struct cf_label_box {
    double x, y;             /* left end of the run's baseline, bp, relative
                                to the label origin; y UP */
    double width;            /* advance width, bp */
    double ascent, descent;  /* logical extents above/below the baseline
                                (descent positive) */
    double size;             /* font size, bp */
    int level;               /* 0 base, 1 script, 2 scriptscript */
    cf_label_kind_t kind;    /* innermost script kind of the run */
    bool italic;
    size_t start, end;       /* 0 and the byte length of the run's text
                                (cf_label_run_text; "" for a fraction
                                rule) */
} cf_label_box_t;

typedef struct cf_label cf_label_t;

/* Parse and lay out text at font size size_bp with the family list family
** (NULL: the default theme's). */
CF_API cf_status_t cf_label_create(const char *text, const char *family,
                                   double size_bp, cf_label_t **out,
                                   cf_diag_t *diag);
CF_API void cf_label_destroy(cf_label_t *label);

CF_API size_t cf_label_box_count(const cf_label_t *label);
/* Box i (NULL if out of range). */
CF_API const cf_label_box_t *cf_label_get_box(const cf_label_t *label,
                                              size_t i);
/* The UTF-8 text of run i ("" if out of range). */
CF_API const char *cf_label_run_text(const cf_label_t *label, size_t i);
/* Logical size of the whole label: width, ascent above and descent below
** the base line (bp). */
CF_API void cf_label_get_extents(const cf_label_t *label, double *width,
                                 double *ascent, double *descent);
/* Number of characters no font of the family list (nor fontconfig's
** fallback) could show: 0 means no empty boxes. */
CF_API size_t cf_label_unknown_glyphs(const cf_label_t *label);

/* Every command of the label syntax, from the parser's own tables (what
** `curvefig help labels` lists): kind "symbol", "space", "accent" or
** "structure", the name without its backslash, and what it gives. */
CF_API void cf_label_each_command(void (*visit)(const char *kind,
                                                const char *name,
                                                const char *what, void *ctx),
                                  void *ctx);

#ifdef __cplusplus
}
#endif

#endif
