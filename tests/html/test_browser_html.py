#!/usr/bin/python3
"""The course pages of `curvefig render -f html` in a real browser.

usage: test_browser_html.py CURVEFIG SOURCE_DIR [EXAMPLE...]

Every shipped interactive example (figures/interactive/*.lua) written
with -f html into a temporary directory and opened from the file (file://,
no server); then the same checks as the live page's test (tests/live/
test_browser.py, whose steps it runs): a slider moved by a key press and a
control point dragged with the pointer, and after each the drawing, now
computed in the page by the WebAssembly module, shows the point the
native core computes for the page's values; the console stays free of
errors.  And the page loads nothing: its Content-Security-Policy is
default-src 'none', and the browser's resource timing lists no request.
A page whose slider drives an endless loop, written with --timeout 3:
the page stops the run (its Web Worker) and shows the time-limit error
within the limit, the tab answering all the while, and draws again when
the slider moves back.
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


def test_page(drv, tool, script, name, spec, outdir):
    out = subprocess.run([tool, 'render', script, '-f', 'html', '-o', outdir],
                         capture_output=True, text=True)
    if 'needs the WebAssembly module' in out.stderr:
        print('SKIP: this build has no WebAssembly module')
        sys.exit(77)
    lb.check(out.returncode == 0, '%s: -f html %s' % (name, out.stderr))
    page = os.path.join(outdir, name + '.html')
    with open(page, encoding='utf-8') as f:
        html = f.read()
    lb.check("default-src 'none'" in html and 'http://' not in html.split(
        '<script>')[0].replace('http://www.w3.org', ''),
        '%s: the page allows no loads' % name)
    native = json.loads(subprocess.run(
        [tool, 'live', script, '--once'], capture_output=True,
        text=True).stdout)
    drv.get('file://' + page)
    lb.exercise(drv, tool, name, spec, native)
    loaded = drv.execute_script(
        'return performance.getEntriesByType("resource")'
        '.map(function (e) { return e.name; });')
    lb.check(loaded == [], '%s: no requests %s' % (name, loaded))
    drv.get('about:blank')


def test_spinning_page(drv, tool, src, outdir):
    script = os.path.join(outdir, 'decasteljau.lua')
    lb.spin_script(src, script)
    out = subprocess.run([tool, 'render', script, '-f', 'html', '-o', outdir,
                          '--timeout', '3', '--max-instructions', '1e15'],
                         capture_output=True, text=True)
    lb.check(out.returncode == 0, 'spin: -f html --timeout 3 %s'
             % out.stderr)
    drv.get('file://' + os.path.join(outdir, 'decasteljau.html'))
    lb.exercise_spin(drv, 'html', 3)
    drv.get('about:blank')


def main():
    tool, src = os.path.abspath(sys.argv[1]), sys.argv[2]
    for path in (lb.CHROMIUM, lb.CHROMEDRIVER):
        if not os.access(path, os.X_OK):
            print('SKIP: no', path)
            sys.exit(77)
    names = sys.argv[3:] or sorted(lb.EXAMPLES)
    drv = lb.make_driver()
    try:
        with tempfile.TemporaryDirectory() as outdir:
            for name in names:
                script = os.path.join(src, 'figures', 'interactive',
                                      name + '.lua')
                test_page(drv, tool, script, name, lb.EXAMPLES[name], outdir)
            if not sys.argv[3:]:
                test_spinning_page(drv, tool, src, outdir)
    finally:
        drv.quit()
    if lb.failures:
        sys.exit('%d failures' % len(lb.failures))


main()
