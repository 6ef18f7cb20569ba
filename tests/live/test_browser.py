#!/usr/bin/python3
"""The live page in a real browser (headless Chromium through selenium).

usage: test_browser.py CURVEFIG SOURCE_DIR [EXAMPLE...]

For every shipped interactive example (figures/interactive/*.lua):
`curvefig live` on a free port, the page loaded; then a slider is moved
(PageUp on it, a real key press) and a control point dragged (a real
pointer drag), and after each the drawing must show what the core
computes for the values the page now holds: the page's own Lua text of
the values is run by `curvefig run` with a line of the curve library
(C(u) of the B-spline, b_0^4(t), the offset point, ...), the point mapped
into the SVG by the figure's map, and a mark (a marker's outline) or a
curve of the page's SVG must lie there -- and must not have lain there
before the change.  The dragged handle must sit on its new value.  The
browser's console must stay free of errors.  A hostile script (a slider
that drives `xpcall(error, function() while true do end end)`, the
instruction limit out of reach) must stop with the time-limit error in
the page within the limit, the tab answering all the while, and the page
must draw again when the slider moves back.  Skipped (77) without
chromium, chromedriver or selenium.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
except ImportError:
    print('SKIP: no selenium for', sys.executable)
    sys.exit(77)

CHROMIUM = '/usr/bin/chromium'
CHROMEDRIVER = '/usr/bin/chromedriver'

# per example: the slider moved and the point the core computes for it
# ('mark': a marker is drawn there; 'curve': a curve passes there); the
# point dragged (param, index) and a point of the curve after the drag.
SPLINE = 'bspline{ degree = %d, knots = %s, points = P }'
U3 = '{ 0, 0, 0, 0, 0.25, 0.4, 0.7, 0.85, 1, 1, 1, 1 }'
U2 = '{ 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }'
# S(u, v) of surface-patch.lua's patch (its box's middle at the origin)
# in the image of its view {-55, 28} (docs/surfaces.md: (ex . S, ey . S))
PATCH = ('(function () local P = { {{0, 0, 0}, {0, 1, 0.6}, {0, 2, 0.6}, '
         '{0, 3, 0}}, {{1, 0, 0.7}, {1, 1, 1.8}, {1, 2, 1.6}, {1, 3, 0.4}}, '
         '{{2, 0, 0.6}, {2, 1, 1.5}, {2, 2, 2.0}, {2, 3, 0.7}}, {{3, 0, 0}, '
         '{3, 1, 0.5}, {3, 2, 0.8}, {3, 3, 0.2}} } '
         'local S = bezier_surface{ points = P }:eval(u, v) '
         'local x, y, z = S[1] - 1.5, S[2] - 1.5, S[3] - 0.9 '
         'local a, e = math.rad(-55), math.rad(28) '
         'return { -math.sin(a) * x + math.cos(a) * y, -math.cos(a) * '
         'math.sin(e) * x - math.sin(a) * math.sin(e) * y + math.cos(e) * z } '
         'end)()')
EXAMPLES = {
    'rational-5.4.1': dict(
        slider='w4', slider_kind='curve',
        slider_point='bezier{ points = P, weights = { w0, w1, w2, w3, w4, '
                     'w5, w6, w7 } }:eval(0.45)',
        drag=('P', 5), drag_point='bezier(P):eval(0.6)'),
    'decasteljau': dict(
        slider='t', slider_kind='mark', slider_point='bezier(P):eval(t)',
        drag=('P', 2), drag_point='bezier(P):eval(0.4)'),
    'deboor': dict(
        slider='u', slider_kind='mark',
        slider_point=SPLINE % (3, U3) + ':eval(u)',
        drag=('P', 3), drag_point=SPLINE % (3, U3) + ':eval(0.45)'),
    'knot-insertion': dict(
        slider='u', slider_kind='mark',
        slider_point=SPLINE % (2, U2) + ':eval(u)',
        drag=('P', 4), drag_point=SPLINE % (2, U2) + ':eval(0.5)'),
    'surface-patch': dict(
        slider='u', slider_kind='mark', slider_point=PATCH,
        drag=('L', 0), drag_point='L[1]'),
    'offset': dict(
        slider='d', slider_kind='curve',
        slider_point='bezier(P):offset_point(0.85, d)',
        drag=('P', 3), drag_point='bezier(P):eval(0.7)'),
}

# In the page: the least distance from (x, y) (SVG units) to a curve of
# the figure's SVG, and whether a mark (a small outline) covers it.
PROBE = r'''
var svg = document.getElementById('cf-figure-' + arguments[0])
  .querySelector('svg');
var x = arguments[1], y = arguments[2], best = 1e9, mark = false;
svg.querySelectorAll('path').forEach(function (p) {
  if (p.closest('symbol') || p.closest('clipPath')) return;
  var b = p.getBBox();
  if (b.width < 20 && b.height < 20 && b.width + b.height > 0 &&
      x >= b.x - 0.5 && x <= b.x + b.width + 0.5 &&
      y >= b.y - 0.5 && y <= b.y + b.height + 0.5) mark = true;
  var n = p.getTotalLength();
  if (!(n > 0)) return;
  for (var s = 0; s <= n; s += 0.1) {
    var q = p.getPointAtLength(s);
    best = Math.min(best, Math.hypot(q.x - x, q.y - y));
  }
});
return [best, mark];
'''

failures = []


def check(cond, what):
    print(('ok   ' if cond else 'FAIL ') + what)
    if not cond:
        failures.append(what)


def example(src, name):
    """The shipped interactive example NAME: its path and its text."""
    script = os.path.join(src, 'figures', 'interactive', name + '.lua')
    with open(script, encoding='utf-8') as f:
        return script, f.read()


def exit_on_failures():
    """Exit with the number of failed checks, if any."""
    if failures:
        sys.exit('%d failures' % len(failures))


def check_console(drv, what=None):
    """No error or warning in the browser's console since the last look."""
    logs = [e for e in drv.get_log('browser')
            if e['level'] in ('SEVERE', 'WARNING')]
    check(logs == [], '%sno console errors %s'
          % (what + ': ' if what else '', logs))


def core_point(tool, lua_values, expr):
    """The point expr of the curve library for the page's values."""
    code = (lua_values + '\nfor k, v in pairs(values) do _ENV[k] = v end\n'
            'local p = ' + expr + '\nprint(string.format("%.17g %.17g", '
            'p[1], p[2]))\n')
    path = '/tmp/cf-browser-%d.lua' % os.getpid()
    with open(path, 'w') as f:
        f.write(code)
    out = subprocess.run([tool, 'run', path], capture_output=True,
                         text=True)
    os.unlink(path)
    if out.returncode != 0:
        raise RuntimeError(out.stderr)
    return [float(v) for v in out.stdout.split()]


def to_svg(m, p):
    return (m[0] * p[0] + m[2] * p[1] + m[4],
            m[1] * p[0] + m[3] * p[1] + m[5])


def settle(drv, runs_before, timeout=20):
    end = time.time() + timeout
    while time.time() < end:
        state = drv.execute_script(
            'var r = document.getElementById("curvefig");'
            'return [Number(r.dataset.runs || 0), r.dataset.busy];')
        if state[0] > runs_before and state[1] == '0':
            return state[0]
        time.sleep(0.05)
    raise RuntimeError('the page did not redraw within %d s: %s; its '
                       'console: %s' % (timeout, page_state(drv),
                                        drv.get_log('browser')))


def page_state(drv):
    """What the page shows, for a message: its runs, busy and draft
    flags, the error line, the address."""
    return drv.execute_script(
        'var r = document.getElementById("curvefig");'
        'var e = document.getElementById("cf-error");'
        'return JSON.stringify({runs: r && r.dataset.runs, busy: r && '
        'r.dataset.busy, draft: r && r.dataset.draft, error: e && !e.hidden '
        '? e.textContent : null, url: location.href});')


def runs(drv):
    return drv.execute_script(
        'return Number(document.getElementById("curvefig").dataset.runs '
        '|| 0);')


def probe(drv, fig, pt):
    return drv.execute_script(PROBE, fig, pt[0], pt[1])


def figure_svg(drv, name):
    return drv.execute_script(
        'return document.getElementById("cf-figure-" + arguments[0])'
        '.querySelector("svg").outerHTML;', name)


def core_moved(tool, old_m, old_lua, m, lua, expr, name):
    """The core's point moved visibly between the old and the new values
    (so that finding it drawn says the drawing followed)."""
    a = to_svg(old_m, core_point(tool, old_lua, expr))
    b = to_svg(m, core_point(tool, lua, expr))
    d = ((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5
    check(d > 2, '%s: ... the core\'s point moved %.1f units' % (name, d))


def page_map(drv, name):
    """The figure's map data -> SVG units, as the page holds it (the map
    moves with the margins the labels need)."""
    return json.loads(drv.find_element(By.ID, 'cf-figure-' + name)
                      .get_attribute('data-to-svg'))


def verify(drv, tool, name, kind, expr, what):
    """The drawing shows the core's point for the page's values now."""
    lua = drv.find_element(By.ID, 'cf-lua').text
    m = page_map(drv, name)
    pt = to_svg(m, core_point(tool, lua, expr))
    dist, mark = probe(drv, name, pt)
    if kind == 'mark':
        check(mark, '%s: %s: a mark at the core\'s point (%.2f, %.2f)'
              % (name, what, pt[0], pt[1]))
    else:
        check(dist < 0.2, '%s: %s: a curve through the core\'s point '
              '(%.2f, %.2f), %.3f away' % (name, what, pt[0], pt[1], dist))
    return pt, lua


def check_aria(drv, name):
    """The figure labelled by its SVG's title, its description in the page,
    every slider named by its label's text with its value said as shown
    (docs/accessibility.md)."""
    got = drv.execute_script("""
      var box = document.getElementById('cf-figure-' + arguments[0]);
      var svg = box.querySelector('svg'), desc = svg.querySelector('desc');
      var d = box.querySelector('details.cf-description p');
      var ids = (svg.getAttribute('aria-labelledby') || '').split(' ');
      return { role: svg.getAttribute('role'),
        title: ids.map(function (i) {
          var e = document.getElementById(i);
          return e && e.tagName === 'title' ? e.textContent : ''; }),
        box: [box.getAttribute('role'), box.getAttribute('aria-labelledby'),
              svg.getAttribute('aria-labelledby')],
        details: d ? d.textContent : null,
        desc: desc ? desc.textContent : null,
        sliders: Array.prototype.map.call(
          document.querySelectorAll('#cf-controls input[type=range]'),
          function (s) {
            return [s.getAttribute('aria-label'),
                    s.getAttribute('aria-valuetext'),
                    document.getElementById('cf-value-' + s.dataset.param)
                      .textContent, s.dataset.param]; }) };""", name)
    check(got['role'] == 'img' and got['title'] != []
          and all(got['title']),
          '%s: the SVG is an image labelled by its <title> %s'
          % (name, got['title']))
    check(got['box'][0] == 'figure' and got['box'][1] == got['box'][2],
          '%s: the figure box is labelled by the title %s' % (name,
                                                             got['box']))
    check(got['details'] is not None and got['details'] == got['desc'],
          '%s: the description is in the page' % name)
    for label, said, shown, param in got['sliders']:
        check(label and not re.search(r'[\\{}$]', label) and said == shown,
              '%s: slider %s named "%s", value said %s as shown %s'
              % (name, param, label, said, shown))


def exercise(drv, tool, name, spec, native):
    """On the loaded page: the slider, then the drag, each checked against
    the core; native is the JSON of a run at the defaults."""
    n = settle(drv, 0)
    check(drv.find_elements(By.CSS_SELECTOR,
                               '[id="cf-figure-%s"] svg' % name)
          != [], '%s: the page shows the figure' % name)
    check_aria(drv, name)

    # the slider
    old_lua = drv.find_element(By.ID, 'cf-lua').text
    old_svg = figure_svg(drv, name)
    old_m = page_map(drv, name)
    slider = drv.find_element(By.ID, 'cf-slider-' + spec['slider'])
    before = slider.get_attribute('value')
    slider.send_keys(Keys.PAGE_UP)
    n = settle(drv, n)
    after = drv.find_element(By.ID, 'cf-slider-' + spec['slider']) \
        .get_attribute('value')
    check(after != before, '%s: slider %s moved %s -> %s'
          % (name, spec['slider'], before, after))
    pt, lua = verify(drv, tool, name, spec['slider_kind'],
                     spec['slider_point'], 'slider ' + spec['slider'])
    check(lua != old_lua and figure_svg(drv, name) != old_svg,
          '%s: the drawing and the Lua text changed' % name)
    core_moved(tool, old_m, old_lua, page_map(drv, name), lua,
               spec['slider_point'], name)

    # the drag: a real pointer drag of the handle
    old_lua = drv.find_element(By.ID, 'cf-lua').text
    old_svg = figure_svg(drv, name)
    old_m = page_map(drv, name)
    param, index = spec['drag']
    handle = drv.find_element(By.ID, 'cf-handle-%s-%d' % (param, index))
    ActionChains(drv).move_to_element(handle).click_and_hold() \
        .move_by_offset(15, -12).move_by_offset(15, -12) \
        .move_by_offset(15, -12).release().perform()
    n = settle(drv, n)
    time.sleep(0.3)
    n = settle(drv, n - 1)
    pt, lua = verify(drv, tool, name, 'curve', spec['drag_point'],
                     'drag of %s[%d]' % (param, index))
    vals = re.search(r'\b%s = \{(.*)\}' % param, lua).group(1)
    pts = [[float(a), float(b)] for a, b in re.findall(
        r'\{([-0-9.e+]+), ([-0-9.e+]+)\}', vals)]
    want = to_svg(page_map(drv, name), pts[index])
    handle = drv.find_element(By.ID, 'cf-handle-%s-%d' % (param, index))
    got = (float(handle.get_attribute('cx')),
           float(handle.get_attribute('cy')))
    check(abs(got[0] - want[0]) < 0.01 and abs(got[1] - want[1]) < 0.01,
          '%s: the handle sits on its new value' % name)
    moved = pts[index] != native['params'][0]['default'][index]
    check(moved, '%s: the drag moved %s[%d] to %s' % (name, param, index,
                                                     pts[index]))
    check(figure_svg(drv, name) != old_svg, '%s: the drawing changed'
          % name)
    core_moved(tool, old_m, old_lua, page_map(drv, name), lua,
               spec['drag_point'], name)
    check_console(drv, name)


def start_live(tool, script):
    """`curvefig live script` on a free port: the process and the page's
    address (None for a build without the live view)."""
    p = subprocess.Popen([tool, 'live', script, '--port', '0'],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
    for _ in range(3):
        mo = re.search(r'http://127\.0\.0\.1:\d+/[0-9a-f]+/',
                       p.stdout.readline())
        if mo:
            return p, mo.group(0)
    err = p.stderr.read()
    if 'no live view' in err:
        return p, None
    p.terminate()
    raise RuntimeError('no URL: ' + err)


def test_example(drv, tool, script, name, spec):
    p, url = start_live(tool, script)
    try:
        if url is None:
            print('SKIP: this build has no live view')
            sys.exit(77)
        native = json.loads(subprocess.run(
            [tool, 'live', script, '--once'], capture_output=True,
            text=True).stdout)
        drv.get(url)
        exercise(drv, tool, name, spec, native)
        drv.get('about:blank')     # ends the page's long poll
    finally:
        p.terminate()
        p.wait(10)


def wait_for(drv, js, timeout=30):
    end = time.time() + timeout
    while time.time() < end:
        if drv.execute_script(js):
            return True
        time.sleep(0.1)
    return False


def test_saving(drv, tool, src):
    """Saving the script: a mistake shows its message and line in the
    page over the faded drawing (no reload: the drawing stays); the save
    that fixes it, and adds a slider, reloads the page at the same
    address (the token still works) with the values set before kept and
    the new slider shown."""
    tmp = tempfile.mkdtemp(prefix='cf-browser-')
    script = os.path.join(tmp, 'decasteljau.lua')
    shutil.copy(os.path.join(src, 'figures', 'interactive',
                             'decasteljau.lua'), script)
    with open(script) as f:
        good = f.read()
    err = open(os.path.join(tmp, 'server.err'), 'w+')
    p = subprocess.Popen([tool, 'live', script, '--port', '0'],
                         stdout=subprocess.PIPE, stderr=err, text=True)
    try:
        url = re.search(r'http://\S+/', p.stdout.readline() +
                        p.stdout.readline()).group(0)
        drv.get(url)
        n = settle(drv, 0)
        time.sleep(0.3)     # the long poll has its version
        # a value set in the page, which the reload must keep
        drv.find_element(By.ID, 'cf-slider-t').send_keys(Keys.PAGE_UP)
        settle(drv, n)
        moved = drv.find_element(By.ID, 'cf-slider-t').get_attribute('value')
        check(moved not in ('0.75', None), 'saving: t moved to %s' % moved)
        drv.execute_script('window.cfBeforeSave = true;')
        line = good.split('\n').index('local c = bezier(P)') + 2
        with open(script, 'w') as f:
            f.write(good.replace('local c = bezier(P)',
                                 'local c = bezier(P)\nerror("broken")'))
        shown = wait_for(drv, 'var e = document.getElementById("cf-error");'
                         'return !e.hidden && e.textContent.indexOf('
                         '"decasteljau.lua:%d: broken") >= 0;' % line)
        check(shown, 'saving a broken script shows its error and line %d '
              'in the page' % line)
        check(wait_for(drv, 'return document.getElementById("cf-figures")'
                       '.classList.contains("cf-stale");'),
              '... the figure stays, faded')
        check(drv.execute_script('return window.cfBeforeSave === true;'),
              '... in the same page (no reload for a failing script)')
        fixed = good.replace('default = 0.75', 'default = 0.5').replace(
            'local c = bezier(P)',
            'local k = slider{ name = "k", label = "k", min = 0, max = 2, '
            'default = 1.5 }\nlocal c = bezier(P)')
        with open(script, 'w') as f:
            f.write(fixed)
        reloaded = wait_for(drv, 'return window.cfBeforeSave === undefined '
                            '&& document.getElementById("cf-slider-k") '
                            '!== null;')
        check(reloaded, 'saving the fixed script with a new slider reloads '
              'the page, which shows the slider')
        n = settle(drv, 0)
        check(drv.current_url == url, '... at the same address %s (%s)'
              % (url, drv.current_url))
        back = drv.execute_script(
            'var e = document.getElementById("cf-error");'
            'return e.hidden && document.querySelector('
            '"#cf-figures svg") !== null && !document.getElementById('
            '"cf-figures").classList.contains("cf-stale");')
        check(back, '... the token still works: the figure is back')
        kept = drv.find_element(By.ID, 'cf-slider-t').get_attribute('value')
        check(kept == moved, '... t kept its value %s (not the new default '
              '0.5): %s' % (moved, kept))
        check(drv.find_element(By.ID, 'cf-slider-k').get_attribute('value')
              == '1.5', '... the new slider k at its default 1.5')
        lua = drv.find_element(By.ID, 'cf-lua').text
        check('k = 1.5' in lua and 't = %s' % moved in lua,
              '... the Lua text has both values: %r' % lua)
        # the reloaded page runs on: a slider of the new page still draws
        drv.find_element(By.ID, 'cf-slider-k').send_keys(Keys.PAGE_DOWN)
        settle(drv, n)
        check('k = 1.5' not in drv.find_element(By.ID, 'cf-lua').text,
              '... and the new slider runs the script')
        check_console(drv, 'saving')
        drv.get('about:blank')
    except Exception:
        # what the server said, beside what the page shows
        p.terminate()
        p.wait(10)
        err.seek(0)
        print('the server\'s messages:\n' + err.read(), file=sys.stderr)
        print('the page\'s console:', drv.get_log('browser'),
              file=sys.stderr)
        raise
    finally:
        p.terminate()
        p.wait(10)
        err.close()
        shutil.rmtree(tmp, ignore_errors=True)



def test_undrawable_reply(drv, tool, src):
    """A reply the page cannot draw (a figure without its handles: the
    drawing throws) is said in the error line, and the page runs on: it
    is not busy for ever, and the next slider step draws (before, the
    throw skipped the bookkeeping of the runs under way, and every later
    run waited for it)."""
    p, url = start_live(tool, os.path.join(src, 'figures', 'interactive',
                                           'decasteljau.lua'))
    try:
        drv.get(url)
        n = settle(drv, 0)
        # the next reply of ./run loses its figures' handles
        drv.execute_script(
            'var real = window.fetch;'
            'window.fetch = function (url, opts) {'
            '  if (!/\\/run$/.test(url)) return real(url, opts);'
            '  window.fetch = real;'
            '  return real(url, opts).then(function (r) {'
            '    return r.json().then(function (j) {'
            '      j.figures.forEach(function (f) { delete f.handles; });'
            '      return new Response(JSON.stringify(j), {headers: '
            '        {"Content-Type": "application/json"}});'
            '    });'
            '  });'
            '};')
        drv.find_element(By.ID, 'cf-slider-t').send_keys(Keys.PAGE_UP)
        n = settle(drv, n)
        said = drv.execute_script(
            'var e = document.getElementById("cf-error");'
            'return e.hidden ? null : e.textContent;')
        check(said is not None and 'could not draw the reply' in said,
              'undrawable reply: said in the page (%r)' % said)
        logs = [e for e in drv.get_log('browser') if e['level'] == 'SEVERE']
        check(len(logs) == 1, '... and in the console once (%d)' % len(logs))
        drv.find_element(By.ID, 'cf-slider-t').send_keys(Keys.PAGE_UP)
        n = settle(drv, n)
        ok = drv.execute_script(
            'return document.getElementById("cf-error").hidden && '
            'document.querySelectorAll(".cf-handle").length > 0;')
        check(ok, '... the next step draws the figure and its handles')
        check_console(drv, 'undrawable reply')
        drv.get('about:blank')
    finally:
        p.terminate()
        p.wait(10)

# A slider that, past its middle, makes the script spin in a way that the
# parent commit's instruction hook could not stop.
SPIN = ('local spin = slider{ name = "spin", label = "spin", min = 0, '
        'max = 1, default = 0 }\n'
        'if spin > 0.5 then xpcall(error, function() while true do end '
        'end) end\n')


def spin_script(src, path):
    """decasteljau.lua with the spinning slider, written to path."""
    with open(os.path.join(src, 'figures', 'interactive',
                           'decasteljau.lua')) as f:
        good = f.read()
    with open(path, 'w') as f:
        f.write(good.replace('local c = bezier(P)',
                             SPIN + 'local c = bezier(P)'))


def responsive(drv):
    """How long the tab takes to run a line of script (it must not be
    blocked by a run)."""
    t = time.time()
    try:
        drv.execute_script('return document.title;')
    except Exception as e:     # a script timeout: the tab is blocked
        print('     (the tab did not answer: %s)' % str(e).split('\n')[0])
        return 1e9
    return time.time() - t


def exercise_spin(drv, what, limit):
    """On a loaded page of spin_script: the slider to its end starts the
    endless run; the page shows the time-limit error within limit + 3 s,
    answering all the while; the slider back redraws."""
    drv.set_script_timeout(5)
    n = settle(drv, 0)
    slider = drv.find_element(By.ID, 'cf-slider-spin')
    t = time.time()
    slider.send_keys(Keys.END)
    worst = 0
    shown = False
    while time.time() - t < limit + 3:
        worst = max(worst, responsive(drv))
        try:
            shown = drv.execute_script(
                'var e = document.getElementById("cf-error");'
                'return !e.hidden && e.textContent.indexOf("exceeded the '
                'time limit of %g s") >= 0;' % limit)
        except Exception:
            shown = False
        if shown:
            break
        time.sleep(0.2)
    took = time.time() - t
    check(shown and took >= limit - 0.5, '%s: the spinning run stops with '
          'the time-limit error after %.1f s (limit %g s)'
          % (what, took, limit))
    check(worst < 1, '%s: the tab answers while the run spins (slowest '
          '%.2f s)' % (what, worst))
    if not shown:
        return
    n = settle(drv, n)
    slider = drv.find_element(By.ID, 'cf-slider-spin')
    slider.send_keys(Keys.HOME)
    n = settle(drv, n)
    back = drv.execute_script(
        'var e = document.getElementById("cf-error");'
        'return e.hidden && !document.getElementById("cf-figures")'
        '.classList.contains("cf-stale") && document.querySelector('
        '"#cf-figures svg") !== null;')
    check(back, '%s: the slider back: the figure is drawn again' % what)
    check_console(drv, what)


def test_spinning(drv, tool, src):
    """The live page with a script that spins: the server kills the run at
    --timeout; the page shows it and draws on."""
    tmp = tempfile.mkdtemp(prefix='cf-browser-')
    script = os.path.join(tmp, 'decasteljau.lua')
    spin_script(src, script)
    p = subprocess.Popen([tool, 'live', script, '--port', '0', '--timeout',
                          '3', '--max-instructions', '1e15'],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
    try:
        mo = re.search(r'http://\S+/', p.stdout.readline() +
                       p.stdout.readline())
        check(mo is not None, 'live --timeout 3 starts: %s'
              % ('' if mo else p.stderr.read()))
        if mo is None:
            return
        drv.get(mo.group(0))
        exercise_spin(drv, 'live', 3)
        drv.get('about:blank')
    finally:
        p.terminate()
        p.wait(10)
        shutil.rmtree(tmp, ignore_errors=True)


def make_driver():
    """Headless Chromium, its console log kept."""
    opts = webdriver.ChromeOptions()
    opts.binary_location = CHROMIUM
    for a in ('--headless', '--no-sandbox', '--disable-gpu',
              '--disable-dev-shm-usage', '--window-size=1400,1000',
              '--no-first-run', '--disable-background-networking'):
        opts.add_argument(a)
    opts.set_capability('goog:loggingPrefs', {'browser': 'ALL'})
    return webdriver.Chrome(service=Service(CHROMEDRIVER), options=opts)


def need_browser():
    """Exit 77 (skipped) without chromium or chromedriver."""
    for path in (CHROMIUM, CHROMEDRIVER):
        if not os.access(path, os.X_OK):
            print('SKIP: no', path)
            sys.exit(77)


def main():
    tool, src = os.path.abspath(sys.argv[1]), sys.argv[2]
    need_browser()
    names = sys.argv[3:] or sorted(EXAMPLES)
    drv = make_driver()
    try:
        for name in names:
            script = os.path.join(src, 'figures', 'interactive',
                                  name + '.lua')
            test_example(drv, tool, script, name, EXAMPLES[name])
        if not sys.argv[3:]:
            test_saving(drv, tool, src)
            test_undrawable_reply(drv, tool, src)
            test_spinning(drv, tool, src)
    finally:
        drv.quit()
    shipped = sorted(f[:-4] for f in os.listdir(
        os.path.join(src, 'figures', 'interactive')) if f.endswith('.lua'))
    check(sorted(EXAMPLES) == shipped, 'every shipped example is tested')
    if failures:
        sys.exit('%d failures' % len(failures))


if __name__ == '__main__':
    main()
