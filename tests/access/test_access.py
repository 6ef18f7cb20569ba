#!/usr/bin/python3
"""Accessible figures (docs/accessibility.md): the text every output
carries, checked in the bytes each format is read by.

usage: test_access.py CURVEFIG SOURCE_DIR

- SVG (a figure and the animated SVG of overlay steps): role="img",
  aria-labelledby naming the <title> (the alt text),
  aria-describedby the <desc> (the long description), xml:lang.
- PDF: the structure tree, followed from the catalog's /StructTreeRoot
  through /K, holds a Figure whose /Alt (UTF-16BE) is the alt text and the
  description; the catalog has /Lang and /MarkInfo; every xref offset
  still points at its object after the bytes were inserted (and pdfinfo
  -struct, when poppler-utils is installed, lists the Figure).
- PS and EPS: %%Title is the alt text, before %%EndComments; PGF: the
  alt text as a comment.
- The automatic description checked against the model: the control
  points parsed back out of it equal the points the scripts give (read
  from the scripts' own text), the de Casteljau point it names is the
  curve's point at t computed here in exact rational arithmetic, the
  knots and weights are the scripts', an offset's distance is the one its
  caption gives; the subdivision and the knot insertion of
  tests/access/a11y.lua are named; Czech with its decimal comma for
  lang = "cs".
- Bad input: alt not a string, alt = "", a misspelt key, a bad language
  tag: each a clear error naming the key.
- The gallery shows each figure's alt text and description.
"""
import html
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from fractions import Fraction

SVG = '{http://www.w3.org/2000/svg}'
FAILS = []


def check(cond, what):
    if not cond:
        FAILS.append(what)
        print('FAIL:', what)


def render(tool, script, outdir, formats, extra=()):
    r = subprocess.run([tool, 'render', '-o', outdir, '-f', formats]
                       + list(extra) + [script],
                       capture_output=True, text=True)
    check(r.returncode == 0, '%s: %s' % (script, r.stderr))
    return r


def svg_text(path):
    """(root, alt, description) of an SVG file, the links checked."""
    root = ET.parse(path).getroot()
    title = root.find(SVG + 'title')
    desc = root.find(SVG + 'desc')
    check(root.get('role') == 'img', path + ': role="img"')
    check(title is not None and title.get('id')
          and root.get('aria-labelledby') == title.get('id'),
          path + ': aria-labelledby names the <title>')
    if desc is not None:
        check(root.get('aria-describedby') == desc.get('id'),
              path + ': aria-describedby names the <desc>')
    return (root, title.text if title is not None else None,
            desc.text if desc is not None else None)


# ---- the description read back -------------------------------------------

def number(s, comma=False):
    s = s.strip()
    if comma:
        s = s.replace(',', '.')
    return Fraction(s) if '/' in s else Fraction(s)


def named_points(desc, comma=False):
    """name -> coordinates of every 'NAME (x, y)' of a description."""
    sep = ';' if comma else ','
    num = r'-?[0-9]+(?:[.,/][0-9]+)?'
    pat = re.compile(r'([A-Za-z]_\d+) \((%s(?:%s %s)+)\)'
                     % (num, sep, num))
    out = {}
    for m in pat.finditer(desc):
        out[m.group(1)] = [number(v, comma) for v in m.group(2).split(sep)]
    return out


def close(a, b, rel=5e-4):
    """Coordinates written with 4 significant digits at least."""
    return len(a) == len(b) and all(
        abs(Fraction(x) - Fraction(y)) <= rel * max(1, abs(Fraction(y)))
        for x, y in zip(a, b))


def decasteljau(pts, t):
    pts = [[Fraction(v) for v in p] for p in pts]
    while len(pts) > 1:
        pts = [[(1 - t) * a + t * b for a, b in zip(p, q)]
               for p, q in zip(pts, pts[1:])]
    return pts[0]


def lua_points(text, var):
    """The points of `local VAR = { {x, y}, ... }` (or bezier{...}) of a
    script's source."""
    m = re.search(r'local %s = (?:bezier)?\{ *((?:\{[^{}]*\}[ ,]*)+)\}'
                  % var, text)
    return [[Fraction(v.strip()) for v in p.split(',')]
            for p in re.findall(r'\{([^{}]*)\}', m.group(1))]


def lua_numbers(text, var):
    m = re.search(r'local %s = \{([^{}]*)\}' % var, text)
    return [Fraction(v.strip()) for v in m.group(1).split(',')]


def list_after(desc, key):
    """The numbers listed after key up to the next ';' or '.  '."""
    m = re.search(re.escape(key) + r'(.*?)(?:;|\. |\.$)', desc)
    return [Fraction(v) for v in
            re.split(r', | and ', m.group(1).strip())]


def check_models(tool, src, out):
    # lec05-decasteljau: a cubic in R^3, de Casteljau at t = 0.4
    path = os.path.join(src, 'figures', 'lec05-decasteljau.lua')
    text = open(path, encoding='utf-8').read()
    render(tool, path, out, 'svg')
    _, alt, desc = svg_text(os.path.join(out, 'lec05-decasteljau.svg'))
    P = lua_points(text, 'c')
    t = Fraction(re.search(r'local t = ([0-9.]+)', text).group(1))
    pts = named_points(desc)
    for i, p in enumerate(P):
        check(close(pts.get('b_%d' % i, []), p),
              'lec05: b_%d of the description is the script\'s %s' % (i, p))
    check("de Casteljau's construction at t = %s" % float(t) in desc,
          'lec05: the construction and its t')
    m = re.search(r'curve point .*\(([^()]*)\)\.', desc)
    check(m is not None and close([Fraction(v) for v in
                                   m.group(1).split(', ')],
                                  decasteljau(P, t)),
          'lec05: the curve point is c(t) computed exactly')
    check(alt and alt.startswith("de Casteljau's algorithm"),
          'lec05: the alt text is the caption')

    # markova-2.17: a quadratic B-spline, its points and knots
    path = os.path.join(src, 'figures', 'markova-2.17.lua')
    text = open(path, encoding='utf-8').read()
    render(tool, path, out, 'svg')
    _, _, desc = svg_text(os.path.join(out, 'markova-2.17.svg'))
    pts = named_points(desc)
    for i, p in enumerate(lua_points(text, 'P')):
        check(close(pts.get('P_%d' % i, []), p),
              'markova-2.17: P_%d is the script\'s' % i)
    check(desc.startswith('A quadratic B-spline curve'),
          'markova-2.17: its kind and degree')
    check(list_after(desc, 'knots ') == lua_numbers(text, 'U'),
          'markova-2.17: the knots are the script\'s')

    # orazem-offset-1: a quartic and its offset (cubic pieces) at the d of
    # the figure's caption
    path = os.path.join(src, 'figures', 'orazem-offset-1.lua')
    text = open(path, encoding='utf-8').read()
    render(tool, path, out, 'svg')
    _, alt, desc = svg_text(os.path.join(out, 'orazem-offset-1.svg'))
    d = re.search(r'd = ([0-9.]+)', alt).group(1)
    check(desc.startswith('A quartic Bézier curve and its offset at '
                          'distance %s.' % d),
          'orazem-offset-1: the offset at d = %s recognised: %s'
          % (d, desc[:80]))
    pts = named_points(desc)
    for i, p in enumerate(lua_points(text, 'P')):
        check(close(pts.get('P_%d' % i, []), p),
              'orazem-offset-1: P_%d is the script\'s' % i)

    # overlay-decasteljau: the animated SVG of overlay steps is labelled
    # too, its construction at the t of its script
    path = os.path.join(src, 'figures', 'overlay-decasteljau.lua')
    text = open(path, encoding='utf-8').read()
    render(tool, path, out, 'svg')
    _, _, desc = svg_text(os.path.join(out, 'overlay-decasteljau.svg'))
    t = re.search(r'local t = ([0-9/ .]+)\n', text).group(1).replace(' ', '')
    check("with de Casteljau's construction at t = %s." % t in desc,
          'overlay-decasteljau: the animated SVG\'s description, t = %s: %s'
          % (t, desc[:90]))

    # lecture5-weight: rational cubics, weight w of p_2 in turn
    path = os.path.join(src, 'figures', 'lecture5-weight.lua')
    text = open(path, encoding='utf-8').read()
    render(tool, path, out, 'svg')
    _, _, desc = svg_text(os.path.join(out, 'lecture5-weight.svg'))
    ws = lua_numbers(text, 'ws')
    for k, w in enumerate(ws):
        m = re.search(r'Curve %d \(a rational cubic B\S+ curve\): .*?'
                      r'weights ((?:[0-9./]+(?:, | and )?)+)' % (k + 1), desc)
        got = [Fraction(v) for v in re.split(r', | and ', m.group(1))] \
            if m else None
        check(got == [1, 1, w, 1],
              'lecture5-weight: curve %d has weights 1, 1, %s, 1' % (k + 1, w))


def check_own(tool, src, out):
    script = os.path.join(src, 'tests', 'access', 'a11y.lua')
    render(tool, script, out, 'svg,pdf,ps,eps,pgf')
    # Czech: decimal comma, the construction, the subdivision
    root, alt, desc = svg_text(os.path.join(out, 'a11y-cs.svg'))
    check(root.get('{http://www.w3.org/XML/1998/namespace}lang') == 'cs',
          'a11y-cs: xml:lang="cs"')
    check(alt == 'Kubická Bézierova křivka a její konstrukce',
          'a11y-cs: <title> is the alt text')
    P = [[0, 5], [2, 7], [5, 7], [6, 2]]
    pts = named_points(desc, comma=True)
    for i, p in enumerate(P):
        check(close(pts.get('P_%d' % i, []), p), 'a11y-cs: P_%d' % i)
    check(desc.startswith('Kubická Bézierova křivka a konstrukce de '
                          'Casteljauova algoritmu v t = 3/4'),
          'a11y-cs: the Czech summary with t = 3/4: ' + desc[:80])
    m = re.search(r'bodě křivky \(([^)]*)\)', desc)
    check(m is not None and close([number(v, True) for v in
                                   m.group(1).split(';')],
                                  decasteljau(P, Fraction(3, 4))),
          'a11y-cs: the curve point at t = 3/4, decimal comma')
    check('Křivka 2 je část křivky 1 před t = 1/2 (dělení)' in desc
          and 'Křivka 3 je část křivky 1 za t = 1/2 (dělení)' in desc,
          'a11y-cs: the two halves named as a subdivision at 1/2')
    _, alt_en, desc_en = svg_text(os.path.join(out, 'a11y-en.svg'))
    check(alt_en == 'A quadratic B-spline & its refinement <u = 1/2>',
          'a11y-en: the alt text, unescaped')
    check('Curve 2 is curve 1 after knot insertion at u = 1/2' in desc_en,
          'a11y-en: the knot insertion recognised: ' + desc_en)
    check(list_after(desc_en, 'knots ') == [0, 0, 0, Fraction(1, 3),
                                           Fraction(2, 3), 1, 1, 1],
          'a11y-en: the knots as fractions')
    check_pdf(os.path.join(out, 'a11y-cs.pdf'), alt + ' ' + desc, 'cs')
    for ext in ('ps', 'eps'):
        data = open(os.path.join(out, 'a11y-cs.' + ext), 'rb').read()
        head = data[:data.find(b'%%EndComments')]
        check(('%%Title: ' + alt + '\n').encode() in head,
              'a11y-cs.%s: %%%%Title is the alt text' % ext)
    pgf = open(os.path.join(out, 'a11y-cs.pgf'), encoding='utf-8').read()
    check('\n% ' + alt + '\n' in pgf, 'a11y-cs.pgf: the alt text comment')


# ---- PDF --------------------------------------------------------------------

def pdf_objects(data):
    """object number -> its bytes, every xref offset checked."""
    x = data.rindex(b'\nxref\n') + 1
    start = int(re.search(rb'startxref\s+(\d+)', data[x:]).group(1))
    check(start == x, 'pdf: startxref is the xref table\'s offset')
    m = re.match(rb'xref\n0 (\d+)\n', data[x:])
    n, at = int(m.group(1)), x + m.end()
    objs = {}
    for i in range(n):
        e = data[at + 20 * i: at + 20 * i + 20]
        if e[17:18] != b'n':
            continue
        off = int(e[:10])
        check(data[off:].startswith(b'%d 0 obj' % i),
              'pdf: xref entry %d points at its object' % i)
        objs[i] = data[off:data.index(b'endobj', off)]
    return objs


def ref(obj, key):
    m = re.search(rb'/' + key + rb' (\d+) 0 R', obj)
    return int(m.group(1)) if m else None


def check_pdf(path, alt, lang):
    data = open(path, 'rb').read()
    objs = pdf_objects(data)
    cat = [o for o in objs.values() if b'/Type /Catalog' in o]
    check(len(cat) == 1, 'pdf: one catalog')
    cat = cat[0]
    check(b'/MarkInfo << /Marked true >>' in cat, 'pdf: /MarkInfo')
    check(('/Lang (%s)' % lang).encode() in cat, 'pdf: /Lang')
    root = objs[ref(cat, b'StructTreeRoot')]
    doc = objs[int(re.search(rb'/K \[ (\d+) 0 R', root).group(1))]
    check(b'/S /Document' in doc, 'pdf: the tree\'s Document')
    fig = objs[ref(doc, b'K')]
    check(b'/S /Figure' in fig, 'pdf: the Document holds a Figure')
    m = re.search(rb'/Alt <FEFF([0-9A-F]*)>', fig)
    got = bytes.fromhex(m.group(1).decode()).decode('utf-16-be') if m else ''
    check(got == alt, 'pdf: the Figure\'s /Alt is the alt text and the '
          'description: %r' % got[:60])
    if shutil.which('pdfinfo'):
        r = subprocess.run(['pdfinfo', '-struct', path], capture_output=True,
                           text=True)
        check(r.returncode == 0 and 'Figure' in r.stdout
              and 'Syntax Error' not in r.stderr,
              'pdfinfo -struct reads the Figure: ' + r.stdout + r.stderr)


# ---- bad input, the gallery ------------------------------------------------

def check_bad(tool, out):
    cases = [
        ('alt = 5', 'figure: alt must be a string, got number'),
        ('alt = ""', 'figure: alt is empty'),
        ('atl = "x"', "unknown option 'atl' (did you mean 'alt'?)"),
        ('description = true', 'figure: description must be a string, '
                               'got boolean'),
        ('lang = "c z"', 'lang "c z" is not a language tag'),
    ]
    for k, (opt, msg) in enumerate(cases):
        script = os.path.join(out, 'bad%d.lua' % k)
        with open(script, 'w') as f:
            f.write('local f = figure{ name = "bad%d", %s }\n'
                    'f:points({{0, 0}})\n' % (k, opt))
        r = subprocess.run([tool, 'render', '-o', out, '-f', 'svg', script],
                           capture_output=True, text=True)
        check(r.returncode != 0 and msg in r.stderr
              and 'bad%d.lua:1:' % k in r.stderr,
              '%s: "%s" expected, got %s' % (opt, msg, r.stderr.strip()))
        check(not os.path.exists(os.path.join(out, 'bad%d.svg' % k)),
              '%s: no file written' % opt)


def check_gallery(tool, src, out):
    script = os.path.join(src, 'tests', 'access', 'a11y.lua')
    man = os.path.join(out, 'a11y.manifest')
    render(tool, script, out, 'svg', ['--manifest', man])
    page = os.path.join(out, 'index.html')
    r = subprocess.run([tool, 'gallery', '-o', page, man],
                       capture_output=True, text=True)
    check(r.returncode == 0, 'gallery: ' + r.stderr)
    text = open(page, encoding='utf-8').read()
    alt = 'A quadratic B-spline & its refinement <u = 1/2>'
    check('alt="%s"' % html.escape(alt) in text.replace('&#x27;', '&#39;'),
          'gallery: the image\'s alt attribute is the alt text')
    check('<p class="alt">%s</p>' % html.escape(alt, quote=True)
          .replace('&#x27;', '&#39;') in text,
          'gallery: the alt text shown')
    check('Curve 2 is curve 1 after knot insertion' in text,
          'gallery: the description shown')


def main():
    tool, src = sys.argv[1], sys.argv[2]
    out = tempfile.mkdtemp(prefix='cf-access-')
    try:
        check_models(tool, src, out)
        check_own(tool, src, out)
        check_bad(tool, out)
        check_gallery(tool, src, out)
    finally:
        shutil.rmtree(out)
    if FAILS:
        print('%d check(s) failed' % len(FAILS))
        sys.exit(1)
    print('ok')


if __name__ == '__main__':
    main()
