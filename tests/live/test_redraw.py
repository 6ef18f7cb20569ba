#!/usr/bin/python3
"""A redraw of the course page replaces the drawing, not the figure's box,
and a release draws once (headless Chromium).

usage: test_redraw.py CURVEFIG SOURCE_DIR

The course page (-f html) of figures/interactive/surface-patch.lua (a 3D
figure, turned by the arrow keys when its box has the focus; a draggable
label point L), opened from the file; skipped without the WebAssembly
module:

- a key press on the focused figure redraws it in the same box element,
  which keeps the focus throughout: no focusout, blur or focusin on the
  page (the box is not taken out of the document and focused again);
- what such a redraw leaves in #cf-figures (the box's attributes, its
  SVG, the button "Reset view", the description) is, character for
  character, what a box built from scratch holds at the same view: the
  page at load (the script's view) against the turned figure reset by
  its button; a turned view drawn in place against the same view drawn
  into new boxes (the page's other path, taken when the figures shown
  change: here a stray element put in #cf-figures), which gives the new
  box the focus again;
- where the browser has pointerrawupdate (Chromium, in a secure context:
  the file), a drag of the background or of the point L follows it as
  well as pointermove (which waits for the next frame): a synthetic
  pointerrawupdate runs the script (turns the figure 10 degrees for
  25 px), the pointermove of the same place after it runs nothing, a
  pointermove to another place runs it;
- released after drafts (the browser's processor slowed down six times
  by DevTools' emulation, so that an exact run takes over 16 ms and the
  page asks for drafts while the pointer moves), a drag of the point L,
  of a slider and of the background each draw the figure once more: the
  exact run's drawing, nothing before it (data-draft "0" after).

The console stays free of errors.  Skipped (77) without chromium,
chromedriver or selenium.
"""
import os
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # (no __pycache__ in the source tree)
import test_browser as lb  # noqa: E402  (skips, 77, without selenium)
from test_rotate import quiet as settle

NAME = 'surface-patch'

# Once: the focus events of the page, and the drawings put into
# #cf-figures (an added SVG, or an added element holding one).
ARM = r'''
if (!window.__redraw) {
  var r = window.__redraw = { focus: [], draws: 0 };
  ['focusout', 'blur', 'focusin', 'focus'].forEach(function (t) {
    document.addEventListener(t, function (e) {
      r.focus.push(t + ':' + (e.target.id || e.target.nodeName));
    }, true);
  });
  new MutationObserver(function (list) {
    list.forEach(function (m) {
      m.addedNodes.forEach(function (n) {
        if (n.nodeName.toLowerCase() === 'svg' ||
            (n.querySelector && n.querySelector('svg')))
          r.draws++;
      });
    });
  }).observe(document.getElementById('cf-figures'),
             { childList: true, subtree: true });
}
'''

STATE = r'''
var box = document.getElementById('cf-figure-' + arguments[0]);
var root = document.getElementById('curvefig');
return { figures: document.getElementById('cf-figures').innerHTML,
         same: box === window.__box, focused: document.activeElement === box,
         focus: window.__redraw.focus.slice(), draws: window.__redraw.draws,
         view: box.getAttribute('data-view'), draft: root.dataset.draft,
         exactMs: Number(root.dataset.exactMs) };
'''


def state(drv):
    return drv.execute_script(STATE, NAME)


def key(drv, name, code):
    for kind in ('rawKeyDown', 'keyUp'):
        drv.execute_cdp_cmd('Input.dispatchKeyEvent', {
            'type': kind, 'key': name, 'code': name,
            'windowsVirtualKeyCode': code})


def mouse(drv, kind, x, y, buttons):
    drv.execute_cdp_cmd('Input.dispatchMouseEvent', {
        'type': kind, 'x': x, 'y': y, 'button': 'left', 'buttons': buttons,
        'clickCount': 1 if kind != 'mouseMoved' else 0})


def keys_in_place(drv, n):
    """The key presses' redraws in the same box; against fresh boxes."""
    load = state(drv)
    drv.execute_script('var b = document.getElementById("cf-figure-" + '
                       'arguments[0]); window.__box = b; b.focus();'
                       'window.__redraw.focus = [];', NAME)
    key(drv, 'ArrowLeft', 37)
    n = settle(drv, n)
    key(drv, 'ArrowLeft', 37)
    n = settle(drv, n)
    turned = state(drv)
    lb.check(turned['view'] == '[-45,28]', 'two Left turned the figure to '
             '[-45, 28] (%s)' % turned['view'])
    lb.check(turned['same'] and turned['focused'] and turned['focus'] == [],
             'the redraws after the key presses kept the box, which kept '
             'the focus (same element %s, focused %s, focus events %s)'
             % (turned['same'], turned['focused'], turned['focus']))
    lb.check('cf-view-reset' in turned['figures'],
             '... and it has the button "Reset view" now')

    # the turned view drawn into new boxes: a stray element in
    # #cf-figures makes the page build them, as on a change of figures
    drv.execute_script('document.getElementById("cf-figures").appendChild('
                       'document.createElement("div"));')
    key(drv, 'ArrowRight', 39)
    n = settle(drv, n)
    drv.execute_script('document.getElementById("cf-figures").appendChild('
                       'document.createElement("div"));')
    key(drv, 'ArrowLeft', 37)
    n = settle(drv, n)
    fresh = state(drv)
    lb.check(fresh['view'] == '[-45,28]' and not fresh['same'] and
             fresh['focused'],
             'drawn into a new box, the same view (%s), the new box has '
             'the focus' % fresh['view'])
    lb.check(fresh['figures'] == turned['figures'],
             'the turned figure drawn in place is what new boxes hold, '
             'character for character (%d characters)'
             % len(turned['figures']))

    # back to the script's view by the button (click(): the focus stays)
    drv.execute_script('window.__box = document.getElementById("cf-figure-" '
                       '+ arguments[0]); window.__redraw.focus = [];', NAME)
    drv.execute_script('document.querySelector("#cf-figure-%s '
                       'button.cf-view-reset").click();' % NAME)
    n = settle(drv, n)
    reset = state(drv)
    lb.check(reset['same'] and reset['focused'] and reset['focus'] == [],
             '"Reset view": redrawn in the same box, which kept the focus '
             '(%s)' % reset['focus'])
    lb.check(reset['figures'] == load['figures'],
             '... and it holds what the page built at load, character for '
             'character (%d characters)' % len(load['figures']))
    return n


WHERE = r'''
var kind = arguments[0], el;
if (kind === 'slider') {
  el = document.querySelector('#cf-controls input[type=range]');
  var r = el.getBoundingClientRect(), f = (Number(el.value) -
      Number(el.min)) / (Number(el.max) - Number(el.min));
  return [r.left + 8 + f * (r.width - 16), r.top + r.height / 2];
}
if (kind === 'point') {
  el = document.querySelector('.cf-handle');
  var c = el.getBoundingClientRect();
  return [c.left + c.width / 2, c.top + c.height / 2];
}
var s = document.querySelector('.cf-figure.cf-3d svg')
    .getBoundingClientRect();
return [s.right - 12, s.top + 50];
'''


def raw_moves(drv, n):
    """A drag of the background and of the point L follow
    pointerrawupdate, and take each move once."""
    if not drv.execute_script('return "onpointerrawupdate" in window;'):
        print('SKIP (raw moves): this browser has no pointerrawupdate')
        return n
    move = ('window.dispatchEvent(new PointerEvent(arguments[0], '
            '{ clientX: arguments[1], clientY: arguments[2], '
            'pointerId: 1, isPrimary: true, bubbles: true }));')

    def ran(n):
        try:
            return settle(drv, n, 5)
        except RuntimeError:
            return n        # (no run: the check fails)

    for kind, want in (('rotate', ('[-45,28]', '[-35,28]')),
                       ('point', None)):
        x, y = drv.execute_script(WHERE, kind)
        mouse(drv, 'mouseMoved', x, y, 0)
        mouse(drv, 'mousePressed', x, y, 1)
        time.sleep(0.6)
        n = settle(drv, n - 1)
        drv.execute_script(move, 'pointerrawupdate', x - 25, y)
        m = ran(n)
        first = state(drv)['view']
        # the browser's pointermove of that move, at its next frame
        drv.execute_script(move, 'pointermove', x - 25, y)
        time.sleep(0.5)
        again = lb.runs(drv)
        lb.check(m == n + 1 and again == m and
                 (want is None or first == want[0]),
                 '%s: a pointerrawupdate 25 px left ran the script (%d '
                 'run(s)%s), the pointermove of the same place after it '
                 'ran nothing (%d)' % (kind, m - n, ', view %s' % first
                                       if want else '', again - m))
        drv.execute_script(move, 'pointermove', x - 50, y)
        n = ran(m)
        lb.check(n == m + 1 and (want is None or
                                 state(drv)['view'] == want[1]),
                 '%s: a pointermove alone (a pointer without raw updates) '
                 'moves it too (%d run(s)%s)'
                 % (kind, n - m, ', view %s' % state(drv)['view']
                    if want else ''))
        mouse(drv, 'mouseReleased', x, y, 0)
        time.sleep(0.6)
        n = settle(drv, n - 1)
    return n


def release_once(drv, n):
    """A drag with drafts, released: one drawing more, the exact one."""
    drv.execute_cdp_cmd('Emulation.setCPUThrottlingRate', {'rate': 6})
    try:
        for kind in ('point', 'slider', 'rotate'):
            x, y = drv.execute_script(WHERE, kind)
            mouse(drv, 'mouseMoved', x, y, 0)
            mouse(drv, 'mousePressed', x, y, 1)
            time.sleep(0.6)
            n = settle(drv, n - 1)
            for k in range(3):
                x += 6
                mouse(drv, 'mouseMoved', x, y, 1)
                n = settle(drv, n)
            held = state(drv)
            lb.check(held['draft'] == '1', '%s: moved, the drawing is a '
                     'draft (data-draft %s; the last exact run took %.0f '
                     'ms)' % (kind, held['draft'], held['exactMs']))
            mouse(drv, 'mouseReleased', x, y, 0)
            if held['draft'] != '1':   # (no exact run follows)
                continue
            n = settle(drv, n)
            after = state(drv)
            lb.check(after['draft'] == '0' and
                     after['draws'] - held['draws'] == 1,
                     '%s: released, the figure was drawn %d time(s) more '
                     '(one: the exact run), data-draft %s'
                     % (kind, after['draws'] - held['draws'],
                        after['draft']))
            time.sleep(0.6)   # (the next press is no double click)
    finally:
        drv.execute_cdp_cmd('Emulation.setCPUThrottlingRate', {'rate': 1})
    return n


def main():
    tool, src = os.path.abspath(sys.argv[1]), sys.argv[2]
    lb.need_browser()
    script = os.path.join(src, 'figures', 'interactive', NAME + '.lua')
    drv = lb.make_driver()
    try:
        with tempfile.TemporaryDirectory() as outdir:
            out = subprocess.run([tool, 'render', script, '-f', 'html', '-o',
                                  outdir], capture_output=True, text=True)
            if 'needs the WebAssembly module' in out.stderr:
                print('SKIP: this build has no WebAssembly module')
                sys.exit(77)
            lb.check(out.returncode == 0, '-f html %s' % out.stderr)
            drv.get('file://' + os.path.join(outdir, NAME + '.html'))
            drv.set_script_timeout(30)
            n = settle(drv, 0)
            drv.execute_script(ARM)
            n = keys_in_place(drv, n)
            n = raw_moves(drv, n)
            release_once(drv, n)
            lb.check_console(drv)
    finally:
        drv.quit()
    lb.exit_on_failures()


if __name__ == '__main__':
    main()
