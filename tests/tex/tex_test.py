#!/usr/bin/env python3
"""Figures in real TeX documents (suite 'tex').

usage: tex_test.py CHECK CURVEFIG SOURCE_ROOT WORK_DIR

CHECK is one of:
  docs     every ```sh and ```latex snippet of docs/latex.md runs or
           compiles (a ```latex block may name its engine after the
           language: ```latex xelatex)
  article  an 11 pt article with figures as PGF (page 1) and as PDF
           (page 2): pdflatex compiles it; page 1 uses only TeX's own
           Type 1 fonts (Computer Modern), page 2 curvefig's embedded
           ones; two PDFs on a page warn about page groups unless
           \\pdfsuppresswarningpagegroup=1
  beamer   a beamer deck with PGF and PDF figures: the PGF labels are in
           beamer's sans fonts
  engines  the PGF figures compile with xelatex and lualatex too
  pixels   every shipped figure without labels: the PGF compiled by
           pdflatex and the cairo PDF, rasterised by pdftoppm at the same
           resolution, compare equal (curvefig compare)
  figures  every shipped figure, labels and all, as PGF in one pdflatex
           document; the PGF is the same on a second run
  labels   labels in every part of the label syntax compile with
           pdflatex (OT1 Computer Modern, and T1 Latin Modern with
           amsmath); labels in scripts pdflatex cannot set are outlines
  commands every command `curvefig help labels` lists parses (curvefig
           renders it) and is valid TeX (pdflatex, with and without
           amsmath)
  slides   a beamer deck on a coloured background with figures rendered
           --theme beamer: PGF frames in TeX's sans fonts, PDF frames in
           curvefig's Latin Modern Sans; a transparent PDF figure shows
           the frame's colour around its ink (pixels), a --background
           white one a white box

Exit 77 (skipped) when pdflatex is not installed.
"""
import os
import re
import shutil
import subprocess
import sys

CHECK, TOOL, ROOT, WORK = sys.argv[1:5]
TOOL, ROOT, WORK = (os.path.abspath(p) for p in (TOOL, ROOT, WORK))
FIGURES = os.path.join(ROOT, "figures")
ENV = dict(os.environ, SOURCE_DATE_EPOCH="0", TEXINPUTS=".:" + WORK + ":")


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def need(*progs):
    for p in progs:
        if shutil.which(p) is None:
            print("SKIP: %s not installed (the tex suite needs TeX Live: "
                  "pdflatex, xelatex, lualatex, beamer, pgf, lmodern, and "
                  "poppler-utils)" % p)
            sys.exit(77)


def run(cmd, cwd=WORK, ok=(0,)):
    r = subprocess.run(cmd, cwd=cwd, env=ENV, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, errors="replace")
    if r.returncode not in ok:
        fail("%s: exit %d\n%s" % (" ".join(cmd), r.returncode, r.stdout[-3000:]))
    return r.stdout


def render(script, formats, extra=(), out=WORK):
    run([TOOL, "render", os.path.join(FIGURES, script), "-o", out,
         "-f", formats] + list(extra))


def tex(name, body, engine="pdflatex"):
    """Compile WORK/name.tex; the log text."""
    with open(os.path.join(WORK, name + ".tex"), "w") as f:
        f.write(body)
    run([engine, "-interaction=nonstopmode", "-halt-on-error",
         name + ".tex"])
    with open(os.path.join(WORK, name + ".log"), errors="replace") as f:
        log = f.read()
    for bad in ("Missing character", "Undefined control sequence",
                "LaTeX Error"):
        if bad in log:
            fail("%s (%s): %s in the log" % (name, engine, bad))
    return log


def fonts(pdf, first=None, last=None):
    """(name, type) of every font of pdf (pages first..last)."""
    cmd = ["pdffonts"]
    if first is not None:
        cmd += ["-f", str(first), "-l", str(last)]
    lines = run(cmd + [pdf]).splitlines()[2:]
    out = []
    for ln in lines:
        m = re.match(r"(\S+)\s+(.+?)\s{2,}", ln)
        if m:
            out.append((m.group(1).split("+")[-1], m.group(2).strip()))
    return out


def pgf_size(path):
    with open(path) as f:
        head = f.readline()
    m = re.search(r"picture, ([0-9.]+) x ([0-9.]+) bp", head)
    if m is None:
        fail(path + ": no size in the first line")
    return float(m.group(1)), float(m.group(2))


def doc(cls, body, pre=""):
    return ("\\documentclass%s\n\\usepackage{pgf}\n\\usepackage{graphicx}\n"
            "%s\\begin{document}\n%s\n\\end{document}\n" % (cls, pre, body))


def figures():
    return sorted(f for f in os.listdir(FIGURES) if f.endswith(".lua"))


# ---- the checks ----------------------------------------------------------

def check_docs():
    with open(os.path.join(ROOT, "docs", "latex.md")) as f:
        md = f.read()
    blocks = re.findall(r"^```([^\n]*)\n(.*?)^```", md, re.S | re.M)
    os.makedirs(os.path.join(WORK, "figures"), exist_ok=True)
    for s in figures():
        shutil.copy(os.path.join(FIGURES, s), os.path.join(WORK, "figures"))
    bindir = os.path.join(WORK, "bin")
    os.makedirs(bindir, exist_ok=True)
    link = os.path.join(bindir, "curvefig")
    if not os.path.exists(link):
        os.symlink(TOOL, link)
    ENV["PATH"] = bindir + os.pathsep + ENV["PATH"]
    n_sh = n_tex = 0
    for info, code in blocks:
        words = info.split()
        if not words:
            continue
        if words[0] == "sh":
            run(["sh", "-e", "-c", code])
            n_sh += 1
        elif words[0] == "latex":
            engine = words[1] if len(words) > 1 else "pdflatex"
            need(engine)
            log = tex("snippet%d" % n_tex, code, engine)
            if "pdfsuppresswarningpagegroup=1" in code and "page group" in log:
                fail("snippet %d: the page-group warning is still there"
                     % n_tex)
            n_tex += 1
    if n_sh == 0 or n_tex < 3:
        fail("docs/latex.md: %d sh and %d latex snippets found" % (n_sh, n_tex))
    print("ok: %d sh and %d latex snippets of docs/latex.md" % (n_sh, n_tex))


PGF_FIGS = ("lec05-decasteljau.lua", "markova-basis-all.lua")
# figures that paint translucently (a shaded hull): their PDF pages are
# transparency groups
TRANSLUCENT = ("lec05-convex-hull.lua", "markova-1.1.lua")


def check_article():
    for s in PGF_FIGS:
        render(s, "pgf,pdf")
    render("orazem-curve.lua", "pdf")
    pgf = "\n\n".join("\\noindent\\input{%s.pgf}" % s[:-4] for s in PGF_FIGS)
    pdf = "\n\n".join("\\noindent\\includegraphics{%s.pdf}" % s[:-4]
                      for s in PGF_FIGS + ("orazem-curve.lua",))
    body = "Text in 11 pt, $x_i$.\n\n%s\n\\clearpage\n%s" % (pgf, pdf)
    log = tex("article", doc("[11pt]{article}", body))
    pages = re.search(r"Pages:\s+(\d+)", run(["pdfinfo", "article.pdf"]))
    if pages is None or int(pages.group(1)) < 2:
        fail("article.pdf: expected the PGF and PDF figures on two pages")
    p1 = fonts("article.pdf", 1, 1)
    if not p1 or any(not n.startswith("CM") or t != "Type 1" for n, t in p1):
        fail("page 1 (PGF) fonts are not only TeX's Computer Modern: %s" % p1)
    if not any(n.startswith("CMMI") for n, t in p1):
        fail("page 1: no math italic (CMMI) for the labels: %s" % p1)
    last = int(pages.group(1))
    p2 = fonts("article.pdf", 2, last)
    if not any(not n.startswith("CM") for n, t in p2):
        fail("pages 2..: the PDF figures' own fonts are missing: %s" % p2)
    # the page-group warning: none for opaque figures (their pages carry no
    # transparency group); with two translucent curvefig PDFs on one page,
    # and gone with the one-line fix
    if "page group" in log:
        fail("a page-group warning for opaque figures")
    for s in TRANSLUCENT:
        render(s, "pdf")
    two = "\n\n".join("\\noindent\\includegraphics{%s.pdf}" % s[:-4]
                       for s in TRANSLUCENT)
    log = tex("article-groups", doc("[11pt]{article}", two))
    if "page group" not in log:
        fail("expected pdfTeX's page-group warning for two translucent "
             "PDFs on a page")
    log = tex("article-fixed", doc("[11pt]{article}", two,
                                   "\\pdfsuppresswarningpagegroup=1\n"))
    if "page group" in log:
        fail("\\pdfsuppresswarningpagegroup=1 did not remove the warning")
    print("ok: article; PGF page fonts %s" % sorted(set(n for n, t in p1)))


def check_beamer():
    for s in PGF_FIGS:
        render(s, "pgf,pdf")
    frames = "".join(
        "\\begin{frame}{%s}\n\\centering\\input{%s.pgf}\n\\end{frame}\n"
        % (s[:-4], s[:-4]) for s in PGF_FIGS)
    frames += ("\\begin{frame}{PDF}\n\\centering\\includegraphics"
               "[width=.8\\linewidth]{%s.pdf}\n\\end{frame}\n" % PGF_FIGS[0][:-4])
    pre = "\\setbeamercolor{background canvas}{bg=blue!10}\n"
    tex("deck", "\\documentclass{beamer}\n%s\\begin{document}\n%s"
        "\\end{document}\n" % (pre, frames))
    f = fonts("deck.pdf", 1, len(PGF_FIGS))
    if not f or any(t != "Type 1" for n, t in f):
        fail("PGF frames use fonts that are not TeX's: %s" % f)
    if not any(n.startswith("CMSS") or n.startswith("LMSans") for n, t in f):
        fail("PGF frames: no sans font: %s" % f)
    print("ok: beamer; PGF frame fonts %s" % sorted(set(n for n, t in f)))


def check_engines():
    need("xelatex", "lualatex")
    for s in PGF_FIGS:
        render(s, "pgf")
    body = "\n\n".join("\\noindent\\input{%s.pgf}" % s[:-4] for s in PGF_FIGS)
    for engine in ("xelatex", "lualatex"):
        tex("doc-" + engine, doc("[11pt]{article}", body), engine)
        f = fonts("doc-%s.pdf" % engine)
        if not any("LMMath" in n or n.startswith("LMRoman") or
                   n.startswith("CM") for n, t in f):
            fail("%s: no Latin Modern / Computer Modern font: %s" % (engine, f))
    print("ok: xelatex and lualatex")


def check_pixels():
    need("pdftoppm")
    nl = os.path.join(WORK, "nolabels")
    tight = os.path.join(WORK, "tight")
    for d in (nl, tight):
        os.makedirs(d, exist_ok=True)
    for s in figures():
        render(s, "pdf,pgf", ["--no-labels"], out=nl)
    for s in PGF_FIGS + ("orazem-decasteljau.lua",):
        render(s, "pdf,pgf", ["--no-labels", "--tight"], out=tight)
    # a figure with overlay steps (a PDF of several pages): its PGF outside
    # beamer shows every step at once, which no cairo page does; beamer
    # decks of it are checked by tests/render/beamer-overlay.sh
    figs = [(d, f[:-4]) for d in ("nolabels", "tight")
            for f in sorted(os.listdir(os.path.join(WORK, d)))
            if f.endswith(".pgf") and re.search(
                r"Pages:\s+1\n", run(["pdfinfo", os.path.join(
                    WORK, d, f[:-4] + ".pdf")]))]
    # one page per figure, each page the figure's size (pdfTeX primitives)
    pages = []
    for d, n in figs:
        w, h = pgf_size(os.path.join(WORK, d, n + ".pgf"))
        pages.append("\\pdfpagewidth=%.4fbp \\pdfpageheight=%.4fbp\n"
                     "\\shipout\\hbox{\\input{%s/%s.pgf}}\n" % (w, h, d, n))
    tex("pixels", "\\documentclass{article}\n\\usepackage{pgf}\n"
        "\\hoffset=-1in \\voffset=-1in\n\\begin{document}\n%s"
        "\\end{document}\n" % "".join(pages))
    dpi = "100"
    run(["pdftoppm", "-r", dpi, "-png", "pixels.pdf", "pgf"])
    bad = []
    width = len(str(len(figs)))
    for k, (d, n) in enumerate(figs):
        b = "cairo-%s-%s" % (d, n)
        run(["pdftoppm", "-r", dpi, "-png", "-singlefile",
             os.path.join(WORK, d, n + ".pdf"), b])
        a = "pgf-%0*d.png" % (width, k + 1)
        # poppler rasterises both, so edges anti-alias alike; the PGF's
        # quarter-turn arcs and 4-decimal coordinates move an edge by
        # well under a pixel: the default threshold and anti-aliasing
        # radius, no pixel beyond them
        r = subprocess.run([TOOL, "compare", a, b + ".png", "--diff",
                            "diff-%s-%s.png" % (d, n)], cwd=WORK,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True)
        if r.returncode != 0:
            bad.append("%s/%s: %s" % (d, n, r.stdout.strip().splitlines()[-1]))
    if bad:
        fail("PGF and PDF differ:\n  " + "\n  ".join(bad))
    print("ok: %d figures without labels (%d cropped): PGF pixels = PDF "
          "pixels" % (len(figs), len(figs) - len(figures_in(nl))))


def figures_in(d):
    return [f for f in os.listdir(d) if f.endswith(".pgf")]


def check_figures():
    a = os.path.join(WORK, "a")
    b = os.path.join(WORK, "b")
    for d in (a, b):
        os.makedirs(d, exist_ok=True)
        for s in figures():
            render(s, "pgf", out=d)
    names = sorted(f for f in os.listdir(a) if f.endswith(".pgf"))
    for n in names:
        with open(os.path.join(a, n), "rb") as x, \
                open(os.path.join(b, n), "rb") as y:
            if x.read() != y.read():
                fail(n + ": two runs give different PGF")
    body = "\n".join("\\noindent\\input{a/%s}\\par" % n for n in names)
    tex("figures", doc("[11pt]{article}", body))
    print("ok: %d figures as PGF compile with pdflatex" % len(names))


LABELS = [
    # source, expected to be set by TeX (True) or drawn as outlines
    ("P_0", True), ("B_i^n(t)", True), ("N_{i,p}(u)", True),
    (r"\omega_i \geq 0", True), (r"\alpha\beta\Gamma\Omega\omicron", True),
    ("αβγ ≤ ∞ − x′", True), (r"x \cdot y \times z \pm \infty", True),
    (r"\hat P \bar{x} \vec v \tilde n \dot a \ddot b", True),
    (r"\frac{1}{2} \mathbf{b} \mathrm{d}x \mathit{f} \operatorname{deg}",
     True),
    (r"\text{if } x_1", True), (r"f(t)\,\;\quad\qquad g \! h", True),
    (r"\{a\} \_ \$ \% \# \& \\ \| \deg 90\deg", True),
    ("a # b % c & d ~ e", True),
    ("$the curve$ x(t) = $b_0^3$ č ž é", True),
    (r"$\alpha$ a_b^c <x> |y| ~ # \{\} \\ \deg \hat{e}", True),
    (r"$\frac{a}{b}$ $\mathrm{x}$ \mathbf{bold} \mathit{it}", True),
    ("$ΑΒΕ$ α ≤ č", True), ("w = √2/2 · ∀x ∈ ∅ ⇒ x′″", True),
    ("x^2' + y^{n}′ + z_1'", True), ("a\tb\n\nc", True),
    (r"w = \sqrt{2}/2, \sqrt[3]{x^2+y^2}, \frac14", True),
    (r"\binom{n}{k} \left( \frac{a}{b} \right] \left. x \right\}", True),
    (r"$radius$ \sqrt{\frac{1}{2}}", True), (r"x \in \mathbb{R}", False),
    ("Кривая Безье", False), ("$кривая$ b_0", False), ("贝塞尔曲线", False),
]


def check_labels():
    n = len(LABELS) + 1
    lua = ["local f = figure{ name = 'labels', width = '12cm', "
           "height = '%dcm', window = {0, 10, 0, %d} }" % (n, n)]
    for k, (src, _) in enumerate(LABELS):
        lua.append("f:label({1, %d}, %s, { place = 'e' })"
                   % (len(LABELS) - k, "[==[" + src + "]==]"))
    with open(os.path.join(WORK, "labels.lua"), "w") as f:
        f.write("\n".join(lua) + "\n")
    run([TOOL, "render", "labels.lua", "-o", WORK, "-f", "pgf,pdf"])
    with open(os.path.join(WORK, "labels.pgf")) as f:
        text = f.read()
    groups = text.split("\\begin{pgfscope}% ")[1:]
    if len(groups) != len(LABELS):
        fail("expected %d label groups, found %d" % (len(LABELS), len(groups)))
    for (src, settable), g in zip(LABELS, groups):
        if ("\\pgftext" in g) != settable:
            fail("label %r: %s" % (src, "drawn as outlines" if settable
                                   else "handed to TeX"))
    tex("labels-doc", doc("[11pt]{article}", "\\input{labels.pgf}"))
    # also with T1 fonts, Latin Modern and amsmath's \text
    tex("labels-t1", doc("[11pt]{article}", "\\input{labels.pgf}",
                         "\\usepackage[T1]{fontenc}\n\\usepackage{lmodern}\n"
                         "\\usepackage{amsmath}\n"))
    print("ok: %d labels compile with pdflatex (OT1 and T1)" % len(LABELS))


def help_commands():
    """(kind, name) of every line of `curvefig help labels`."""
    out = run([TOOL, "help", "labels"])
    cmds = re.findall(r"^  (symbol|space|accent|structure)\s+\\(\S+)", out,
                      re.M)
    if len(cmds) < 100:
        fail("curvefig help labels lists %d commands" % len(cmds))
    return cmds


def check_commands():
    labels = []
    for kind, name in help_commands():
        if kind == "structure":
            labels.append("\\%s{A}{B}" % name if name in ("frac", "binom")
                          else "\\%s(A\\right)" % name if name == "left"
                          else "\\%s{A}" % name)
        elif kind == "accent":
            labels.append("\\%s{x}" % name)
        else:
            labels.append("a\\%s b" % name)
    lua = ["local f = figure{ name = 'commands', width = '12cm', "
           "height = '%dcm', window = {0, 4, 0, %d} }"
           % (len(labels) // 4 + 2, len(labels) // 4 + 1)]
    for k, src in enumerate(labels):
        lua.append("f:label({%d, %d}, [==[%s]==], { place = 'e' })"
                   % (k % 4, k // 4, src))
    with open(os.path.join(WORK, "commands.lua"), "w") as f:
        f.write("\n".join(lua) + "\n")
    run([TOOL, "render", "commands.lua", "-o", WORK, "-f", "pgf,pdf"])
    with open(os.path.join(WORK, "commands.pgf")) as f:
        text = f.read()
    # \mathbb needs amssymb: its label is drawn as outlines
    settable = [src for src in labels if "mathbb" not in src]
    if text.count("\\pgftext") != len(settable):
        fail("expected %d labels set by TeX, found %d"
             % (len(settable), text.count("\\pgftext")))
    tex("commands-doc", doc("[11pt]{article}", "\\input{commands.pgf}"))
    tex("commands-ams", doc("[11pt]{article}", "\\input{commands.pgf}",
                            "\\usepackage{amsmath}\n"))
    print("ok: %d listed commands parse and compile (with and without "
          "amsmath)" % len(labels))


def ppm(path):
    """(width, height, bytes) of a binary PPM."""
    with open(path, "rb") as f:
        data = f.read()
    m = re.match(rb"P6\s+(\d+)\s+(\d+)\s+(\d+)\s", data)
    if m is None:
        fail(path + ": not a binary PPM")
    w, h = int(m.group(1)), int(m.group(2))
    return w, h, data[m.end():m.end() + 3 * w * h]


def page_pixels(pdf, page):
    """Pixels of page of pdf at 40 dpi: (count, share of white, share of
    the colour of the top left corner, the frame's)."""
    base = "px-%d" % page
    run(["pdftoppm", "-r", "40", "-f", str(page), "-l", str(page),
         "-singlefile", pdf, base])
    w, h, px = ppm(os.path.join(WORK, base + ".ppm"))
    corner = px[0:3]
    n = w * h
    white = sum(1 for i in range(0, 3 * n, 3)
                if px[i] >= 250 and px[i + 1] >= 250 and px[i + 2] >= 250)
    frame = sum(1 for i in range(0, 3 * n, 3) if px[i:i + 3] == corner)
    return n, white / n, frame / n, tuple(corner)


def check_slides():
    need("pdftoppm")
    figs = ("lec05-decasteljau.lua", "markova-basis-all.lua")
    for s in figs:
        render(s, "pgf,pdf", ["--theme", "beamer"],
               out=os.path.join(WORK, "slides"))
    render(figs[0], "pdf", ["--theme", "beamer", "--background", "white"],
           out=os.path.join(WORK, "white"))
    frames = "".join("\\begin{frame}\n\\centering\\input{slides/%s.pgf}\n"
                     "\\end{frame}\n" % s[:-4] for s in figs)
    frames += "".join("\\begin{frame}\n\\centering\\includegraphics"
                      "{slides/%s.pdf}\n\\end{frame}\n" % s[:-4]
                      for s in figs)
    frames += ("\\begin{frame}\n\\centering\\includegraphics"
               "{white/%s.pdf}\n\\end{frame}\n" % figs[0][:-4])
    pre = "\\setbeamercolor{background canvas}{bg=orange!30}\n"
    tex("slides", "\\documentclass{beamer}\n%s\\begin{document}\n%s"
        "\\end{document}\n" % (pre, frames))
    pgf = fonts("slides.pdf", 1, 2)
    if not pgf or any(t != "Type 1" for n, t in pgf):
        fail("PGF frames use fonts that are not TeX's: %s" % pgf)
    if not any(n.startswith("CMSS") for n, t in pgf):
        fail("PGF frames: not in beamer's sans (CMSS): %s" % pgf)
    pdf = fonts("slides.pdf", 3, 4)
    names = set(n for n, t in pdf)
    if not any(n.startswith("LMSans") for n in names):
        fail("PDF frames: no Latin Modern Sans of --theme beamer: %s" % names)
    if any(n.startswith("LMRoman") for n in names):
        fail("PDF frames: serif Latin Modern in a sans theme: %s" % names)
    # transparent: the frame's colour around the ink, no white box (white
    # only in the halos of labels over lines, well under 2 % of the frame);
    # the same figure with --background white: a white box
    for page in (1, 3):
        n, white, frame, corner = page_pixels("slides.pdf", page)
        if corner[2] > 200 or white > 0.02 or frame < 0.8:
            fail("page %d: %.2f %% white, %.1f %% frame colour %s: the "
                 "figure is not transparent" % (page, 100 * white,
                                                100 * frame, corner))
    n, white5, frame5, _ = page_pixels("slides.pdf", 5)
    if white5 < 0.1:
        fail("page 5 (--background white): only %.2f %% white"
             % (100 * white5))
    print("ok: beamer deck, sans theme on orange!30; PGF fonts %s, PDF "
          "fonts %s; transparent PDF: %.1f %% of the frame its colour, "
          "white PDF: %.1f %% white" % (sorted(set(n for n, t in pgf)),
                                        sorted(names), 100 * frame,
                                        100 * white5))


def main():
    need("pdflatex", "pdffonts", "pdfinfo")
    os.makedirs(WORK, exist_ok=True)
    checks = {"docs": check_docs, "article": check_article,
              "beamer": check_beamer, "engines": check_engines,
              "pixels": check_pixels, "figures": check_figures,
              "labels": check_labels, "commands": check_commands,
              "slides": check_slides}
    if CHECK not in checks:
        fail("unknown check " + CHECK)
    checks[CHECK]()


main()
