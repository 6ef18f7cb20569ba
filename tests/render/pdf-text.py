#!/usr/bin/env python3
"""The PDF writer's labels are text in embedded subset fonts.

    pdf-text.py CURVEFIG FIGURES_DIR

- `pdftotext` of markova-2.17 gives its labels P0 ... P7 (the P as the
  mathematical italic capital it is set in, U+1D443: compared after NFKC);
  of lecture5-conics its Russian label; of a script here, its Chinese,
  Russian and Latin labels (one with a halo, one with a fraction);
- `pdffonts` lists every font of those files embedded and subset, with a
  ToUnicode map, as CID Type 0C (CFF) or CID TrueType, among them a
  Noto CJK face for the Chinese when fontconfig has one;
- a label with a character no font has (pango draws a box) comes out as
  its outlines (not in the text), and the script's PDF rasterised by pdftoppm
  is its PNG within 2 % of the pixels (see pdf-raster.py).
Skipped (77) without poppler's tools.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unicodedata

SCRIPT = r"""local f = figure{ name = "scripts", width = "6cm", height = "3cm",
                   background = "#ffffff" }
f:polyline({ {0, 0}, {1, 1}, {2, 0}, {3, 1} }, { width = 3 })
f:label({0.5, 0.5}, "曲线 $x^2$ кривая", { halo = 2 })
f:label({2, 0.2}, "$\\frac{1}{2}$ of it", { anchor = "s" })
f:label({2.5, 0.9}, "box \u{10FFFD} here", { anchor = "n" })
"""

fails = []


def check(cond, what):
    if not cond:
        fails.append(what)


def text_of(pdf):
    r = subprocess.run(['pdftotext', pdf, '-'], capture_output=True,
                       text=True)
    check(r.returncode == 0, 'pdftotext reads %s: %s' % (pdf, r.stderr))
    return unicodedata.normalize('NFKC', r.stdout)


def fonts_of(pdf):
    r = subprocess.run(['pdffonts', pdf], capture_output=True, text=True)
    check(r.returncode == 0, 'pdffonts reads %s' % pdf)
    rows = r.stdout.splitlines()[2:]
    check(len(rows) > 0, '%s has fonts' % pdf)
    for row in rows:
        m = re.match(r'(\S+)\s+(CID Type 0C|CID TrueType)\s+Identity-H\s+'
                     r'(yes|no)\s+(yes|no)\s+(yes|no)', row)
        check(m is not None and m.group(3) == 'yes' and m.group(4) == 'yes'
              and m.group(5) == 'yes' and re.match(r'[A-Z]{6}\+',
                                                   m.group(1)),
              '%s: embedded, subset, ToUnicode, CID font: %r' % (pdf, row))
    return rows


def render(tool, script, out, formats='pdf', extra=()):
    subprocess.run([tool, 'render', script, '-f', formats, '-o', out]
                   + list(extra), check=True, capture_output=True)


def main(argv):
    tool, figdir = os.path.abspath(argv[1]), argv[2]
    for t in ('pdftotext', 'pdffonts', 'pdftoppm'):
        if shutil.which(t) is None:
            print(t + ' missing: skipped')
            return 77
    with tempfile.TemporaryDirectory() as tmp:
        render(tool, os.path.join(figdir, 'markova-2.17.lua'), tmp, 'pdf',
               ['--only', 'markova-2.17'])
        pdf = os.path.join(tmp, 'markova-2.17.pdf')
        words = text_of(pdf).split()
        for k in range(8):
            check('P%d' % k in words, 'markova-2.17: P%d in its text: %r'
                  % (k, words))
        fonts_of(pdf)
        render(tool, os.path.join(figdir, 'lecture5-conics.lua'), tmp)
        pdf = os.path.join(tmp, 'lecture5-conics.pdf')
        check('дуга эллипса' in text_of(pdf),
              'lecture5-conics: its Russian label in its text')
        rows = fonts_of(pdf)
        check(any('CID TrueType' in r for r in rows),
              'lecture5-conics: a TrueType face (CMU Serif)')
        script = os.path.join(tmp, 'scripts.lua')
        with open(script, 'w') as f:
            f.write(SCRIPT)
        render(tool, script, tmp, 'pdf,png', ['--dpi', '72'])
        pdf = os.path.join(tmp, 'scripts.pdf')
        text = text_of(pdf)
        for w in ('曲线', 'x2', 'кривая', 'of it'):
            check(w in text, 'scripts: %r in its text: %r' % (w, text))
        check('box' not in text, 'scripts: the label with a missing glyph '
              'is its outlines, not text')
        rows = fonts_of(pdf)
        cjk = subprocess.run(['fc-match', '-f', '%{family}', ':lang=zh-cn'],
                             capture_output=True, text=True).stdout
        if 'CJK' in cjk:
            check(any('CJK' in r for r in rows),
                  'scripts: a Noto CJK face: %r' % rows)
        subprocess.run(['pdftoppm', '-r', '72', '-png', '-singlefile', pdf,
                        os.path.join(tmp, 'scripts-pdf')], check=True)
        c = subprocess.run([tool, 'compare',
                            os.path.join(tmp, 'scripts-pdf.png'),
                            os.path.join(tmp, 'scripts.png'),
                            '--max-bad', '2%'], capture_output=True,
                           text=True)
        check(c.returncode == 0, 'scripts: the PDF rasterised is its PNG: '
              + c.stdout)
    for f in fails:
        print('FAIL', f)
    return 1 if fails else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
