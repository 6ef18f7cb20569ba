#!/usr/bin/python3
"""The live page's sliders and handles in a real browser (headless
Chromium through selenium, as test_browser.py).

usage: test_page.py CURVEFIG

A script of its own (a rational cubic whose middle weight is a log
slider w_1 from 1 to 100, a slider t of step 0.1, four draggable points
labelled P_0..P_3, an automatic legend, no window: the map follows the
points) served by `curvefig live`:
- three steps of 0.1 show and copy as 0.3 (not 0.30000000000000004);
- the log slider's range input holds log10 of the value: its middle is
  w_1 = 10, and the value shown and copied is rounded to the step;
- the slider's label w_1 is typeset: an italic w, a subscript 1;
- a dragged point's coordinates are copied to a tenth of a bp, not 17
  digits;
- while a point is dragged the figure keeps its map (the drawing stands
  still although the point moves the fitted window), and takes its own
  once released;
- a handle dragged far out of the figure stays inside its view;
- no handle's visible paint reaches a label's glyphs;
- the figure fills the page's width (not its print size).
Skipped (77) without chromium, chromedriver or selenium.
"""
import json
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # (no __pycache__ in the source tree)
import test_browser as tb  # noqa: E402  (skips without selenium)
from selenium.webdriver.common.action_chains import ActionChains  # noqa
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402

SCRIPT = r'''
local t = slider{ name = "t", min = 0, max = 1, default = 0, step = 0.1 }
local w = slider{ name = "w1", label = "w_1", min = 1, max = 100,
                  default = 2, step = 0.01, scale = "log" }
local P = points{ name = "P", default = { {0, 0}, {1, 2}, {3, 2}, {4, 0} } }
local f = figure{ name = "s", width = "8cm", height = "6cm" }
local c = bezier{ points = P, weights = { 1, w, 1, 1 } }
f:polygon(c)
f:curve(c, { legend = "$c(t)$" })
f:points({ c:eval(t) }, { legend = "$c(t)$ at the slider" })
for i = 1, 4 do f:label(P[i], "P_" .. (i - 1)) end
'''

check = tb.check


def lua_text(drv):
    return drv.find_element(By.ID, 'cf-lua').text


def page_map(drv):
    return json.loads(drv.find_element(By.ID, 'cf-figure-s')
                      .get_attribute('data-to-svg'))


# The least distance from each visible handle paint (a circle whose fill
# or stroke shows) to a label glyph's box, less its radius: > 0 when no
# handle reaches a glyph.
CLEARANCE = r'''
var svg = document.querySelector('#cf-figure-s svg'), worst = 1e9;
var boxes = [];
svg.querySelectorAll('use').forEach(function (u) {
  if (u.closest('defs')) return;
  var b = u.getBBox();
  if (b.width > 0) boxes.push(b);
});
svg.querySelectorAll('circle').forEach(function (c) {
  var s = getComputedStyle(c);
  var fill = s.fill === 'none' || s.fill === 'transparent' ||
             /rgba\(.*, 0\)$/.test(s.fill) || Number(s.fillOpacity) === 0;
  var stroke = s.stroke === 'none' || parseFloat(s.strokeWidth) === 0;
  if (fill && stroke) return;
  var r = Number(c.getAttribute('r')) +
          (stroke ? 0 : parseFloat(s.strokeWidth) / 2);
  var x = Number(c.getAttribute('cx')), y = Number(c.getAttribute('cy'));
  boxes.forEach(function (b) {
    var dx = Math.max(b.x - x, 0, x - b.x - b.width);
    var dy = Math.max(b.y - y, 0, y - b.y - b.height);
    worst = Math.min(worst, Math.hypot(dx, dy) - r);
  });
});
return [worst, boxes.length];
'''


def exercise(drv, tool):
    n = tb.settle(drv, 0)
    # three steps of 0.1
    slider = drv.find_element(By.ID, 'cf-slider-t')
    for _ in range(3):
        slider.send_keys(Keys.ARROW_RIGHT)
        n = tb.settle(drv, n)
    shown = drv.find_element(By.ID, 'cf-value-t').text
    lua = lua_text(drv)
    check(shown == '0.3' and re.search(r'\bt = 0\.3[,\n]', lua + '\n')
          and '0000' not in lua,
          'three steps of 0.1: shown %r, copied %r' % (shown, lua))

    # the log slider: its middle is 10
    w = drv.find_element(By.ID, 'cf-slider-w1')
    check(w.get_attribute('min') == '0' and w.get_attribute('max') == '2',
          'log slider range 0..2 (log10): %s..%s'
          % (w.get_attribute('min'), w.get_attribute('max')))
    drv.execute_script('arguments[0].value = 1; arguments[0].dispatchEvent('
                       'new Event("input")); arguments[0].dispatchEvent('
                       'new Event("change"));', w)
    n = tb.settle(drv, n)
    check(re.search(r'\bw1 = 10[,\n]', lua_text(drv) + '\n') is not None
          and drv.find_element(By.ID, 'cf-value-w1').text == '10',
          'the log slider in the middle: w1 = 10 (%r)' % lua_text(drv))
    drv.execute_script('arguments[0].value = 0.5; arguments[0].dispatchEvent('
                       'new Event("input")); arguments[0].dispatchEvent('
                       'new Event("change"));', w)
    n = tb.settle(drv, n)
    check(re.search(r'\bw1 = 3\.16[,\n]', lua_text(drv) + '\n') is not None,
          'log10 = 0.5: w1 = 3.16, rounded to the step (%r)'
          % lua_text(drv))

    # the label typeset
    lab = drv.find_element(By.CSS_SELECTOR, 'label[for="cf-slider-w1"]')
    html = lab.get_attribute('innerHTML')
    check('<i>w</i><sub>1</sub>' in html, 'the label w_1 typeset: %r' % html)

    # no handle paint on a label's glyphs
    clear, nbox = drv.execute_script(CLEARANCE)
    check(nbox > 0 and clear > 0, 'no handle reaches a label glyph (%d '
          'glyphs, nearest %.2f bp)' % (nbox, clear))

    # the figure fills the width
    size = drv.execute_script(
        'var s = document.querySelector("#cf-figure-s svg");'
        'return [s.getBoundingClientRect().width,'
        ' s.viewBox.baseVal.width * 4 / 3];')
    check(size[0] > 1.5 * size[1], 'the figure scaled to the window: %.0f '
          'px wide, %.0f px at print size' % tuple(size))

    # a drag: the map held while dragging, values rounded
    before = page_map(drv)
    handle = drv.find_element(By.ID, 'cf-handle-P-3')
    chain = ActionChains(drv).move_to_element(handle).click_and_hold()
    chain.perform()
    held = []
    for _ in range(4):
        ActionChains(drv).move_by_offset(-30, -20).perform()
        n = tb.settle(drv, n)
        held.append(page_map(drv))
    check(all(m == before for m in held), 'the map stays still while the '
          'point is dragged (%s vs %s)' % (held, before))
    ActionChains(drv).release().perform()
    time.sleep(0.3)
    n = tb.settle(drv, n - 1)
    after = page_map(drv)
    check(after != before, 'released, the figure takes its own map')
    lua = lua_text(drv)
    nums = re.findall(r'-?\d+\.(\d+)', lua)
    check(nums and max(len(d) for d in nums) <= 4,
          'the dragged point copied to a tenth of a bp: %r' % lua)

    # far out of the figure: the handle stays in the view
    handle = drv.find_element(By.ID, 'cf-handle-P-0')
    ActionChains(drv).move_to_element(handle).click_and_hold() \
        .move_by_offset(-250, 150).perform()
    n = tb.settle(drv, n)
    inside = drv.execute_script(
        'var s = document.querySelector("#cf-figure-s svg"),'
        ' h = document.getElementById("cf-handle-P-0"),'
        ' v = s.viewBox.baseVal, x = Number(h.getAttribute("cx")),'
        ' y = Number(h.getAttribute("cy"));'
        'return [x >= v.x && x <= v.x + v.width && y >= v.y &&'
        ' y <= v.y + v.height, x, y, v.width, v.height];')
    check(inside[0], 'a handle dragged out stays in the view: %s' % inside)
    ActionChains(drv).release().perform()
    time.sleep(0.3)
    tb.settle(drv, n - 1)
    tb.check_console(drv)


def main():
    tool = os.path.abspath(sys.argv[1])
    for path in (tb.CHROMIUM, tb.CHROMEDRIVER):
        if not os.access(path, os.X_OK):
            print('SKIP: no', path)
            sys.exit(77)
    tmp = tempfile.mkdtemp(prefix='cf-page-')
    script = os.path.join(tmp, 'page.lua')
    with open(script, 'w') as f:
        f.write(SCRIPT)
    p = subprocess.Popen([tool, 'live', script, '--port', '0'],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
    drv = None
    try:
        mo = re.search(r'http://\S+/', p.stdout.readline() +
                       p.stdout.readline())
        if mo is None:
            err = p.stderr.read()
            if 'no live view' in err:
                print('SKIP: this build has no live view')
                sys.exit(77)
            raise RuntimeError('no URL: ' + err)
        drv = tb.make_driver()
        drv.get(mo.group(0))
        exercise(drv, tool)
        drv.get('about:blank')
    finally:
        if drv is not None:
            drv.quit()
        p.terminate()
        p.wait(10)
        os.unlink(script)
        os.rmdir(tmp)
    tb.exit_on_failures()


if __name__ == '__main__':
    main()
