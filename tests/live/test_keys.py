#!/usr/bin/python3
"""The keyboard alone on an interactive figure, in a real browser
(headless Chromium through selenium, as test_browser.py).

usage: test_keys.py CURVEFIG [live|html]...

A script of its own (a cubic Bézier curve, its points P_0..P_3
draggable, de Casteljau's construction at a slider t of step 0.1), served
by `curvefig live` and written by `curvefig render -f html` (computed in
the page by the WebAssembly module).  With key presses only (Tab, the
arrow keys, Shift, End), no pointer and no script in the page:
- Tab reaches the slider t, then the handles of the points in order; the
  focused handle is a slider named P_1 whose aria-valuetext says its
  coordinates;
- the slider: End and ArrowLeft set t = 1 and 0.9;
- P_1: ArrowRight and ArrowUp move it one step (0.1 here: the power of
  ten of data units that is 1 to 10 bp in this figure), Shift+ArrowRight
  ten steps; the Lua text of the values, the aria-valuetext and the
  aria-live announcement say the new coordinates, and the handle keeps
  the focus across the redraw;
- after every key the page's drawing is, element for element, the SVG
  that `curvefig live SCRIPT --once VALUES` renders from the script with
  the page's values (the point at its new coordinates), the page's own
  handles left out.
Skipped (77) without chromium, chromedriver or selenium, or (for html)
without the WebAssembly module.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # (no __pycache__ in the source tree)
import test_browser as tb  # noqa: E402  (skips without selenium)
from selenium.webdriver.common.action_chains import ActionChains  # noqa
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402

SCRIPT = r'''
local t = slider{ name = "t", min = 0, max = 1, default = %s, step = 0.1 }
local P = points{ name = "P", default = { %s } }
local f = figure{ name = "k", width = "8cm", height = "5cm",
                  window = { -0.5, 5.5, -0.5, 3.5 }, page = "fixed" }
local c = bezier(P)
f:polygon(c)
f:curve(c)
f:decasteljau(c, t)
for i = 1, 4 do f:label(P[i], "P_" .. (i - 1)) end
'''


def script_text(t, P):
    return SCRIPT % (repr(t), ', '.join('{%r, %r}' % tuple(q) for q in P))


check = tb.check

# The page's drawing of figure k without the page's handles, serialised
# by the browser; and a static SVG parsed the same way (its ids prefixed
# as the page does).
DRAWING = r'''
var svg = document.querySelector('#cf-figure-k svg').cloneNode(true);
svg.querySelectorAll('.cf-handle, .cf-ring').forEach(function (c) {
  c.remove();
});
return [svg.getAttribute('viewBox'), svg.innerHTML];
'''
PARSED = r'''
var d = document.createElement('div');
d.innerHTML = arguments[0];
var ref = d.querySelector('svg');
return [ref.getAttribute('viewBox'), ref.innerHTML];
'''


def page_ids(svg):
    svg = re.sub(r'<\?xml[^>]*\?>\s*', '', svg)
    svg = re.sub(r'\bid="([^"]*)"', r'id="cf0-\1"', svg)
    svg = re.sub(r'href="#([^"]*)"', r'href="#cf0-\1"', svg)
    return re.sub(r'url\(#([^)]*)\)', r'url(#cf0-\1)', svg)


def page_values(drv):
    """The values the page holds, read from its Lua text."""
    lua = drv.find_element(By.ID, 'cf-lua').text
    t = float(re.search(r'\bt = ([-0-9.e]+)', lua).group(1))
    pts = re.search(r'\bP = \{(.*)\}', lua, re.S).group(1)
    P = [[float(a), float(b)] for a, b in re.findall(
        r'\{([-0-9.e]+), ([-0-9.e]+)\}', pts)]
    return {'t': t, 'P': P}


def compare(what, vals, got, want):
    check(got == want, '%s: the drawing is the static render at %s (%d '
          'and %d characters)' % (what, json.dumps(vals), len(got[1]),
                                  len(want[1])))


def same_as_static(drv, tool, script, what, later):
    """The page's drawing now against the script rendered with the page's
    values: at once for the live view (`curvefig live --once VALUES`, the
    server's renderer); for the course page, later (into the list later),
    against a page of its own, written with those values as the script's
    defaults, which the same WebAssembly module draws."""
    vals = page_values(drv)
    got = drv.execute_script(DRAWING)
    if later is not None:
        later.append((what, vals, got))
        return vals
    out = subprocess.run([tool, 'live', script, '--once', json.dumps(vals)],
                         capture_output=True, text=True)
    check(out.returncode == 0, '%s: the static render %s' % (what,
                                                             out.stderr))
    svg = json.loads(out.stdout)['figures'][0]['svg']
    compare(what, vals, got, drv.execute_script(PARSED, page_ids(svg)))
    return vals


def active_id(drv):
    return drv.execute_script('var a = document.activeElement;'
                              'return a ? a.id : null;')


def keys(drv, *k):
    ActionChains(drv).send_keys(*k).perform()


def shift_key(drv, k):
    ActionChains(drv).key_down(Keys.SHIFT).send_keys(k) \
        .key_up(Keys.SHIFT).perform()


def exercise(drv, tool, script, what, later=None):
    n = tb.settle(drv, 0)
    # Tab to the slider, then to the handles in order
    order = []
    for _ in range(12):
        keys(drv, Keys.TAB)
        order.append(active_id(drv))
        if order[-1] == 'cf-handle-P-1':
            break
    check('cf-slider-t' in order and order.index('cf-slider-t') <
          order.index('cf-handle-P-0') if 'cf-handle-P-0' in order
          else False, '%s: Tab reaches the slider, then P_0 (%s)'
          % (what, order))
    check(order[-1] == 'cf-handle-P-1', '%s: Tab reaches P_1' % what)
    h = drv.switch_to.active_element
    check(h.get_attribute('role') == 'slider' and
          h.get_attribute('aria-valuetext') == 'P_1: x 1, y 2' and
          h.get_attribute('tabindex') == '0',
          '%s: the handle is a slider, "%s"' % (
              what, h.get_attribute('aria-valuetext')))
    ring = drv.execute_script(
        'return getComputedStyle(document.activeElement'
        '.nextElementSibling).strokeWidth;')
    check(ring == '2.2px', '%s: the focused handle\'s ring drawn thick '
          '(%s)' % (what, ring))

    # the slider, by keys: back to it with Shift+Tab
    for _ in range(6):
        if active_id(drv) == 'cf-slider-t':
            break
        ActionChains(drv).key_down(Keys.SHIFT).send_keys(Keys.TAB) \
            .key_up(Keys.SHIFT).perform()
    check(active_id(drv) == 'cf-slider-t', '%s: Shift+Tab back to the '
          'slider' % what)
    keys(drv, Keys.END)
    n = tb.settle(drv, n)
    v = same_as_static(drv, tool, script, what + ': End on t', later)
    check(v['t'] == 1, '%s: End sets t = 1 (%s)' % (what, v['t']))
    keys(drv, Keys.ARROW_LEFT)
    n = tb.settle(drv, n)
    v = same_as_static(drv, tool, script, what + ': ArrowLeft on t',
                       later)
    check(v['t'] == 0.9, '%s: ArrowLeft sets t = 0.9 (%s)' % (what, v['t']))

    # forward to P_1 again
    for _ in range(12):
        if active_id(drv) == 'cf-handle-P-1':
            break
        keys(drv, Keys.TAB)
    check(active_id(drv) == 'cf-handle-P-1', '%s: Tab to P_1 again' % what)
    steps = [(Keys.ARROW_RIGHT, False, [1.1, 2]),
             (Keys.ARROW_UP, False, [1.1, 2.1]),
             (Keys.ARROW_RIGHT, True, [2.1, 2.1]),
             (Keys.ARROW_DOWN, True, [2.1, 1.1])]
    for key, shift, want in steps:
        name = ('Shift+' if shift else '') + {
            Keys.ARROW_RIGHT: 'ArrowRight', Keys.ARROW_UP: 'ArrowUp',
            Keys.ARROW_DOWN: 'ArrowDown'}[key]
        if shift:
            shift_key(drv, key)
        else:
            keys(drv, key)
        n = tb.settle(drv, n)
        v = same_as_static(drv, tool, script, '%s: %s on P_1' % (what, name),
                           later)
        check(v['P'][1] == want and v['P'][0] == [0, 0],
              '%s: %s moves P_1 to %s (%s)' % (what, name, want, v['P']))
        text = 'P_1: x %g, y %g' % tuple(want)
        h = drv.switch_to.active_element
        check(h.get_attribute('id') == 'cf-handle-P-1',
              '%s: P_1 keeps the focus after %s' % (what, name))
        check(h.get_attribute('aria-valuetext') == text and
              drv.find_element(By.ID, 'cf-announce').get_attribute(
                  'textContent') == text,
              '%s: "%s" in aria-valuetext and the live region' % (what,
                                                                   text))
    m = json.loads(drv.find_element(By.ID, 'cf-figure-k')
                   .get_attribute('data-to-svg'))
    want = tb.to_svg(m, [2.1, 1.1])
    got = (float(h.get_attribute('cx')), float(h.get_attribute('cy')))
    check(abs(got[0] - want[0]) < 0.01 and abs(got[1] - want[1]) < 0.01,
          '%s: the handle sits on (2.1, 1.1)' % what)
    tb.check_console(drv, what)


def live(drv, tool, script):
    p = subprocess.Popen([tool, 'live', script, '--port', '0'],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
    try:
        mo = re.search(r'http://\S+/', p.stdout.readline() +
                       p.stdout.readline())
        if mo is None:
            err = p.stderr.read()
            if 'no live view' in err:
                print('SKIP: this build has no live view')
                return
            raise RuntimeError('no URL: ' + err)
        drv.get(mo.group(0))
        exercise(drv, tool, script, 'live')
        drv.get('about:blank')
    finally:
        p.terminate()
        p.wait(10)


def html(drv, tool, script, tmp):
    out = subprocess.run([tool, 'render', script, '-f', 'html', '-o', tmp],
                         capture_output=True, text=True)
    if 'needs the WebAssembly module' in out.stderr:
        print('SKIP: this build has no WebAssembly module')
        return
    check(out.returncode == 0, 'html: -f html %s' % out.stderr)
    drv.get('file://' + os.path.join(tmp, 'k.html'))
    later = []
    exercise(drv, tool, script, 'html', later)
    # each state against a page whose defaults are its values
    for k, (what, vals, got) in enumerate(later):
        d = os.path.join(tmp, 'ref%d' % k)
        os.mkdir(d)
        ref = os.path.join(d, 'k.lua')
        with open(ref, 'w') as f:
            f.write(script_text(vals['t'], vals['P']))
        out = subprocess.run([tool, 'render', ref, '-f', 'html', '-o', d],
                             capture_output=True, text=True)
        check(out.returncode == 0, '%s: -f html of the static %s'
              % (what, out.stderr))
        drv.get('file://' + os.path.join(d, 'k.html'))
        tb.settle(drv, 0)
        compare(what, vals, got, drv.execute_script(DRAWING))
    drv.get('about:blank')


def main():
    tool = os.path.abspath(sys.argv[1])
    which = sys.argv[2:] or ['live', 'html']
    for path in (tb.CHROMIUM, tb.CHROMEDRIVER):
        if not os.access(path, os.X_OK):
            print('SKIP: no', path)
            sys.exit(77)
    drv = tb.make_driver()
    try:
        with tempfile.TemporaryDirectory(prefix='cf-keys-') as tmp:
            script = os.path.join(tmp, 'k.lua')
            with open(script, 'w') as f:
                f.write(script_text(0.5, [[0, 0], [1, 2], [3, 2], [4, 0]]))
            if 'live' in which:
                live(drv, tool, script)
            if 'html' in which:
                html(drv, tool, script, tmp)
    finally:
        drv.quit()
    tb.exit_on_failures()


if __name__ == '__main__':
    main()
