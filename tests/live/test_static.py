#!/usr/bin/env python3
"""One script is the printed and the interactive figure: every shipped
interactive example (figures/interactive/*.lua) renders statically (SVG,
PDF, PNG), and its static SVG is byte for byte the SVG that
`curvefig live --once` gives for no values (the defaults); with values
set, the SVG differs.  `--once` exits 0 on a good run, 1 with the
message (file:line) on stderr on a script error (the JSON still carries
it), 2 on values that are not JSON.

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
            once = subprocess.run([tool, 'live', path, '--once'],
                                  capture_output=True, text=True)
            j = json.loads(once.stdout)
            good = once.returncode == 0 and j['error'] is None
            print('ok  ' if good else 'FAIL', s, '--once exits 0, no error')
            bad += not good
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
        bad += once_errors(tool, d, out)
    if bad:
        sys.exit('%d failures' % bad)


def once_errors(tool, d, out):
    """--once on a script that fails (at run time, in a declaration) and
    on bad values: the status, the message on stderr, the JSON's error."""
    with open(os.path.join(d, 'decasteljau.lua')) as f:
        good = f.read()
    lines = good.split('\n')
    at = lines.index('local c = bezier(P)')
    broken = '\n'.join(lines[:at + 1] + ['error("broken here")'] +
                       lines[at + 1:])
    decl = good.replace('default = 0.75', 'default = 7.5', 1)
    decl_line = 1 + next(i for i, l in enumerate(decl.split('\n'))
                         if 'default = 7.5' in l)
    bad = 0
    for name, text, line, what in (
            ('broken.lua', broken, at + 2, 'broken here'),
            ('declared.lua', decl, decl_line, "slider 't': default 7.5")):
        path = os.path.join(out, name)
        with open(path, 'w') as f:
            f.write(text)
        r = subprocess.run([tool, 'live', path, '--once'],
                           capture_output=True, text=True)
        j = json.loads(r.stdout)
        want = '%s:%d: %s' % (name, line, what)
        ok = (r.returncode == 1 and want in r.stderr and
              j['error'] is not None and j['error']['line'] == line and
              want in j['error']['message'] and j['figures'] == [])
        print('ok  ' if ok else 'FAIL', name, '--once exits 1 with "%s" '
              '(status %d, stderr %r)' % (want, r.returncode, r.stderr))
        bad += not ok
    r = subprocess.run([tool, 'live', os.path.join(d, 'decasteljau.lua'),
                        '--once', '{"t": '], capture_output=True, text=True)
    ok = r.returncode == 2 and 'values:' in r.stderr
    print('ok  ' if ok else 'FAIL', '--once exits 2 on values that are not '
          'JSON (status %d, stderr %r)' % (r.returncode, r.stderr))
    return bad + (not ok)


main()
