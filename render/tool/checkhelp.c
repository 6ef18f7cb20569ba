/*
** The help of `curvefig compare` and `curvefig test`.
*/
#include <stdio.h>
#include <string.h>

#include "checks.h"

static const char compare_help[] =
    "usage: curvefig compare A B [--diff D.png] [--dpi N] [--threshold T]\n"
    "                            [--aa-radius R] [--max-bad N | P%]\n"
    "\n"
    "Compare two images, each a PNG or an SVG (rasterised by librsvg at\n"
    "--dpi, by default the resolution the other image, a PNG, records (150\n"
    "for `curvefig render`'s) or 144, at its own size, the last partial\n"
    "pixel rounded up as the PNG renderer does, so that a figure's SVG and\n"
    "PNG compare).  PDF is not supported (no PDF rasteriser):\n"
    "compare the figure's SVG or PNG.  B is the expected image.\n"
    "\n"
    "Prints the size of each, then the verdict: how many pixels differ and\n"
    "their share, and how many more differ by anti-aliasing only.\n"
    "\n"
    "The comparator: every pixel, composited on white, gets the YIQ colour\n"
    "distance of pixelmatch, 0 (equal) to 1 (black against white).  A pixel\n"
    "over the threshold is forgiven as anti-aliasing when each image's\n"
    "colour lies within the colours of the other's neighbourhood of radius\n"
    "R (an edge a fraction of a pixel elsewhere), or when the two\n"
    "neighbourhoods carry the same ink (a hairline on one row against two\n"
    "half rows).  The others differ; the images are the same when at most\n"
    "--max-bad of them differ.\n"
    "\n"
    "Options:\n"
    "  --diff D.png       write the diff image: B faded, red where the\n"
    "                     images differ, yellow where only anti-aliasing\n"
    "                     does\n"
    "  --dpi N            resolution for SVG files, 1..2400 (default: a\n"
    "                     PNG operand's own, else 144)\n"
    "  --threshold T      YIQ distance a pixel may differ by, 0..1\n"
    "                     (default 0.1, about 26 grey levels)\n"
    "  --aa-radius R      neighbourhood of the anti-aliasing allowance,\n"
    "                     0 (none) .. 8 pixels (default 1)\n"
    "  --max-bad N | P%   differing pixels allowed, a count or a share\n"
    "                     (default 0; `curvefig test` allows 0.05% on\n"
    "                     figures with labels)\n"
    "\n"
    "Exit status: 0 the same picture, 1 different, 2 an error (a file that\n"
    "is missing or not a PNG or SVG, images whose sizes differ, usage).\n";

static const char test_help[] =
    "usage: curvefig test [SCRIPT.lua... | DIR...] --references REF\n"
    "                     [-o OUT] [--update] [--dpi N] [--threshold T]\n"
    "\n"
    "Guard figures against change: render every figure of the scripts (a\n"
    "DIR stands for its *.lua files) as SVG and PNG at --dpi (default 144),\n"
    "with labels into OUT (default ./curvefig-test) and without them into\n"
    "OUT/nolabels, and check each figure four times with the comparator of\n"
    "`curvefig compare`:\n"
    "  its PNG against REF/nolabels/NAME.png: no pixel may differ;\n"
    "  its PNG against REF/NAME.png: 0.05% of the pixels may differ (glyph\n"
    "    rasterisation);\n"
    "  its SVG, rasterised by librsvg, against its PNG, without labels\n"
    "    (strict) and with them (0.05%): the two outputs draw one picture.\n"
    "A figure with overlay steps is checked step by step as well: its\n"
    "NAME-K.png (step K alone) against REF/NAME-K.png, the same four ways;\n"
    "a failure names the step.\n"
    "With DIR operands only, a reference whose figure no script defines any\n"
    "more fails too.  Every failure is printed and shown in OUT/report.html\n"
    "with the expected, actual and diff images (in OUT/failures) and the\n"
    "numbers.\n"
    "\n"
    "  --update           write the references instead: each figure is\n"
    "                     listed as new, changed (with what changed) or\n"
    "                     unchanged (its file is left alone); with DIR\n"
    "                     operands references of figures that are gone are\n"
    "                     removed.  Each file is written under a temporary\n"
    "                     name and renamed; a script that fails writes none.\n"
    "  --references REF   the reference directory (REF and REF/nolabels)\n"
    "  -o, --output OUT   the output directory (default curvefig-test)\n"
    "  --dpi N            PNG resolution, 1..2400 (default 144)\n"
    "  --threshold T      the comparator's YIQ threshold (default 0.1)\n"
    "\n"
    "Figure names must differ across the scripts: they name the files.\n"
    "\n"
    "Exit status: 0 every figure matches; 1 some figure differs, has no\n"
    "reference or lost its figure; 2 an error (usage, a missing reference\n"
    "directory, a script that fails, a file that cannot be written).\n";

int
cf__tool_checks_help(const char *topic)
{
    if (strcmp(topic, "compare") == 0)
        fputs(compare_help, stdout);
    else if (strcmp(topic, "test") == 0)
        fputs(test_help, stdout);
    else
        return 2;
    return 0;
}
