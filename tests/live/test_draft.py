#!/usr/bin/env python3
"""A draft run of an interactive figure (docs/interactive.md, "Drafts")
against the exact run of the same values.

usage: test_draft.py CURVEFIG SOURCE_DIR

For every shipped example (figures/interactive) at its defaults and at
moved values (a slider, a point, a turned 3D view; a 3D figure also
seen from below), `curvefig live
--once` with the values and with the values plus "@draft": 1:

- the draft's reply has the same parameters, values, figures, handles,
  places of the labels and Lua as the exact one (only the drawing may
  differ);
- the drawing of the draft is within the draft's stated tolerance of the
  exact drawing: every point of every path (outside the glyph
  definitions) of either lies within the bound of some path of the other
  (both ways, so nothing is left out or added), the bound being the
  draft's fitting tolerance plus the exact one (10 x 0.01 bp + 0.01 bp)
  and, in a figure with c:offset, the offset's tolerance in data units
  times the figure's scale (10 x 0.01 + 0.01 units); in a figure with
  surfaces, whose silhouettes are traced within 20 fitting tolerances,
  20 times the fitting tolerances instead (2 bp + 0.2 bp, the draft's
  made for the layout's first pass and serving its later ones within
  1.25 times their tolerance: 2.5 bp + 0.2 bp); plus 0.02 bp for the
  SVG's three decimals and the sampling here;
- with surfaces, the draft's visible lines lie within SPLIT (6 bp) of
  the exact visible lines and its hidden (dashed) lines within 6 bp of
  the exact hidden ones, both ways: the visible/hidden split agrees
  except within 6 bp of a change of visibility (measured: at most 4.7
  bp over 60 views of the patch, 0.6 bp at the median);
- where the draft saves work (the offset's certified offset, the
  surface's hidden lines) it is a different drawing, not the exact one
  (the flag reached the run);
- a static render never sees the flag: `curvefig render` of the example
  is the exact run's drawing (the same path data).
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile

FIG_TOL, FACTOR, SLACK = 0.01, 10, 0.02
SCENE = 20   # the silhouette's and the hidden lines' tolerance, in
             # fitting tolerances (render/figure/el-surface.c)
DRAFT_SLACK = 1.25   # a draft's surfaces serve the layout's later passes
                     # when made within 1.25 times their tolerance
                     # (CF_FIGURE_DRAFT_SLACK, curvefig/figure.h)
SPLIT = 6.0   # bp: where the draft's visible and hidden lines may part
              # from the exact ones (docs/interactive.md, "Drafts")
failures = []


def check(cond, what):
    print(('ok   ' if cond else 'FAIL ') + what, flush=True)
    if not cond:
        failures.append(what)


def once(tool, script, values):
    out = subprocess.run([tool, 'live', script, '--once',
                          json.dumps(values)], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit('%s %s: %s' % (script, values, out.stderr))
    return json.loads(out.stdout)


def paths(svg, dashed=None):
    """The path data outside <defs> (the glyphs are the same); with
    dashed True or False, only the dashed paths (hidden lines) or only
    the others."""
    body = re.sub(r'<defs>.*?</defs>', '', svg, flags=re.S)
    return [m.group(2) for m in re.finditer(r'<path([^>]*) d="([^"]*)"'
                                            r'([^>]*)>', body)
            if dashed is None or
            dashed == ('stroke-dasharray' in m.group(1) + m.group(3))]


def polylines(d, step=0.25):
    """Path data (M L C Z, absolute, as cairo writes it) as polylines,
    cubics cut into pieces of at most about step bp."""
    nums = [float(x) for x in re.findall(r'-?\d+(?:\.\d+)?(?:e-?\d+)?', d)]
    cmds = re.findall(r'[MLCZ]', d)
    out, cur, start, k = [], None, None, 0
    for c in cmds:
        if c == 'M':
            cur = start = (nums[k], nums[k + 1])
            k += 2
            out.append([cur])
        elif c == 'L':
            cur = (nums[k], nums[k + 1])
            k += 2
            out[-1].append(cur)
        elif c == 'C':
            p = [cur, (nums[k], nums[k + 1]), (nums[k + 2], nums[k + 3]),
                 (nums[k + 4], nums[k + 5])]
            k += 6
            hull = sum(math.dist(p[i], p[i + 1]) for i in range(3))
            n = max(2, int(math.ceil(hull / step)))
            for i in range(1, n + 1):
                t = i / n
                u = 1 - t
                b = (u ** 3, 3 * u * u * t, 3 * u * t * t, t ** 3)
                out[-1].append((sum(b[j] * p[j][0] for j in range(4)),
                                sum(b[j] * p[j][1] for j in range(4))))
            cur = p[3]
        elif c == 'Z':
            out[-1].append(start)
            cur = start
    return out


def segments(svg, dashed=None):
    segs = []
    for d in paths(svg, dashed):
        for pl in polylines(d):
            if len(pl) == 1:
                segs.append((pl[0], pl[0]))
            segs.extend(zip(pl, pl[1:]))
    return segs


def seg_dist(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    ll = dx * dx + dy * dy
    t = 0 if ll == 0 else max(0, min(1, ((p[0] - a[0]) * dx +
                                         (p[1] - a[1]) * dy) / ll))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def farthest(a_segs, b_segs, bound):
    """The largest distance of a point of a_segs (their ends and points
    every 0.25 bp) from b_segs, as far as it exceeds bound (a grid of
    cells of the bound's size: only the neighbours are measured, so a
    point farther than the bound reports the bound's first multiple it
    passed, enough to fail)."""
    cell = max(bound, 0.5)
    grid = {}
    for s in b_segs:
        x0, x1 = sorted((s[0][0], s[1][0]))
        y0, y1 = sorted((s[0][1], s[1][1]))
        for i in range(int(math.floor(x0 / cell)) - 1,
                       int(math.floor(x1 / cell)) + 2):
            for j in range(int(math.floor(y0 / cell)) - 1,
                           int(math.floor(y1 / cell)) + 2):
                grid.setdefault((i, j), []).append(s)
    worst = 0.0
    for a, b in a_segs:
        n = max(1, int(math.ceil(math.dist(a, b) / 0.25)))
        for k in range(n + 1):
            p = (a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n)
            near = grid.get((int(math.floor(p[0] / cell)),
                             int(math.floor(p[1] / cell))), [])
            d = min((seg_dist(p, s[0], s[1]) for s in near),
                    default=2 * cell)
            worst = max(worst, d)
    return worst


def same_but_drawing(exact, draft):
    def strip(j):
        j = json.loads(json.dumps(j))
        for f in j['figures']:
            f.pop('svg')
        return j
    return strip(exact) == strip(draft)


def compare(tool, script, name, values, differs):
    exact = once(tool, script, values)
    draft = once(tool, script, dict(values, **{'@draft': 1}))
    what = '%s %s' % (name, json.dumps(values) if values else 'defaults')
    check(exact['error'] is None and draft['error'] is None,
          '%s: both run' % what)
    check(same_but_drawing(exact, draft), '%s: the draft has the exact '
          'run\'s parameters, values, figures, handles, label places and '
          'Lua' % what)
    text = open(script).read()
    offset, surface = 'offset(' in text, ':surface(' in text
    for fe, fd in zip(exact['figures'], draft['figures']):
        m = fe['to_svg']
        scale = math.sqrt(abs(m[0] * m[3] - m[1] * m[2]))
        bound = (FACTOR + 1) * FIG_TOL + SLACK
        if surface:
            bound = (FACTOR * DRAFT_SLACK + 1) * SCENE * FIG_TOL + SLACK
        if offset:
            bound += (FACTOR + 1) * 0.01 * scale
        se, sd = segments(fe['svg']), segments(fd['svg'])
        far = max(farthest(sd, se, bound), farthest(se, sd, bound))
        check(se and sd and far <= bound,
              '%s, figure %s: the draft within %.3g bp of the exact '
              'drawing, both ways (%.3g bp)' % (what, fe['name'], bound,
                                                  far))
        if surface:
            # the split between visible and hidden (dashed) lines: each
            # part of the draft within SPLIT bp of the same part of the
            # exact drawing, both ways
            split = 0.0
            for dashed in (False, True):
                he, hd = segments(fe['svg'], dashed), segments(fd['svg'],
                                                              dashed)
                if he or hd:
                    split = max(split, farthest(hd, he, SPLIT) if he
                                else math.inf, farthest(he, hd, SPLIT)
                                if hd else math.inf)
            check(split <= SPLIT,
                  '%s, figure %s: the draft\'s visible and hidden lines '
                  'within %.3g bp of the exact ones, both ways (%.3g bp)'
                  % (what, fe['name'], SPLIT, split))
        if differs:
            check(fe['svg'] != fd['svg'], '%s, figure %s: the draft is '
                  'drawn differently (the flag reached the run)'
                  % (what, fe['name']))
    return exact


def main():
    tool, src = sys.argv[1], sys.argv[2]
    d = os.path.join(src, 'figures', 'interactive')
    names = sorted(f[:-4] for f in os.listdir(d) if f.endswith('.lua'))
    tmp = tempfile.mkdtemp(prefix='cf-draft-')
    for name in names:
        script = os.path.join(d, name + '.lua')
        differs = name in ('offset', 'surface-patch')
        exact = compare(tool, script, name, {}, differs)
        # the static render is the exact run's drawing
        out = subprocess.run([tool, 'render', script, '-f', 'svg', '-o',
                              tmp], capture_output=True, text=True)
        check(out.returncode == 0, '%s: curvefig render' % name)
        for f in exact['figures']:
            with open(os.path.join(tmp, f['name'] + '.svg')) as g:
                static = g.read()
            check(paths(static) == paths(f['svg']),
                  '%s, figure %s: curvefig render draws the exact run\'s '
                  'paths' % (name, f['name']))
        moved = {}
        for p in exact['params']:
            if p['kind'] == 'slider':
                moved[p['name']] = p['min'] + 0.7 * (p['max'] - p['min'])
            elif not moved.get('@points'):
                q = [list(xy) for xy in p['value']]
                q[0][0] += 0.25
                q[0][1] -= 0.125
                moved[p['name']] = q
                moved['@points'] = True
        moved.pop('@points', None)
        for f in exact['figures']:
            if f.get('view'):
                moved['@view:' + f['name']] = [[f['view'][0] + 25,
                                                f['view'][1] + 12]]
        compare(tool, script, name, moved, differs)
        # a 3D figure seen from below and the side, where the draft's
        # hidden lines part farthest from the exact ones
        below = {'@view:' + f['name']: [[f['view'][0] + 145, -20]]
                 for f in exact['figures'] if f.get('view')}
        if below:
            compare(tool, script, name, below, differs)
    for f in os.listdir(tmp):
        os.unlink(os.path.join(tmp, f))
    os.rmdir(tmp)
    if failures:
        sys.exit('%d failures' % len(failures))


main()
