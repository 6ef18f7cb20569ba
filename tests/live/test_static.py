#!/usr/bin/env python3
"""One script is the printed and the interactive figure: every shipped
interactive example (figures/interactive/*.lua) renders statically (SVG,
PDF, PNG), and its static SVG is byte for byte the SVG that
`curvefig live --once` gives for no values (the defaults); with values
set, the SVG differs.

usage: test_static.py CURVEFIG SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile


def main():
    tool, src = sys.argv[1], sys.argv[2]
    d = os.path.join(src, 'figures', 'interactive')
    scripts = sorted(f for f in os.listdir(d) if f.endswith('.lua'))
    bad = 0
    if len(scripts) < 5:
        sys.exit('FAIL: %d interactive examples, expected 5' % len(scripts))
    with tempfile.TemporaryDirectory() as out:
        for s in scripts:
            path = os.path.join(d, s)
            r = subprocess.run([tool, 'render', path, '-o', out, '-f',
                                'svg,pdf,png'], capture_output=True,
                               text=True)
            if r.returncode != 0:
                print('FAIL', s, 'does not render:', r.stderr)
                bad += 1
                continue
            j = json.loads(subprocess.run([tool, 'live', path, '--once'],
                                          capture_output=True,
                                          text=True).stdout)
            for fig in j['figures']:
                with open(os.path.join(out, fig['name'] + '.svg')) as f:
                    static = f.read()
                same = static == fig['svg']
                print('ok  ' if same else 'FAIL', s, fig['name'],
                      'static SVG = the SVG at the defaults')
                bad += not same
            sliders = [p for p in j['params'] if p['kind'] == 'slider']
            p = sliders[0]
            moved = {p['name']: p['max'] if p['default'] != p['max']
                     else p['min']}
            k = json.loads(subprocess.run(
                [tool, 'live', path, '--once', json.dumps(moved)],
                capture_output=True, text=True).stdout)
            differs = k['error'] is None and \
                k['figures'][0]['svg'] != j['figures'][0]['svg']
            print('ok  ' if differs else 'FAIL', s, 'another value of the first slider '
                  'draws another figure')
            bad += not differs
    if bad:
        sys.exit('%d failures' % bad)


main()
