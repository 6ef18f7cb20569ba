#!/usr/bin/python3
"""Animations of `curvefig render` (docs/animations.md).

usage: test_anim.py CHECK CURVEFIG SOURCE_DIR

CHECK is one of
  frames   frame k of the animated PDF (pdftoppm) and of the animated SVG
           (the frame's group alone, rsvg-convert) shows the figure at
           slider value k: the pixels of a static render of the script
           whose slider defaults to that value (labels left out on both
           sides: their places follow the stability rule, checked by
           `labels`); the PDF has one page per frame, all of one size; the
           overlay steps animate one step per frame
  union    a figure on a page cropped to its ink whose point moves far:
           every frame the same size, and every frame's static ink inside
           it (nothing clipped: no inked pixel in the frame's margin)
  labels   a label whose point moves 0.3 bp a frame keeps its place
           relative to the point in every frame (its glyph's offset from a
           centred label at the same point never changes), where a static
           render at the last frame's values places it on the other side
  bad      an unknown slider (the nearest name), a range outside the
           slider's [min, max], zero frames, fps <= 0, -f png, nothing to
           animate: each a clear error, and no file left behind
  beamer   the printed \\animategraphics line compiles in a beamer frame
           with pdflatex and the animate package (skipped without them)
  raster   frame k of the GIF and of the APNG (decoded by ffmpeg, an
           independent decoder) shows the figure at slider value k: the
           static PNG at the same dpi, within the GIF's palette (a pixel
           differs when a channel is off by more than 48); the videos are
           read back by tests/render/test_anim_video.c
  browser  the animated SVG plays in headless Chromium: paused at two
           times it shows two frames that differ as the static renders do
           (skipped without chromium, chromedriver or selenium)
Exit 77 (skipped) when a program a check needs is missing.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

SKIP = 77


def check(cond, what):
    if not cond:
        print('FAIL:', what)
        sys.exit(1)


def need(*progs):
    for p in progs:
        if shutil.which(p) is None:
            print('SKIP: no', p)
            sys.exit(SKIP)


def run(args, ok=True, **kw):
    r = subprocess.run(args, capture_output=True, text=True, **kw)
    if ok:
        check(r.returncode == 0, '%s: %s' % (' '.join(args), r.stderr))
    return r


def ppm(path):
    """(width, height, bytes) of a binary PPM."""
    with open(path, 'rb') as f:
        data = f.read()
    parts = data.split(maxsplit=4)
    check(parts[0] == b'P6' and parts[3] == b'255', path + ': not a PPM')
    return int(parts[1]), int(parts[2]), parts[4]


def pdf_page(pdf, page, out, dpi=72):
    run(['pdftoppm', '-r', str(dpi), '-f', str(page), '-l', str(page),
         '-singlefile', pdf, out])
    return ppm(out + '.ppm')


def svg_pixels(svg, out):
    """The SVG's pixels: rsvg-convert's PDF of it through pdftoppm."""
    run(['rsvg-convert', '-f', 'pdf', '-o', out + '.pdf', svg])
    return pdf_page(out + '.pdf', 1, out)


def differing(a, b, step):
    """Pixels of two images of one size whose channels differ by > 2."""
    check(a[0] == b[0] and a[1] == b[1],
          'sizes differ: %dx%d, %dx%d' % (a[0], a[1], b[0], b[1]))
    n = 0
    da, db = a[2], b[2]
    for i in range(0, len(da), step):
        if any(abs(da[i + c] - db[i + c]) > 2 for c in range(step)):
            n += 1
    return n


def with_default(src, dst, name, value):
    """The script src with slider name's default (and no step) set."""
    with open(src, encoding='utf-8') as f:
        text = f.read()
    pat = re.compile(r'(slider\{\s*name = "%s",[^}]*?default = )[-0-9.]+'
                     % re.escape(name), re.S)
    text, n = pat.subn(lambda m: m.group(1) + repr(value), text)
    check(n == 1, 'no slider %s with a default in %s' % (name, src))
    text = re.sub(r',\s*step = [0-9.]+', '', text)
    with open(dst, 'w', encoding='utf-8') as f:
        f.write(text)


def frame_svg(svg, k, dst):
    """The animated SVG with frame k alone shown, its animations gone."""
    with open(svg, encoding='utf-8') as f:
        text = f.read()
    text = re.sub(r'<animate [^>]*/>', '', text)
    text = re.sub(r'<g id="frame-(\d+)" visibility="\w+">',
                  lambda m: '<g id="frame-%s" visibility="%s">'
                  % (m.group(1), 'visible' if int(m.group(1)) == k
                     else 'hidden'), text)
    with open(dst, 'w', encoding='utf-8') as f:
        f.write(text)


def check_frames(tool, src, tmp):
    need('pdftoppm', 'rsvg-convert')
    script = os.path.join(src, 'figures', 'interactive', 'decasteljau.lua')
    values = [0, 0.25, 0.5, 0.75, 1]
    r = run([tool, 'render', script, '--sweep', 't=0:1', '--frames', '5',
             '--no-labels', '-f', 'svg,pdf', '-o', tmp])
    pdf = os.path.join(tmp, 'decasteljau.pdf')
    info = run(['pdfinfo', '-f', '1', '-l', '5', pdf]).stdout
    check('Pages:           5' in info, 'the PDF has 5 pages: ' + info)
    sizes = set(re.findall(r'Page +\d+ size: +([0-9. x]+pts)', info))
    check(len(sizes) == 1, 'every page one size: %s' % sizes)
    check(r.stdout.strip() == '\\animategraphics[loop,autoplay,controls]'
          '{25}{%s}{0}{4}' % os.path.join(tmp, 'decasteljau'),
          'the beamer line: ' + r.stdout)
    for k in (1, 3, 4):
        d = os.path.join(tmp, 'static%d' % k)
        os.mkdir(d)
        s = os.path.join(d, 's.lua')
        with_default(script, s, 't', values[k])
        run([tool, 'render', s, '--no-labels', '-f', 'svg,pdf', '-o', d])
        a = pdf_page(pdf, k + 1, os.path.join(tmp, 'a%d' % k))
        b = pdf_page(os.path.join(d, 'decasteljau.pdf'), 1,
                     os.path.join(d, 'b'))
        n = differing(a, b, 3)
        check(n == 0, 'PDF page %d differs from the static render at t = %g '
              'in %d pixels' % (k + 1, values[k], n))
        frame_svg(os.path.join(tmp, 'decasteljau.svg'), k,
                  os.path.join(tmp, 'f%d.svg' % k))
        a = svg_pixels(os.path.join(tmp, 'f%d.svg' % k),
                       os.path.join(tmp, 'fa%d' % k))
        b = svg_pixels(os.path.join(d, 'decasteljau.svg'),
                       os.path.join(d, 'fb'))
        n = differing(a, b, 3)
        check(n == 0, 'SVG frame %d differs from the static render at t = %g '
              'in %d pixels' % (k, values[k], n))
    # with labels: the first frame (no frame before it) is the static
    # render at t = 0 (the labels placed afresh), every label included
    lab = os.path.join(tmp, 'lab')
    run([tool, 'render', script, '--sweep', 't=0:1', '--frames', '5',
         '-f', 'pdf', '-o', lab])
    d = os.path.join(tmp, 'static0')
    os.mkdir(d)
    with_default(script, os.path.join(d, 's.lua'), 't', 0)
    run([tool, 'render', os.path.join(d, 's.lua'), '-f', 'pdf', '-o', d])
    n = differing(pdf_page(os.path.join(lab, 'decasteljau.pdf'), 1,
                           os.path.join(lab, 'a0')),
                  pdf_page(os.path.join(d, 'decasteljau.pdf'), 1,
                           os.path.join(d, 'b0')), 3)
    check(n == 0, 'the first frame with its labels differs from the static '
          'render at t = 0 in %d pixels' % n)
    # the overlay steps: one step a frame, each the static step's page
    ov = os.path.join(src, 'figures', 'overlay-deboor.lua')
    od = os.path.join(tmp, 'ov')
    run([tool, 'render', ov, '--animate', '--step-seconds', '2', '-f',
         'pdf', '-o', od])
    run([tool, 'render', ov, '--steps', '-f', 'pdf', '-o',
         os.path.join(od, 'st')])
    info = run(['pdfinfo', os.path.join(od, 'overlay-deboor.pdf')]).stdout
    check('Pages:           4' in info, 'one page per step: ' + info)
    for k in (1, 4):
        a = pdf_page(os.path.join(od, 'overlay-deboor.pdf'), k,
                     os.path.join(od, 'a%d' % k))
        b = pdf_page(os.path.join(od, 'st', 'overlay-deboor-%d.pdf' % k), 1,
                     os.path.join(od, 'b%d' % k))
        check(differing(a, b, 3) == 0, 'step %d of the animation is the '
              'static step' % k)


UNION = '''
local a = slider{ name = "a", min = 0, max = 4, default = 0 }
local f = figure{ name = "moving", page = "ink", width = "8cm",
                  height = "6cm", margin = "6bp", window = { -1, 6, -1, 6 } }
f:curve(bezier{ {0, 0}, {1, 2}, {2, 0} }, { color = "blue" })
f:points({ {a, a * a / 4} }, { marker = "dot" })
'''


def check_union(tool, src, tmp):
    need('pdftoppm')
    s = os.path.join(tmp, 'moving.lua')
    with open(s, 'w') as f:
        f.write(UNION)
    run([tool, 'render', s, '--sweep', 'a=0:4', '--frames', '5', '-f', 'pdf',
         '-o', tmp])
    pdf = os.path.join(tmp, 'moving.pdf')
    info = run(['pdfinfo', '-f', '1', '-l', '5', pdf]).stdout
    sizes = set(re.findall(r'Page +\d+ size: +([0-9. x]+pts)', info))
    check(len(sizes) == 1, 'every frame one size: %s' % sizes)
    w, h = [float(x) for x in sizes.pop().split()[0:3:2]]
    widths = []
    for k in range(5):
        st = os.path.join(tmp, 's%d' % k)
        os.mkdir(st)
        with_default(s, os.path.join(st, 'moving.lua'), 'a', float(k))
        run([tool, 'render', os.path.join(st, 'moving.lua'), '-f', 'pdf',
             '-o', st])
        m = re.search(r'Page size: +([0-9.]+) x ([0-9.]+)',
                      run(['pdfinfo', os.path.join(st, 'moving.pdf')]).stdout)
        widths.append(float(m.group(1)))
        # the frame's ink stays 4 bp inside the page (the margin is 6 bp,
        # 1 bp for the antialiasing of the ink box's pixels)
        fw, fh, px = pdf_page(pdf, k + 1, os.path.join(tmp, 'p%d' % k))
        edge = 4
        for y in range(fh):
            for x in list(range(edge)) + list(range(fw - edge, fw)):
                check(px[3 * (y * fw + x):3 * (y * fw + x) + 3]
                      == b'\xff\xff\xff', 'frame %d inked at its edge' % k)
        for y in list(range(edge)) + list(range(fh - edge, fh)):
            check(px[3 * y * fw:3 * (y + 1) * fw] == b'\xff' * 3 * fw,
                  'frame %d inked at its top or bottom' % k)
    check(w >= max(widths) - 0.01 and w > min(widths) + 10,
          'the page %g bp wide holds every frame (%s)' % (w, widths))


LABELS = '''
local a = slider{ name = "a", min = 0, max = 1, default = 0 }
local f = figure{ name = "lab", page = "fixed", width = "6cm",
                  height = "4cm", window = { -2, 2, -1.5, 1.5 } }
local p = { -0.5 + 0.2 * a, 0 }
-- two segments from the point leave NE and NW about as clear; a faint
-- third one turning above the point tips the balance from one to the other
f:polyline({ p, {p[1] + 0.6, p[2] - 0.6} }, { color = "gray" })
f:polyline({ p, {p[1] - 0.6, p[2] - 0.6} }, { color = "gray" })
local th = 1.2 + 0.7 * a
f:polyline({ {p[1] + 0.05 * math.cos(th), 0.05 * math.sin(th)},
             {p[1] + 0.5 * math.cos(th), 0.5 * math.sin(th)} },
           { color = "gray", width = 0.3 })
f:points({ p }, { marker = "dot" })
f:label(p, "W", { place = "auto" })
f:label(p, "M", { place = "center", color = "white" })
'''


def glyph_uses(group):
    return [(m.group(1), float(m.group(2)), float(m.group(3)))
            for m in re.finditer(r'<use xlink:href="#(g\d+)" x="([-0-9.]+)" '
                                 r'y="([-0-9.]+)"', group)]


def label_offset(svg_text):
    """The auto label W's first glyph from the centred M's, bp."""
    uses = glyph_uses(svg_text)
    check(len(uses) == 2, 'two glyphs, W and M: %s' % uses)
    (_, wx, wy), (_, mx, my) = uses
    return (round(wx - mx, 1), round(wy - my, 1))


def check_labels(tool, src, tmp):
    s = os.path.join(tmp, 'lab.lua')
    with open(s, 'w') as f:
        f.write(LABELS)
    # the point moves 0.18 data units in 20 frames: 0.3 bp a frame
    frames = 21
    run([tool, 'render', s, '--sweep', 'a=0:0.9', '--frames', str(frames),
         '-f', 'svg', '-o', tmp])
    with open(os.path.join(tmp, 'lab.svg'), encoding='utf-8') as f:
        groups = re.split(r'<g id="frame-\d+"', f.read())[1:]
    check(len(groups) == frames, '%d frames in the SVG' % len(groups))
    kept = set(label_offset(g) for g in groups)
    check(len(kept) == 1, 'the label keeps its place: offsets %s'
          % sorted(kept))
    # placed afresh at the last frame's value, it goes to the other side:
    # the label would have hopped
    st = os.path.join(tmp, 'st')
    os.mkdir(st)
    with_default(s, os.path.join(st, 'lab.lua'), 'a', 0.9)
    run([tool, 'render', os.path.join(st, 'lab.lua'), '-f', 'svg', '-o', st])
    with open(os.path.join(st, 'lab.svg'), encoding='utf-8') as f:
        fresh = label_offset(f.read())
    check(fresh not in kept, 'placed afresh at a = 0.9 the label goes '
          'elsewhere (%s), the frames kept %s' % (fresh, kept))


def check_bad(tool, src, tmp):
    script = os.path.join(src, 'figures', 'interactive', 'decasteljau.lua')
    static = os.path.join(src, 'figures', 'orazem-decasteljau.lua')
    cases = [
        (['--sweep', 'tt=0:1'], "no slider 'tt'; did you mean 't'?"),
        (['--sweep', 't=0:2'], 'leaves the slider\'s range [0, 1]'),
        (['--sweep', 't=0:1', '--frames', '0'], '--frames \'0\''),
        (['--sweep', 't=0:1', '--fps', '0'], '--fps \'0\''),
        (['--sweep', 't=0:1', '--fps', '-5'], '--fps \'-5\''),
        # positive but outside: the message says which bound
        (['--sweep', 't=0:1', '--fps', '1e-300'],
         "--fps '1e-300' is too small: the least is 0.001"),
        (['--sweep', 't=0:1', '--fps', '1e-400'],
         "--fps '1e-400' is too small: the least is 0.001"),
        (['--sweep', 't=0:1', '--seconds', '1e5'],
         "--seconds '1e5' is too large: the most is 10000"),
        (['--sweep', 't=0:1', '--fps', '0'], 'give a positive number'),
        (['--sweep', 't=0:1', '--fps', 'x'],
         "--fps 'x': give a number from 0.001 to 10000"),
        (['--sweep', 't=0:1', '-f', 'png'], '-f png makes no animation'),
        (['--sweep', 't=0'], 'give NAME=FROM:TO'),
        (['--ease', 'fast'], 'use linear or in-out'),
    ]
    for args, msg in cases:
        out = os.path.join(tmp, 'bad')
        r = run([tool, 'render', script, '-o', out] + args, ok=False)
        check(r.returncode != 0 and msg in r.stderr,
              '%s: wanted "%s", got "%s"' % (args, msg, r.stderr))
        check(not os.path.exists(out) or os.listdir(out) == [],
              '%s left files: %s' % (args, os.listdir(out)))
    # the options of an animation belong to render: run and list refuse
    # them rather than ignore them
    for cmd in ('run', 'list'):
        r = run([tool, cmd, script, '--sweep', 't=0:1'], ok=False)
        check(r.returncode != 0 and 'options of an animation are render'
              in r.stderr, '%s --sweep: %s' % (cmd, r.stderr))
    r = run([tool, 'render', static, '--animate', '-o', tmp], ok=False)
    check(r.returncode == 1 and 'nothing to animate' in r.stderr,
          'a figure without sliders or steps: ' + r.stderr)
    # animate{} in the script: its keys and values checked where it is
    head = 'local t = slider{ name = "t", min = 0, max = 1 }\n'
    tail = ('local f = figure{ name = "x" }\n'
            'f:curve(bezier{ {0, 0}, {1, t} })\n')
    for body, msg in [
            ('animate{ slidr = "t", from = 0, to = 1 }',
             "animate: unknown key 'slidr' (did you mean slider?)"),
            ('animate{ slider = "t", from = 0 }',
             "slider 't' needs from and to"),
            ('animate{ slider = "t", from = 0, to = 1, ease = "fast" }',
             'ease "fast" is unknown'),
            ('animate{ slider = "t", from = 0, to = 1, frames = 0 }',
             'frames 0 must be a whole number from 1'),
            ('animate{ slider = "t", from = 0, to = 1, fps = -1 }',
             'fps -1 must be positive'),
            ('animate{ slider = "t", from = 0, to = 1 }\n'
             'animate{ slider = "t", from = 1, to = 0 }', 'called twice'),
            ('animate{ slider = "u", from = 0, to = 1 }',
             "animate{} (line 2): the script declares no slider 'u'"),
            ('animate{ slider = "t", from = -1, to = 1 }',
             "animate{} (line 2): t from -1 to 1 leaves the slider's "
             "range [0, 1]")]:
        path = os.path.join(tmp, 'anim-bad.lua')
        with open(path, 'w') as f:
            f.write(head + body + '\n' + tail)
        out = os.path.join(tmp, 'anim-bad')
        r = run([tool, 'render', path, '-f', 'gif', '-o', out], ok=False)
        check(r.returncode != 0 and msg in r.stderr and 'anim-bad.lua'
              in r.stderr, '%s: wanted "%s", got "%s"' % (body, msg,
                                                          r.stderr))
        check(not os.path.exists(out) or os.listdir(out) == [],
              '%s left files' % body)
    # a frame whose script fails: named, nothing written
    bad = os.path.join(tmp, 'fails.lua')
    with open(bad, 'w') as f:
        f.write('local t = slider{ name = "t", min = 0, max = 1 }\n'
                'if t > 0.5 then error("too far") end\n'
                'local f = figure{ name = "x" }\n'
                'f:curve(bezier{ {0, 0}, {1, t} })\n')
    out = os.path.join(tmp, 'fails')
    r = run([tool, 'render', bad, '--sweep', 't=0:1', '--frames', '4',
             '-f', 'svg,pdf', '-o', out], ok=False)
    check(r.returncode == 1 and 'frame 3' in r.stderr
          and 'too far' in r.stderr, 'a failing frame: ' + r.stderr)
    check(os.listdir(out) == [], 'a failing frame left %s' % os.listdir(out))


def check_beamer(tool, src, tmp):
    need('pdflatex', 'kpsewhich')
    if run(['kpsewhich', 'animate.sty'], ok=False).stdout.strip() == '':
        print('SKIP: no animate.sty (Debian: texlive-latex-extra)')
        sys.exit(SKIP)
    script = os.path.join(src, 'figures', 'interactive', 'decasteljau.lua')
    r = run([tool, 'render', script, '--sweep', 't=0:1', '--frames', '6',
             '-f', 'pdf', '-o', tmp], cwd=tmp)
    line = r.stdout.strip().replace(tmp + '/', '')
    check(line.startswith('\\animategraphics'), 'printed: ' + r.stdout)
    with open(os.path.join(tmp, 'slides.tex'), 'w') as f:
        f.write('\\documentclass{beamer}\n\\usepackage{animate}\n'
                '\\begin{document}\n\\begin{frame}{de Casteljau}\n'
                '\\centering\n%s\n\\end{frame}\n\\end{document}\n'
                % line.replace('controls]', 'controls,height=0.7'
                               '\\textheight]'))
    # animate's timeline needs a second run (its temporary extra page)
    for _ in range(2):
        r = run(['pdflatex', '-interaction=nonstopmode', '-halt-on-error',
                 'slides.tex'], ok=False, cwd=tmp)
        check(r.returncode == 0, 'pdflatex: ' + r.stdout[-2000:])
    info = run(['pdfinfo', os.path.join(tmp, 'slides.pdf')]).stdout
    check('Pages:           1' in info, 'one slide: ' + info)


def decode(path, outdir):
    """Every frame of an animated image as PPM files, through ffmpeg."""
    os.mkdir(outdir)
    run(['ffmpeg', '-loglevel', 'error', '-i', path, '-fps_mode',
         'passthrough', '-pix_fmt', 'rgb24',
         os.path.join(outdir, 'f%03d.ppm')])
    return sorted(os.path.join(outdir, f) for f in os.listdir(outdir))


def far(a, b, tol):
    """Pixels of two RGB images of one size with a channel off by > tol."""
    check(a[:2] == b[:2], 'sizes differ: %s, %s' % (a[:2], b[:2]))
    da, db = a[2], b[2]
    return sum(1 for i in range(0, len(da), 3)
               if max(abs(da[i] - db[i]), abs(da[i + 1] - db[i + 1]),
                      abs(da[i + 2] - db[i + 2])) > tol)


def check_raster(tool, src, tmp):
    need('ffmpeg')
    script = os.path.join(src, 'figures', 'interactive', 'decasteljau.lua')
    values = [0, 0.25, 0.5, 0.75, 1]
    run([tool, 'render', script, '--sweep', 't=0:1', '--frames', '5',
             '--dpi', '60', '--no-labels', '-f', 'gif,apng', '-o', tmp])
    gif = decode(os.path.join(tmp, 'decasteljau.gif'), os.path.join(tmp, 'g'))
    apng = decode(os.path.join(tmp, 'decasteljau.apng'),
                  os.path.join(tmp, 'a'))
    check(len(gif) == 5 and len(apng) == 5,
          'five frames: GIF %d, APNG %d' % (len(gif), len(apng)))
    for k in (1, 3):
        d = os.path.join(tmp, 'static%d' % k)
        os.mkdir(d)
        with_default(script, os.path.join(d, 's.lua'), 't', values[k])
        run([tool, 'render', os.path.join(d, 's.lua'), '--no-labels',
             '--dpi', '60', '-f', 'png', '-o', d])
        run(['ffmpeg', '-loglevel', 'error', '-i',
             os.path.join(d, 'decasteljau.png'), '-pix_fmt', 'rgb24',
             os.path.join(d, 'static.ppm')])
        want = ppm(os.path.join(d, 'static.ppm'))
        n = far(ppm(apng[k]), want, 2)
        check(n == 0, 'APNG frame %d differs from the static PNG at t = %g '
              'in %d pixels' % (k, values[k], n))
        n = far(ppm(gif[k]), want, 48)
        check(n <= 0.002 * want[0] * want[1], 'GIF frame %d differs from '
              'the static PNG at t = %g in %d pixels' % (k, values[k], n))
        other = ppm(gif[4 - k])
        check(far(other, want, 48) > 50, 'GIF frame %d is not frame %d'
              % (4 - k, k))


def check_browser(tool, src, tmp):
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        print('SKIP: no selenium')
        sys.exit(SKIP)
    for p in ('/usr/bin/chromium', '/usr/bin/chromedriver'):
        if not os.access(p, os.X_OK):
            print('SKIP: no', p)
            sys.exit(SKIP)
    script = os.path.join(src, 'figures', 'interactive', 'decasteljau.lua')
    run([tool, 'render', script, '--sweep', 't=0:1', '--frames', '3',
         '--seconds', '3', '-f', 'svg', '-o', tmp])
    opts = webdriver.ChromeOptions()
    opts.binary_location = '/usr/bin/chromium'
    for a in ('--headless', '--no-sandbox', '--disable-gpu',
              '--disable-dev-shm-usage', '--window-size=500,600'):
        opts.add_argument(a)
    drv = webdriver.Chrome(service=Service('/usr/bin/chromedriver'),
                           options=opts)
    try:
        drv.get('file://' + os.path.join(tmp, 'decasteljau.svg'))
        shots, shown = [], []
        for t in (0.5, 1.5, 2.5):
            drv.execute_script('var s = document.documentElement;'
                               's.pauseAnimations(); s.setCurrentTime(%g);'
                               % t)
            shown.append(drv.execute_script(
                'return Array.from(document.querySelectorAll('
                '"g[id^=frame-]")).filter(function (g) { return '
                'getComputedStyle(g).visibility == "visible"; })'
                '.map(function (g) { return g.id; });'))
            shots.append(drv.get_screenshot_as_png())
        # frame 0 alone, shown without SMIL: the screenshot at 0.5 s
        frame_svg(os.path.join(tmp, 'decasteljau.svg'), 0,
                  os.path.join(tmp, 'only0.svg'))
        drv.get('file://' + os.path.join(tmp, 'only0.svg'))
        only0 = drv.get_screenshot_as_png()
    finally:
        drv.quit()
    check(shown == [['frame-0'], ['frame-1'], ['frame-2']],
          'the frame shown at 0.5, 1.5, 2.5 s: %s' % shown)
    check(shots[0] != shots[1] and shots[1] != shots[2],
          'the screenshots at two times differ')
    check(only0 == shots[0], 'the screenshot at 0.5 s is frame 0')


def main():
    what, tool, src = sys.argv[1], os.path.abspath(sys.argv[2]), sys.argv[3]
    checks = {'frames': check_frames, 'union': check_union,
              'labels': check_labels, 'bad': check_bad,
              'beamer': check_beamer, 'raster': check_raster,
              'browser': check_browser}
    with tempfile.TemporaryDirectory() as tmp:
        checks[what](tool, src, tmp)
    print('ok', what)


if __name__ == '__main__':
    main()
