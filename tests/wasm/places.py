#!/usr/bin/python3
"""The places of the labels in a course page and in the tool, number for
number.

usage: places.py CURVEFIG SOURCE_DIR

Every shipped interactive example (figures/interactive/*.lua) at its
defaults and with its first slider moved to 0.37 and 0.81 of its range:
the tool's places (`curvefig live SCRIPT --once VALUES`, the "labels" of
its JSON: what the layout chose, cf_figure_render_places) against the
page's, read in headless Chromium from the WebAssembly module of the page
that `curvefig render -f html` wrote (a second engine of the page's own
data, run with the same values).  Each label must have the same source and
place, and its origin the same double, to the bit: a label of the
defaults has its runs in the glyph data as pango shaped them (S lines,
pango's own numbers); a label the page composes from its characters (a
slider's readout at a value the defaults never showed) has each glyph's
advance, kern and ink box rounded to pango units as pango rounds them
(render/labels/font-table.c), from per-bp values written with 7 and 9
significant digits, which is the same at these sizes.
Skipped (77) without chromium, chromedriver or selenium.
"""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', 'live'))
import test_browser as lb  # noqa: E402  (skips, 77, without selenium)

# further parameter sets of some examples, beside their defaults and slider
EXTRA = {
    'surface-patch': [{'L': [[-1.6, 1.9]]}],
}

# a second engine of the page's data, made once a page
MAKE = 'window.cfPlaces = new CurvefigWasmEngine(%s);'
RUN = '''
var done = arguments[arguments.length - 1];
window.cfPlaces.run(%s).then(function (r) { done(JSON.stringify(r)); },
                             function (x) { done('error: ' + x); });
'''


def engine_data(html):
    """The literal the page hands CurvefigWasmEngine."""
    key = 'new CurvefigWasmEngine('
    start = html.index(key) + len(key)
    end = html.rindex('));\n</script>')
    return html[start:end]


def compare(name, at, tool_labels, page_labels, shaped):
    bad = 0
    if len(tool_labels) != len(page_labels):
        print('FAIL %s %s: %d labels in the tool, %d in the page'
              % (name, at, len(tool_labels), len(page_labels)))
        return 1
    worst = 0.0
    for t, p in zip(tool_labels, page_labels):
        if t['text'] != p['text'] or t['place'] != p['place']:
            print('FAIL %s %s: %r placed %d in the tool, %r %d in the page'
                  % (name, at, t['text'], t['place'], p['text'],
                     p['place']))
            bad += 1
            continue
        d = max(abs(t['x'] - p['x']), abs(t['y'] - p['y']))
        worst = max(worst, d)
        if d != 0 or t['anchor_x'] != p['anchor_x'] \
                or t['anchor_y'] != p['anchor_y']:
            print('FAIL %s %s: %r at (%r, %r) in the tool, (%r, %r) in the '
                  'page (%s at export)' % (name, at, t['text'], t['x'],
                                           t['y'], p['x'], p['y'],
                                           'shaped' if t['text'] in shaped
                                           else 'not shaped'))
            bad += 1
    print('%s %s %s: %d labels, largest difference %g bp'
          % ('ok  ' if not bad else 'FAIL', name, at, len(tool_labels),
             worst))
    return bad


def main():
    tool, src = os.path.abspath(sys.argv[1]), sys.argv[2]
    for path in (lb.CHROMIUM, lb.CHROMEDRIVER):
        if not os.access(path, os.X_OK):
            print('SKIP: no', path)
            sys.exit(77)
    folder = os.path.join(src, 'figures', 'interactive')
    examples = sorted(f[:-4] for f in os.listdir(folder)
                      if f.endswith('.lua'))
    failures = 0
    drv = lb.make_driver()
    drv.set_script_timeout(120)
    try:
        with tempfile.TemporaryDirectory() as outdir:
            for name in examples:
                script = os.path.join(folder, name + '.lua')
                out = subprocess.run([tool, 'render', script, '-f', 'html',
                                      '-o', outdir], capture_output=True,
                                     text=True)
                if 'needs the WebAssembly module' in out.stderr:
                    print('SKIP: this build has no WebAssembly module')
                    sys.exit(77)
                lb.check(out.returncode == 0, '%s: -f html %s'
                         % (name, out.stderr))
                page = os.path.join(outdir, name + '.html')
                with open(page, encoding='utf-8') as f:
                    html = f.read()
                data = engine_data(html)
                drv.get('file://' + page)
                drv.execute_script(MAKE % data)
                defaults = json.loads(subprocess.run(
                    [tool, 'live', script, '--once'], capture_output=True,
                    text=True, check=True).stdout)
                slider = next(p for p in defaults['params']
                              if p['kind'] == 'slider')
                # the labels of the export: their runs are in the glyph
                # data as pango shaped them
                shaped = set(lab['text'] for f in defaults['figures']
                             for lab in f['labels'])
                values = [{}]
                for at in (0.37, 0.81):
                    v = slider['min'] + at * (slider['max'] - slider['min'])
                    values.append({slider['name']: round(v, 2)})
                values += EXTRA.get(name, [])
                for v in values:
                    native = json.loads(subprocess.run(
                        [tool, 'live', script, '--once', json.dumps(v)],
                        capture_output=True, text=True, check=True).stdout)
                    nfig = next(f for f in native['figures']
                                if f['name'] == name)
                    reply = drv.execute_async_script(RUN % json.dumps(v))
                    lb.check(not reply.startswith('error'),
                             '%s: the page ran at %s%s' % (
                                 name, json.dumps(v), reply[:200]
                                 if reply.startswith('error') else ''))
                    pfig = json.loads(reply)['figures'][0]
                    failures += compare(name, json.dumps(v), nfig['labels'],
                                        pfig['labels'], shaped)
                drv.get('about:blank')
    finally:
        drv.quit()
    sys.exit(1 if failures else 0)


if __name__ == '__main__':
    main()
