#!/usr/bin/env python3
"""Every shipped figure's PDF, rasterised by poppler, is its PNG.

    pdf-raster.py CURVEFIG FIGURES_DIR

The PDF is written by curvefig's own PDF writer
(render/backends/backend-pdfw.c), the PNG by cairo: each figure of every
script in FIGURES_DIR is rendered as both at 72 dpi, each page of the PDF
(one per overlay step) rasterised by `pdftoppm -r 72` and compared with
the PNG of that step (NAME-K.png, or NAME.png for a one-page PDF) by
`curvefig compare`: pixels whose colour differs by more than its
threshold (YIQ 0.1, about 26 grey levels) and that anti-aliasing does not
explain count as bad.

The tolerance: at most 2 % of a page's pixels, and 0.5 % of all pages'
together.  The two renderers differ where they may: poppler and cairo
anti-alias edges their own way (forgiven by the comparator), poppler
dashes a curve along its own flattening, so that dash ends along a
dashed curve move by a pixel (the most of the difference: cairo's own
PDFs of the same figures, the PDF output before this writer, differ
from its PNGs by up to 1.6 % of a page (example-legend), 26 of 116
pages by more than 0.5 %), labels are drawn from the same outlines by
different rasterisers, and the PDF's numbers are rounded to 1/1000 bp
and colours to 1e-4.  A missing element, a wrong colour, opacity, clip
or mesh covers more than 2 % of any figure.  Skipped (77) without
pdftoppm.
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

MAX_PAGE = 0.02
MAX_ALL = 0.005
COUNTS = re.compile(r'(\d[\d,]*) of (\d[\d,]*) pixels differ'
                    r'|the (\d[\d,]*) pixels are identical'
                    r'|pixels of (\d[\d,]*) differ by anti-aliasing only')


def main(argv):
    tool, figdir = os.path.abspath(argv[1]), argv[2]
    if shutil.which('pdftoppm') is None:
        print('pdftoppm missing: skipped')
        return 77
    bad, pages, all_bad, all_px, worst = [], 0, 0, 0, (0, '')
    with tempfile.TemporaryDirectory() as tmp:
        for script in sorted(glob.glob(os.path.join(figdir, '**', '*.lua'),
                                       recursive=True)):
            out = os.path.join(tmp, os.path.relpath(script, figdir)[:-4])
            r = subprocess.run([tool, 'render', script, '-f', 'pdf,png',
                                '--dpi', '72', '-o', out],
                               capture_output=True, text=True)
            if r.returncode != 0:
                bad.append('%s: render failed: %s' % (script, r.stderr))
                continue
            for pdf in sorted(glob.glob(os.path.join(out, '*.pdf'))):
                name = pdf[:-4]
                info = subprocess.run(['pdfinfo', pdf], capture_output=True,
                                      text=True).stdout
                n = int(re.search(r'Pages:\s+(\d+)', info).group(1))
                for k in range(1, n + 1):
                    png = name + ('-%d.png' % k if n > 1 else '.png')
                    ras = '%s-pdf-%d' % (name, k)
                    subprocess.run(['pdftoppm', '-r', '72', '-png',
                                    '-singlefile', '-f', str(k), '-l',
                                    str(k), pdf, ras], check=True)
                    c = subprocess.run([tool, 'compare', ras + '.png', png,
                                        '--max-bad', '100%'],
                                       capture_output=True, text=True)
                    pages += 1
                    m = COUNTS.search(c.stdout)
                    what = '%s page %d' % (os.path.basename(pdf), k)
                    if c.returncode != 0 or m is None:
                        bad.append('%s: %s' % (what, c.stdout + c.stderr))
                        continue
                    n_bad = int((m.group(1) or '0').replace(',', ''))
                    n_px = int((m.group(2) or m.group(3) or m.group(4))
                               .replace(',', ''))
                    all_bad += n_bad
                    all_px += n_px
                    worst = max(worst, (n_bad / n_px, what))
                    if n_bad > MAX_PAGE * n_px:
                        bad.append('%s: %s' % (what, c.stdout))
    for b in bad:
        print('FAIL', b)
    share = all_bad / all_px if all_px else 1
    print('%d pages compared, %d differ beyond %g %%; all pages: %.3f %% of '
          'pixels differ (at most %g %%); the most: %.3f %% (%s)'
          % (pages, len(bad), 100 * MAX_PAGE, 100 * share, 100 * MAX_ALL,
             100 * worst[0], worst[1]))
    return 1 if bad or pages == 0 or share > MAX_ALL else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
