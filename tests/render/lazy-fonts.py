#!/usr/bin/env python3
"""fontconfig and FreeType are opened at their first call, not at start;
HarfBuzz only for a label the renderer's own shaper hands on; no font
library at all for a labelled PDF or SVG in the tool's own configuration.

    lazy-fonts.py CURVEFIG

A `curvefig` whose fontconfig and FreeType functions are trampolines
(render/tool/lazy.c) is linked without them: a figure without labels is
rendered without loading them or what they bring (expat, libpng, brotli),
as the loader reports the files it loads (LD_DEBUG=files); a figure with
a label loads them under another configuration (FONTCONFIG_FILE), its
PNG loads FreeType in any, and its PDF embeds its font; `--version`
(which builds the font configuration) works.  Labels whose items are all simple
(render/fontfile/shape.h: "$P_0$", "abc", "$x^2$ and text", Greek,
Cyrillic, digits, ligatures, kerning pairs) are shaped by the renderer's
own shaper: a figure of them renders in SVG and PDF without loading
libharfbuzz, GLib, graphite2 or PCRE2 (render/backends/hb-lazy.c); a
label with a combining mark, which that shaper hands on, loads HarfBuzz
and renders.  When the tool uses its own font configuration (render/tool/fonts.c,
`--version`), it chooses the faces itself (render/backends/font-match.h)
from its fonts' metadata cache: a label, and a labelled shipped figure
(markova-2.17, PDF and SVG), load no font library at all (libfontconfig,
libexpat, libfreetype, libpng, brotli), with the cache made by the first
run (a fresh HOME) and read by the next, whose PDF is the same; a
label's PNG, drawn through cairo, loads FreeType.  The same figure rendered to PDF and to SVG
calls no FreeType function: its glyphs' outlines and ink extents are read
from the font files (render/backends/font-outlines.h), so the tool's
trampolines never resolve FreeType's glyph functions (LD_DEBUG=bindings:
the trampoline's dlsym is a second binding of the symbol within
libfreetype, after the library's own relocation); to PNG it does (the
check sees them).  Skipped (77) when the program is linked with the
libraries (render/tool/meson.build: not x86-64).
"""
import os
import subprocess
import sys
import tempfile

PLAIN = """local f = figure{ name = "plain", width = "3cm", height = "2cm" }
f:polyline({ {0, 0}, {1, 1}, {2, 0} })
"""
LABEL = PLAIN.replace('"plain"', '"label"') + \
    'f:label({1, 1}, "$x^2$ and text", { anchor = "n" })\n'
FONT_LIBRARIES = ("libfontconfig", "libfreetype", "libexpat", "libpng",
                  "libbrotli")
SIMPLE = PLAIN.replace('"plain"', '"simple"') + "".join(
    'f:label({%d, 1}, "%s", { anchor = "n" })\n' % (i, text)
    for i, text in enumerate([
        "$P_0$", "abc", "$x^2$ and text", "αβγ δ", "Привет, мир",
        "0123 (x + y)", "fine office", "AV To"]))
MARK = PLAIN.replace('"plain"', '"mark"') + \
    'f:label({1, 1}, "e\\u{301}t\\u{E9}", { anchor = "n" })\n'
HARFBUZZ = ("libharfbuzz", "libglib-2.0", "libgraphite2", "libpcre2")


SHIPPED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                       "..", "figures", "markova-2.17.lua")


def loaded(tool, script, out, fmt="pdf", home=None):
    """Render script (to PDF); the objects the loader loaded."""
    env = dict(os.environ, LD_DEBUG="files")
    if home is not None:
        env["HOME"] = home
        env.pop("XDG_CACHE_HOME", None)
    run = subprocess.run([tool, "render", script, "-o", out, "-f", fmt],
                         env=env, capture_output=True, text=True)
    if run.returncode != 0:
        sys.stderr.write(run.stderr[-2000:])
        raise RuntimeError("the render of %s failed (status %d)"
                           % (script, run.returncode))
    return sorted({os.path.basename(line.split("file=")[1].split()[0])
                   for line in run.stderr.splitlines() if "file=" in line})


FREETYPE_GLYPHS = ("FT_Init_FreeType", "FT_New_Face", "FT_Load_Glyph",
                   "FT_Set_Char_Size")


def freetype_resolved(tool, script, out, fmt):
    """The FreeType glyph functions the tool's trampolines resolved."""
    env = dict(os.environ, LD_DEBUG="bindings")
    run = subprocess.run([tool, "render", script, "-o", out, "-f", fmt],
                         env=env, capture_output=True, text=True,
                         cwd=os.path.dirname(script))
    if run.returncode != 0:
        sys.stderr.write(run.stderr[-2000:])
        raise RuntimeError("the render of %s failed (status %d)"
                           % (script, run.returncode))
    count = {}
    for line in run.stderr.splitlines():
        if "libfreetype.so" not in line.split(" to ")[0]:
            continue
        for name in FREETYPE_GLYPHS:
            if line.endswith("`%s'" % name):
                count[name] = count.get(name, 0) + 1
    return sorted(name for name, n in count.items() if n >= 2)


def shipped_failures(tool, tmp):
    """What the shipped labelled figure's renders find wrong."""
    failures = []
    here = os.path.dirname(os.path.abspath(__file__))
    script = os.path.join(here, "..", "..", "figures", "markova-2.17.lua")
    for fmt in ("pdf", "svg"):
        called = freetype_resolved(tool, script, tmp, fmt)
        if called:
            failures.append("markova-2.17 (%s) called FreeType: %s"
                            % (fmt, ", ".join(called)))
    if not freetype_resolved(tool, script, tmp, "png"):
        failures.append("markova-2.17's PNG called no FreeType function: "
                        "the check sees nothing")
    return failures


def harfbuzz_failures(tool, tmp):
    """What the HarfBuzz half of the test finds wrong."""
    failures = []
    for name, text in (("simple", SIMPLE), ("mark", MARK)):
        with open(os.path.join(tmp, name + ".lua"), "w") as f:
            f.write(text)
    for fmt in ("svg", "pdf"):
        objs = loaded(tool, os.path.join(tmp, "simple.lua"), tmp, fmt)
        early = [o for o in objs if o.startswith(HARFBUZZ)]
        if early:
            failures.append("simple labels (%s) loaded %s"
                            % (fmt, ", ".join(early)))
        # the tool's own faces and outlines: no font library at all; under
        # another configuration fontconfig (which brings FreeType)
        if own_configuration(tool):
            fonts = [o for o in objs if o.startswith(FONT_LIBRARIES)]
            if fonts:
                failures.append("simple labels (%s) loaded %s"
                                % (fmt, ", ".join(fonts)))
        elif not any(o.startswith("libfontconfig") for o in objs):
            failures.append("simple labels (%s) did not load fontconfig"
                            % fmt)
    objs = loaded(tool, os.path.join(tmp, "mark.lua"), tmp, "svg")
    if not any(o.startswith("libharfbuzz") for o in objs):
        failures.append("a combining mark did not load HarfBuzz")
    with open(os.path.join(tmp, "mark.svg"), "rb") as f:
        if b"<svg" not in f.read():
            failures.append("the label with a mark did not render")
    return failures


def own_configuration(tool):
    """Whether the tool uses its own font configuration here."""
    env = dict(os.environ)
    env.pop("FONTCONFIG_FILE", None)
    env.pop("FONTCONFIG_PATH", None)
    run = subprocess.run([tool, "--version"], capture_output=True,
                         text=True, env=env)
    return "curvefig's configuration" in run.stdout and \
        not os.environ.get("FONTCONFIG_FILE") and \
        not os.environ.get("FONTCONFIG_PATH")


def own_failures(tool, tmp, label):
    """What the test of the tool's own faces finds wrong."""
    failures = []
    early = [o for o in label if o.startswith(FONT_LIBRARIES)]
    if early:
        failures.append("a label in the tool's own configuration loaded %s"
                        % ", ".join(early))
    home = os.path.join(tmp, "home")
    os.mkdir(home)
    pdfs = []
    for run in ("first", "cached"):
        for fmt in ("pdf", "svg"):
            out = os.path.join(tmp, run)
            os.makedirs(out, exist_ok=True)
            objs = loaded(tool, SHIPPED, out, fmt, home)
            early = [o for o in objs if o.startswith(FONT_LIBRARIES)]
            if early:
                failures.append("markova-2.17 (%s, %s run) loaded %s"
                                % (fmt, run, ", ".join(early)))
        with open(os.path.join(tmp, run, "markova-2.17.pdf"), "rb") as f:
            pdfs.append(f.read())
    cache = os.path.join(home, ".cache", "curvefig", "faces-2.cache")
    if not os.path.isfile(cache):
        failures.append("no cache was written at %s" % cache)
    if len(pdfs) == 2 and pdfs[0] != pdfs[1]:
        failures.append("the PDF made with the cache differs")
    return failures


def main(argv):
    tool = os.path.abspath(argv[1])
    # the libraries the loader loads with the program (ldd)
    linked = subprocess.run(["ldd", tool], capture_output=True, text=True,
                            check=True).stdout.split()
    if any(word.startswith("libfontconfig") for word in linked):
        print("%s is linked with fontconfig: nothing to check" % tool)
        return 77
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in (("plain", PLAIN), ("label", LABEL)):
            with open(os.path.join(tmp, name + ".lua"), "w") as f:
                f.write(text)
        plain = loaded(tool, os.path.join(tmp, "plain.lua"), tmp)
        early = [o for o in plain if o.startswith(FONT_LIBRARIES)]
        if early:
            failures.append("a figure without labels loaded %s"
                            % ", ".join(early))
        own = own_configuration(tool)
        label = loaded(tool, os.path.join(tmp, "label.lua"), tmp)
        if own:
            # a PNG draws its glyphs through cairo: FreeType is loaded
            # there (the check sees a library when one is loaded)
            png = loaded(tool, os.path.join(tmp, "label.lua"), tmp, "png")
            if not any(o.startswith("libfreetype") for o in png):
                failures.append("a label's PNG did not load libfreetype")
        else:
            for lib in ("libfontconfig", "libfreetype"):
                if not any(o.startswith(lib) for o in label):
                    failures.append("a label did not load %s" % lib)
        if own:
            failures += own_failures(tool, tmp, label)
        with open(os.path.join(tmp, "label.pdf"), "rb") as f:
            if b"/FontFile" not in f.read():
                failures.append("the label's PDF embeds no font")
        if not any(word.startswith("libharfbuzz") for word in linked):
            failures += harfbuzz_failures(tool, tmp)
        failures += shipped_failures(tool, tmp)
    version = subprocess.run([tool, "--version"], capture_output=True,
                             text=True)
    if version.returncode != 0 or "fonts:" not in version.stdout:
        failures.append("--version failed: %r" % (version.stdout +
                                                   version.stderr))
    for f in failures:
        print("FAIL: " + f)
    if not failures:
        print("fonts opened on the first label: %d objects without labels, "
              "%d with; HarfBuzz only for a combining mark; no font "
              "library for a labelled PDF or SVG in the tool's own "
              "configuration"
              % (len(plain), len(label)))
    return 1 if failures else 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except RuntimeError as e:
        print("FAIL: %s" % e)
        sys.exit(1)
