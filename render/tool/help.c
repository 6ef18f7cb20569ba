/*
** The help texts: `curvefig --help` (the tool), `curvefig help COMMAND`,
** and `curvefig help language` (the figure-language reference, generated
** from docs/language.md at build time).
*/
#include <stdio.h>
#include <string.h>

#include "checks.h"
#include "curvefig/label.h"
#include "help.h"
#include "helpers.h"
#include "language-text.h"   /* generated from docs/language.md */

static const char *const overview[] = {
    "usage: curvefig COMMAND [OPTIONS] SCRIPT.lua\n",
    "\n",
    "Figure scripts (Lua 5.4) describe lecture figures of Bezier curves,\n",
    "B-splines and NURBS; curvefig runs them in a sandbox and writes the files.\n",
    "\n",
    "Commands:\n",
    "  render SCRIPT.lua   write every figure the script defines\n",
    "  run SCRIPT.lua      run the script for what it prints (computations)\n",
    "  list SCRIPT.lua     print the names of the figures the script defines\n",
    "                      (one per line; the script's own prints go to stderr)\n",
    "  check SCRIPT.lua [--json] [--min-de N]\n",
    "                      name two elements of a figure whose colours\n",
    "                      protanopia, deuteranopia, tritanopia or greyscale\n",
    "                      print bring closer than a CIEDE2000 of N (default\n",
    "                      10); --json: as JSON on stdout; exit 1 when some\n",
    "                      do (docs/accessibility.md)\n",
    "  live SCRIPT.lua [--port N]\n",
    "                      serve the script's figures with their sliders and\n",
    "                      draggable points on 127.0.0.1 (docs/interactive.md)\n",
    "  gallery -o INDEX.html MANIFEST...\n",
    "                      write an HTML page showing the figures listed in\n",
    "                      render manifests (see --manifest), in that order\n",
    "  compare A B         compare two images (PNG or SVG) pixel by pixel\n",
    "  test SCRIPT... | DIR --references REF [--update]\n",
    "                      check every figure against its reference image\n",
    "  help [TOPIC]        this text; TOPIC: render, run, list, check,\n",
    "                      gallery, compare, test, live, language (the figure\n",
    "                      language reference), labels (every command\n",
    "                      of labels)\n",
    "  --version           print the version\n",
    "\n",
    "Options of render:\n",
    "  -o, --output DIR    directory for the files (created; default .)\n",
    "  -f, --formats LIST  comma-separated: svg, pdf, png, ps, eps, pgf (a\n",
    "                      pgfpicture for LaTeX, labels set by TeX), html\n",
    "                      (a self-contained page whose sliders and points\n",
    "                      work in the browser), or all (every one but\n",
    "                      html; default svg,pdf,png)\n",
    "  --dpi N             PNG resolution, 1..2400 (default 150)\n",
    "  --width L, --height L  every figure's page over the script's, any\n",
    "                      unit (12cm, 324texpt; docs/latex.md gives\n",
    "                      \\linewidth); one alone keeps the proportions\n",
    "  --seed N            math.random's seed (default 0: a script renders\n",
    "                      the same every time)\n",
    "  --only NAME[,NAME]  render only these figures (each must exist)\n",
    "  --tight             crop every page to its ink box (a figure with\n",
    "                      page = \"fixed\" too; the others always are)\n",
    "  --font FAMILY       the labels' family for every figure: serif\n",
    "                      (Latin Modern), sans (Latin Modern Sans, beamer's\n",
    "                      mathematics) or a font list; over theme{} calls\n",
    "  --font-size SIZE    the labels' size, TeX points (11) or with a unit\n",
    "                      (11bp, 4mm); tick labels scale with it\n",
    "  --theme NAME        article (serif, 10 pt) or beamer (sans, 11 pt)\n",
    "  --background B      auto (PNG white, other formats transparent;\n",
    "                      default), none, or a colour for every format\n",
    "  --steps             a figure with overlay steps (visible = \"2-\")\n",
    "                      also as NAME-K.EXT, step K alone, in every format\n",
    "                      (PNG always; NAME.pdf and .ps have a page per\n",
    "                      step, NAME.svg is animated, NAME.png and .eps\n",
    "                      show the last step)\n",
    "  --no-labels         leave out every label, tick and axis label (the\n",
    "                      label-free layer of the pixel tests)\n",
    "  --manifest FILE     also write FILE: one line per figure written,\n",
    "                      NAME<TAB>FORMATS<TAB>CAPTION<TAB>SCRIPT<TAB>ALT\n",
    "                      <TAB>DESCRIPTION (for `gallery`: it shows the\n",
    "                      script's source and the figure's alt text)\n",
    "  -v, --verbose       print the name of every file written\n",
    "Animations (render; docs/animations.md):\n",
    "  --sweep NAME=FROM:TO  move slider NAME from FROM to TO over the\n",
    "                      frames (repeat it: the sliders move together);\n",
    "                      -f svg is then one animated SVG, pdf a page per\n",
    "                      frame (the \\animategraphics line for beamer is\n",
    "                      printed), and gif, apng, mp4, webm (ffmpeg) the\n",
    "                      formats of animations (default svg,pdf,gif)\n",
    "  --frames N          the number of frames (default fps x seconds)\n",
    "  --fps F, --seconds S  frame rate (default 25) and length (default 4)\n",
    "  --ease linear|in-out  how the sliders move (default linear)\n",
    "  --bounce            there and back (the loop ends where it starts)\n",
    "  --animate           animate as the script's animate{} says, or a\n",
    "                      figure's overlay steps one a frame (also what\n",
    "                      -f gif, apng, mp4 or webm alone do)\n",
    "  --step-seconds S    an overlay step's time on screen (default 1.5)\n",
    "  --workers N         processes drawing the frames (default: cores)\n",
    "  --prefix P          write P + NAME instead of NAME (and so in the\n",
    "                      manifest)\n",
    "Options of list:\n",
    "  -l, --long          print NAME<TAB>CAPTION\n",
    "Options of gallery:\n",
    "  -o FILE             the page to write (default index.html); the\n",
    "                      figures' files are linked relative to it, the\n",
    "                      scripts read relative to the current directory;\n",
    "                      a manifest line it cannot read is an error\n",
    "                      naming the file and line, and -o may not be a\n",
    "                      manifest\n",
    "  --title TEXT        the page title\n",
    "Limits (render, run, list, check; live: of every run):\n",
    "  --max-memory MIB    memory a script may use (default 256)\n",
    "  --max-instructions N  Lua instructions a script may run (default 5e8;\n",
    "                      every 16 bytes it allocates count as one)\n",
    "  --timeout S         wall-clock seconds for the whole command (default\n",
    "                      120; catches time spent inside one library call);\n",
    "                      with -f html also the limit of a run in the page\n",
    "\n",
    "Files: a figure named NAME is written as DIR/NAME.svg, NAME.pdf, ...;\n",
    "each file is written under a temporary name and renamed, so a failed\n",
    "render never leaves a broken file.  Output is byte-for-byte the same on\n",
    "every run (PDF dates come from SOURCE_DATE_EPOCH, or none).\n",
    "\n",
    "Exit status: 0 success; 1 the script failed (its file, line and message\n",
    "are printed), a figure could not be drawn, or a file could not be\n",
    "written; 2 usage error (unknown command or option, bad value, no such\n",
    "figure for --only, a script that cannot be read).\n",
    "\n",
    "The sandbox: base library (no dofile, loadfile, require; load accepts\n",
    "text chunks only; setmetatable refuses __gc), math, string (no\n",
    "string.dump), table, utf8.  No io, os, package, debug or coroutine.\n",
    "The steps of a pattern search (string.find, match, gmatch, gsub) count\n",
    "as instructions.  A script that exceeds a limit stops with \"script\n",
    "exceeded the memory limit of N MiB\" or \"script exceeded the\n",
    "instruction limit of N instructions\"; pcall cannot catch these.\n",
    "\n",
    "Example:\n",
    "  curvefig render figures/sir.lua -o build/figures -f svg,pdf\n",
    "  curvefig help language\n",
    NULL,
};

static const char *const labels_head[] = {
    "The commands of labels (curvefig's TeX-like syntax, valid TeX too:\n",
    "docs/latex.md).  A label without $ is all mathematics; with $, the\n",
    "text outside $...$ is text.  Also: x_i x^{n} scripts, ' a prime, { }\n",
    "groups, any UTF-8 text (letters outside ASCII upright).\n",
    "\n",
    NULL,
};

static void
put_command(const char *kind, const char *name, const char *what,
            void *ctx)
{
    (void)ctx;
    printf("  %-10s \\%-14s %s\n", kind, name, what);
}

static const char *const commands[] = { "render", "run", "list", "check",
                                        "gallery", NULL };

static void
put_lines(const char *const *lines)
{
    for (; *lines != NULL; lines++)
        fputs(*lines, stdout);
}

int
cf__tool_help(const char *topic)
{
    if (topic == NULL) {
        put_lines(overview);
        return 0;
    }
    if (cf__tool_checks_help(topic) == 0)
        return 0;
    if (strcmp(topic, "live") == 0) {
        /* the help is the live program's own */
        static char prog[] = "curvefig", live[] = "live", help[] = "--help";
        char *argv[] = { prog, live, help, NULL };
        fflush(stdout);
        return cf__tool_run_helper(CF__TOOL_LIVE_HELPER, 3, argv);
    }
    if (strcmp(topic, "language") == 0) {
        put_lines(language);
        return 0;
    }
    if (strcmp(topic, "labels") == 0) {
        put_lines(labels_head);
        cf_label_each_command(put_command, NULL);
        return 0;
    }
    for (int i = 0; commands[i] != NULL; i++) {
        if (strcmp(topic, commands[i]) == 0) {
            put_lines(overview);
            return 0;
        }
    }
    fprintf(stderr, "curvefig: no help on '%s'; topics: render, run, list, "
            "check, gallery, compare, test, live, language, labels\n", topic);
    return 2;
}
