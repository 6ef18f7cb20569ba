/*
** The format list of `curvefig render -f` (formats-arg.c): names
** separated by commas, each a figure format (svg, pdf, png, ps, eps, pgf),
** html, an animation format (gif, apng, mp4, webm) or all.
*/
#ifndef CURVEFIG_TOOL_FORMATS_ARG_H
#define CURVEFIG_TOOL_FORMATS_ARG_H

/* The bits of the formats in list (CF_FORMAT_BIT, CF__TOOL_HTML_BIT, the
** animation bits of animate.h) in *out: 0, or -1 for an empty or unknown
** name. */
int cf__tool_parse_formats(const char *list, unsigned *out);
/* The nearest valid name to the first unknown one in list (NULL: none
** near enough). */
const char *cf__tool_nearest_format(const char *list);

#endif
