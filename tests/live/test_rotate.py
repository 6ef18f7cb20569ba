#!/usr/bin/python3
"""Turning a 3D figure in the page, in a real browser (headless Chromium).

usage: test_rotate.py CURVEFIG SOURCE_DIR

figures/interactive/surface-patch.lua (a bicubic patch, sliders u and v,
a draggable label point L), in the page of `curvefig live` and in the
course page of -f html (opened from the file; skipped without the
WebAssembly module):

- at load the figure shows the script's view (data-view [-55, 28]) and
  its drawing is `curvefig render`'s (the same paths, live);
- while the pointer holds the background and has moved, the drawing is a
  draft (data-draft "1"; when an exact run takes over the page's
  data-draft-after-ms, 16 ms, as it does here, else exact); released where it was pressed, the exact
  drawing of the script's view follows (data-draft "0", curvefig
  render's paths);
- a pointer drag of the background turns it by 0.4 degree a pixel: the
  page reports the new azimuth and elevation, and its drawing is that of
  a static `curvefig render` of the script with view = {azimuth,
  elevation} written in: in live the same path data, byte for byte; in
  the course page (computed by the WebAssembly module, glyphs as outline
  paths) the same pixels, both drawn into a canvas by the browser, while
  the render at the script's view differs in many pixels;
- the arrow keys turn the focused figure 5 degrees a press; the time of
  a redraw after a key press is printed (median of 4); a key held down
  (repeating) turns it as a drag does: drafts while it repeats (when an
  exact run takes over 16 ms), the exact drawing of the view reached
  when it goes up;
- the handle of L still drags in the turned figure: L moves, the view
  stays;
- a double click on the background goes back to the script's view, and
  the click focused the figure: Right turns it 5 degrees; its button
  "Reset view" goes back again;
- in the course page of a 2D figure (decasteljau) a drag of the
  background changes nothing (no run, the same drawing).

The console stays free of errors.  Skipped (77) without chromium,
chromedriver or selenium.
"""
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # (no __pycache__ in the source tree)
import test_browser as lb  # noqa: E402  (skips, 77, without selenium)
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

NAME = 'surface-patch'
SCRIPT_VIEW = [-55, 28]
DEG_PER_PX = 0.4

# In the page: the figure's SVG without the handles and the static SVG
# arguments[0], each drawn by the browser into a W x H canvas
# (arguments[2], [3]); the number of pixels whose channels differ by more
# than 48 of 255.
RASTER = r'''
var done = arguments[arguments.length - 1];
var box = document.getElementById('cf-figure-' + arguments[1]);
var svg = box.querySelector('svg').cloneNode(true);
svg.querySelectorAll('.cf-handle, .cf-ring').forEach(function (e) {
  e.remove(); });
var W = arguments[2], H = arguments[3];
function raster(text) {
  return new Promise(function (res, rej) {
    var img = new Image();
    img.onload = function () {
      var c = document.createElement('canvas');
      c.width = W; c.height = H;
      var g = c.getContext('2d');
      g.fillStyle = '#fff'; g.fillRect(0, 0, W, H);
      g.drawImage(img, 0, 0, W, H);
      res(g.getImageData(0, 0, W, H).data);
    };
    img.onerror = function () { rej('the image did not load'); };
    img.src = 'data:image/svg+xml;charset=utf-8,' + encodeURIComponent(text);
  });
}
Promise.all([raster(new XMLSerializer().serializeToString(svg)),
             raster(arguments[0])]).then(function (r) {
  var bad = 0;
  for (var i = 0; i < r[0].length; i += 4)
    for (var k = 0; k < 3; k++)
      if (Math.abs(r[0][i + k] - r[1][i + k]) > 48) { bad++; break; }
  done(bad);
}, function (e) { done(String(e)); });
'''

# In the page: the time from a key press on the figure to the redraw it
# causes (ms), measured with the page's clock.
KEY_TIME = r'''
var done = arguments[arguments.length - 1];
var root = document.getElementById('curvefig');
var box = document.getElementById('cf-figure-' + arguments[0]);
var runs = Number(root.dataset.runs), t0 = performance.now();
var seen = new MutationObserver(function () {
  if (Number(root.dataset.runs) > runs && root.dataset.busy === '0') {
    seen.disconnect();
    done(performance.now() - t0);
  }
});
seen.observe(root, { attributes: true });
box.focus();
box.dispatchEvent(new KeyboardEvent('keydown', { key: arguments[1],
                                                 bubbles: true }));
'''

# A key event of kind arguments[2] ('keydown' or 'keyup', repeating when
# arguments[3]) for key arguments[1] on figure arguments[0], focused.
KEY_EVENT = r'''
var box = document.getElementById('cf-figure-' + arguments[0]);
if (document.activeElement !== box) box.focus();
box.dispatchEvent(new KeyboardEvent(arguments[2], { key: arguments[1],
                                                   repeat: arguments[3],
                                                   bubbles: true }));
'''


def quiet(drv, n, timeout=20):
    """Wait until the page has drawn past n runs and stays idle 0.3 s."""
    n = lb.settle(drv, n, timeout)
    while True:
        time.sleep(0.3)
        m = lb.runs(drv)
        busy = drv.execute_script(
            'return document.getElementById("curvefig").dataset.busy;')
        if m == n and busy == '0':
            return n
        n = lb.settle(drv, m - 1 if busy == '0' else m, timeout)


def slow_runs(drv):
    """Whether the last exact run took longer than the page's threshold of
    drafts (data-exact-ms > data-draft-after-ms): drags draw drafts."""
    return drv.execute_script(
        'var d = document.getElementById("curvefig").dataset;'
        'return Number(d.exactMs) > Number(d.draftAfterMs);')


def draft(drv):
    return drv.execute_script(
        'return document.getElementById("curvefig").dataset.draft;')


def view(drv):
    return json.loads(drv.find_element(By.ID, 'cf-figure-' + NAME)
                      .get_attribute('data-view'))


def paths(svg):
    return re.findall(r'<path\b[^>]*?\sd="([^"]*)"', svg)


def static_svg(tool, text, az, el, outdir):
    """The SVG of `curvefig render` of the script with view = {az, el}."""
    d = tempfile.mkdtemp(dir=outdir)
    path = os.path.join(d, NAME + '.lua')
    with open(path, 'w', encoding='utf-8') as f:
        f.write(text.replace('view = { %d, %d }' % tuple(SCRIPT_VIEW),
                             'view = { %r, %r }' % (az, el)))
    out = subprocess.run([tool, 'render', path, '-f', 'svg', '-o', d],
                         capture_output=True, text=True)
    lb.check(out.returncode == 0, 'render at view {%r, %r} %s'
             % (az, el, out.stderr))
    with open(os.path.join(d, NAME + '.svg'), encoding='utf-8') as f:
        return f.read()


def same_drawing(drv, what, svg_static, exact):
    """The page's figure against a static SVG: the same path data (live,
    exact) or the same pixels (the course page); the number of bad
    pixels."""
    page = lb.figure_svg(drv, NAME)
    if exact:
        return paths(page) == paths(svg_static) and paths(page) != []
    box = [float(v) for v in re.search(r'viewBox="([^"]*)"',
                                       svg_static).group(1).split()]
    return drv.execute_async_script(RASTER, svg_static, NAME,
                                    int(2 * box[2]), int(2 * box[3]))


def background_drag(drv, dx, dy):
    """Press near the figure's upper right corner (no handle there; the
    button "Reset view" of a turned figure is above), move by (dx, dy) in
    three steps, release."""
    svg = drv.find_element(By.CSS_SELECTOR, '[id="cf-figure-%s"] svg'
                           % NAME)
    size = svg.size
    ActionChains(drv).move_to_element_with_offset(
        svg, size['width'] // 2 - 12, 50 - size['height'] // 2) \
        .click_and_hold().move_by_offset(dx // 3, dy // 3) \
        .move_by_offset(dx // 3, dy // 3) \
        .move_by_offset(dx - 2 * (dx // 3), dy - 2 * (dy // 3)) \
        .release().perform()


def exercise(drv, tool, text, what, exact, outdir):
    drv.set_script_timeout(20)
    n = quiet(drv, 0)
    lb.check(view(drv) == SCRIPT_VIEW, '%s: the figure shows the script\'s '
             'view %s' % (what, view(drv)))
    first = lb.figure_svg(drv, NAME)
    script_svg = static_svg(tool, text, *SCRIPT_VIEW, outdir)
    if exact:
        lb.check(same_drawing(drv, what, script_svg, True),
                 '%s: at load, the drawing is curvefig render\'s' % what)

    # a drag under way draws drafts; the release, the exact run
    svg = drv.find_element(By.CSS_SELECTOR, '[id="cf-figure-%s"] svg'
                           % NAME)
    size = svg.size
    hold = ActionChains(drv)
    hold.move_to_element_with_offset(
        svg, size['width'] // 2 - 12, 50 - size['height'] // 2) \
        .click_and_hold().move_by_offset(-10, 5).perform()
    n = quiet(drv, n)
    slow = slow_runs(drv)
    lb.check(draft(drv) == ('1' if slow else '0'), '%s: while the pointer '
             'holds the figure, the drawing is a draft when an exact run '
             'takes over data-draft-after-ms (data-draft %r)' % (what, draft(drv)))
    ActionChains(drv).move_by_offset(10, -5).release().perform()
    n = quiet(drv, n)
    lb.check(draft(drv) == '0' and view(drv) == SCRIPT_VIEW,
             '%s: released, the exact run is drawn (data-draft %r, view %s)'
             % (what, draft(drv), view(drv)))
    if exact:
        lb.check(same_drawing(drv, what, script_svg, True),
                 '%s: ... and it is curvefig render\'s again' % what)

    # a drag of the background
    background_drag(drv, -60, 30)
    n = quiet(drv, n)
    lb.check(draft(drv) == '0', '%s: after the drag the drawing is exact'
             % what)
    v = view(drv)
    want = [SCRIPT_VIEW[0] + 60 * DEG_PER_PX, SCRIPT_VIEW[1] + 30 *
            DEG_PER_PX]
    lb.check(abs(v[0] - want[0]) < 1 and abs(v[1] - want[1]) < 1,
             '%s: the drag turned the figure to %s (about %s)'
             % (what, v, want))
    lb.check(lb.figure_svg(drv, NAME) != first, '%s: the drawing changed'
             % what)
    turned = static_svg(tool, text, v[0], v[1], outdir)
    if exact:
        lb.check(same_drawing(drv, what, turned, True),
                 '%s: the same paths as curvefig render with view = '
                 '{%r, %r}' % (what, v[0], v[1]))
    else:
        bad = same_drawing(drv, what, turned, False)
        off = same_drawing(drv, what, script_svg, False)
        lb.check(bad == 0 and isinstance(off, int) and off > 500,
                 '%s: the same pixels as curvefig render with view = '
                 '{%r, %r}: %s bad (%s against the script\'s view)'
                 % (what, v[0], v[1], bad, off))
    lua = drv.find_element(By.ID, 'cf-lua').text
    lb.check('-- %s: view = { %s, %s }' % (NAME, _num(v[0]), _num(v[1]))
             in lua, '%s: the values show the view as Lua' % what)

    # the arrow keys, timed
    times = []
    for k in range(4):
        key = 'ArrowLeft' if k % 2 == 0 else 'ArrowUp'
        times.append(drv.execute_async_script(KEY_TIME, NAME, key))
    n = quiet(drv, lb.runs(drv) - 1)
    v2 = view(drv)
    lb.check(abs(v2[0] - (v[0] + 10)) < 1e-9 and abs(v2[1] - (v[1] - 10))
             < 1e-9, '%s: two Left and two Up turned it to %s' % (what, v2))
    print('     %s: a redraw after a key press: %.0f ms median (%.0f to '
          '%.0f)' % (what, statistics.median(times), min(times), max(times)))

    # a key held down: a press, then repeats (drafts), then up (exact);
    # in the course page the browser's processor is slowed down six times
    # (DevTools' emulation), so that the module's exact runs take over
    # 16 ms and the repeats are drafts however fast this machine is
    if not exact:
        drv.execute_cdp_cmd('Emulation.setCPUThrottlingRate', {'rate': 6})
    drv.execute_script(KEY_EVENT, NAME, 'ArrowLeft', 'keydown', False)
    n = quiet(drv, n)
    slow = slow_runs(drv)
    lb.check(exact or slow, '%s: slowed down, an exact run takes over '
             'data-draft-after-ms' % what)
    for k in range(3):
        drv.execute_script(KEY_EVENT, NAME, 'ArrowLeft', 'keydown', True)
        n = quiet(drv, n)
    v3 = view(drv)
    lb.check(abs(v3[0] - (v2[0] + 20)) < 1e-9 and v3[1] == v2[1] and
             draft(drv) == ('1' if slow else '0'),
             '%s: Left held (a press, three repeats) turned it to %s, '
             'drawn as a draft when an exact run takes over the '
             'threshold '
             '(data-draft %r)' % (what, v3, draft(drv)))
    drv.execute_script(KEY_EVENT, NAME, 'ArrowLeft', 'keyup', False)
    if slow:
        n = quiet(drv, n)
    lb.check(draft(drv) == '0' and view(drv) == v3,
             '%s: the key up: the exact drawing (data-draft %r)'
             % (what, draft(drv)))
    if not exact:
        drv.execute_cdp_cmd('Emulation.setCPUThrottlingRate', {'rate': 1})
    same = same_drawing(drv, what, static_svg(tool, text, v3[0], v3[1],
                                              outdir), exact)
    lb.check(same is True if exact else same == 0,
             '%s: ... the drawing of curvefig render with view = {%r, %r} '
             '(%r)' % (what, v3[0], v3[1], same))
    v2 = v3   # (the handle's drag below keeps this view)

    # the label's handle still drags, the view stays
    old_lua = drv.find_element(By.ID, 'cf-lua').text
    handle = drv.find_element(By.ID, 'cf-handle-L-0')
    ActionChains(drv).move_to_element(handle).click_and_hold() \
        .move_by_offset(20, 10).move_by_offset(20, 10).release().perform()
    n = quiet(drv, n)
    lua = drv.find_element(By.ID, 'cf-lua').text
    lb.check(re.search(r'L = \{.*\}', lua).group(0) !=
             re.search(r'L = \{.*\}', old_lua).group(0) and view(drv) == v2,
             '%s: the handle of L dragged (%s), the view kept'
             % (what, re.search(r'L = \{.*\}', lua).group(0)))

    # a double click goes back to the script's view
    svg = drv.find_element(By.CSS_SELECTOR, '[id="cf-figure-%s"] svg' % NAME)
    size = svg.size
    ActionChains(drv).move_to_element_with_offset(
        svg, size['width'] // 2 - 12, 50 - size['height'] // 2) \
        .double_click().perform()
    n = quiet(drv, n)
    lb.check(view(drv) == SCRIPT_VIEW, '%s: a double click: the script\'s '
             'view again' % what)
    # the click focused the figure: a real key press turns it
    ActionChains(drv).send_keys(Keys.ARROW_RIGHT).perform()
    quiet(drv, n)
    n = quiet(drv, n)
    lb.check(view(drv) == [SCRIPT_VIEW[0] - 5, SCRIPT_VIEW[1]],
             '%s: clicked, then Right: %s' % (what, view(drv)))
    # the button of a turned figure
    drv.find_element(By.CSS_SELECTOR, '[id="cf-figure-%s"] '
                     'button.cf-view-reset' % NAME).click()
    quiet(drv, n)
    lb.check(view(drv) == SCRIPT_VIEW and drv.find_elements(
        By.CSS_SELECTOR, 'button.cf-view-reset') == [],
        '%s: "Reset view": the script\'s view, the button gone' % what)
    lb.check_console(drv, what)


def _num(x):
    """x as JavaScript's String(x) writes a tenth of a degree."""
    return str(int(x)) if x == int(x) else repr(x)


def flat_drag(drv, outdir, tool, src):
    """A 2D figure's page: a background drag changes nothing."""
    name = 'decasteljau'
    out = subprocess.run([tool, 'render', os.path.join(
        src, 'figures', 'interactive', name + '.lua'), '-f', 'html', '-o',
        outdir], capture_output=True, text=True)
    lb.check(out.returncode == 0, '2D: -f html %s' % out.stderr)
    drv.get('file://' + os.path.join(outdir, name + '.html'))
    n = quiet(drv, 0)
    before = lb.figure_svg(drv, name)
    box = drv.find_element(By.ID, 'cf-figure-' + name)
    svg = box.find_element(By.TAG_NAME, 'svg')
    lb.check('cf-3d' not in box.get_attribute('class') and
             box.get_attribute('data-view') is None,
             '2D: the figure is not marked as turnable')
    size = svg.size
    ActionChains(drv).move_to_element_with_offset(
        svg, size['width'] // 2 - 12, 50 - size['height'] // 2) \
        .click_and_hold().move_by_offset(-40, 20).move_by_offset(-40, 20) \
        .release().perform()
    time.sleep(0.5)
    lb.check(lb.runs(drv) == n and lb.figure_svg(drv, name) == before,
             '2D: a drag of the background changed nothing (%d runs)'
             % (lb.runs(drv) - n))
    drv.get('about:blank')


def live(drv, tool, script, text, outdir):
    p, url = lb.start_live(tool, script)
    try:
        if url is None:
            print('SKIP (live): this build has no live view')
            return
        drv.get(url)
        exercise(drv, tool, text, 'live', True, outdir)
        drv.get('about:blank')
    finally:
        p.terminate()
        p.wait(10)


def html(drv, tool, script, text, outdir, src):
    out = subprocess.run([tool, 'render', script, '-f', 'html', '-o',
                          outdir], capture_output=True, text=True)
    if 'needs the WebAssembly module' in out.stderr:
        print('SKIP (html): this build has no WebAssembly module')
        return
    lb.check(out.returncode == 0, 'html: -f html %s' % out.stderr)
    drv.get('file://' + os.path.join(outdir, NAME + '.html'))
    exercise(drv, tool, text, 'html', False, outdir)
    drv.get('about:blank')
    flat_drag(drv, outdir, tool, src)


def main():
    tool, src = os.path.abspath(sys.argv[1]), sys.argv[2]
    lb.need_browser()
    script, text = lb.example(src, NAME)
    drv = lb.make_driver()
    try:
        with tempfile.TemporaryDirectory() as outdir:
            live(drv, tool, script, text, outdir)
            html(drv, tool, script, text, outdir, src)
    finally:
        drv.quit()
    lb.exit_on_failures()


if __name__ == '__main__':
    main()
