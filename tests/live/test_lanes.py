#!/usr/bin/python3
"""A release while a draft is under way: the course page's exact run goes
at once, on its own worker, and the draft's late reply is dropped
(headless Chromium).

usage: test_lanes.py CURVEFIG SOURCE_DIR

The course page (-f html) of figures/interactive/surface-patch.lua,
opened from the file (skipped without the WebAssembly module), with the
page's Worker wrapped before its scripts run (DevTools'
Page.addScriptToEvaluateOnNewDocument): the wrapper logs each run sent
to a worker (which worker, draft or not) and each reply taken, and can
hold a draft's reply back, as a draft that is still computing when the
pointer is released.  The page is written with a time limit of
LIMIT_S = 2 s.  The browser's processor is slowed down six times
(DevTools' emulation, as in test_redraw.py), so that an exact run takes
over 16 ms and a drag draws drafts.

For a drag of the background (turning the figure), of the point L and
of a slider: a few moves, each awaited (drafts); one more move whose
draft's reply is held back (1.5 s; the point's 3 s, beyond the time
limit); the release while that draft is under way.  Then:

- the exact run is sent at once, to another worker than the draft's,
  and its drawing is shown (data-draft "0") before the held reply is let
  through: the release does not wait for the draft (on a page with one
  worker, the exact run is sent only once the draft's reply has come);
- the draft's reply, when it comes, is dropped: no drawing more
  (data-runs unchanged), the figure's SVG the same, data-draft "0", no
  error shown; held beyond the time limit, the page stopped the drafts'
  worker (terminate) and dropped its answer (the time limit's error)
  too, and the slider's drafts after it run on a fresh worker;
- the page never has more than two workers at a time;
- after the turn (the background's drag, the first), the drawing is the
  one `curvefig render` draws at the view the page reports (the same
  pixels, as test_rotate.py checks the course page).

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
import test_redraw as rd
import test_rotate as tr

NAME = 'surface-patch'
LIMIT_S = 2     # the page's time limit (-f html --timeout)

# Before the page's scripts: Worker wrapped.  __lanes.log: [what, worker,
# id, draft, time] for 'send' (a run posted), 'reply' (its answer taken
# by the page); __lanes.hold: how long a draft's answer is held back.
WRAP = r'''
(function () {
  var W = window.Worker;
  var L = window.__lanes = { workers: 0, live: 0, log: [], hold: 0 };
  window.Worker = function (url, opts) {
    var w = new W(url, opts), k = L.workers++, drafts = {}, handler = null;
    var post = w.postMessage.bind(w), end = w.terminate.bind(w);
    L.live++;
    w.terminate = function () {
      L.live--;
      L.log.push(['terminate', k, 0, false, performance.now()]);
      end();
    };
    w.postMessage = function (m) {
      if (m && m.values) {
        var d = !!m.values['@draft'];
        if (d) drafts[m.id] = true;
        L.log.push(['send', k, m.id, d, performance.now()]);
      }
      post(m);
    };
    w.addEventListener('message', function (ev) {
      var m = ev.data, d = !!drafts[m.id];
      function take() {
        if (!m.started && !m.ok)
          L.log.push(['reply', k, m.id, d, performance.now()]);
        if (handler) handler(ev);
      }
      if (d && !m.started && L.hold > 0) setTimeout(take, L.hold);
      else take();
    });
    Object.defineProperty(w, 'onmessage', {
      set: function (f) { handler = f; },
      get: function () { return handler; }
    });
    return w;
  };
})();
'''

# The drawings shown: [data-runs, data-draft, time] at each change of
# data-runs.
ARM = r'''
if (!window.__shown) {
  var root = document.getElementById('curvefig');
  window.__shown = [];
  new MutationObserver(function () {
    var s = window.__shown, n = Number(root.dataset.runs);
    if (!s.length || s[s.length - 1][0] !== n)
      s.push([n, root.dataset.draft, performance.now()]);
  }).observe(root, { attributes: true });
  window.addEventListener('pointerup', function () {
    window.__releasedAt = performance.now();
  }, true);
}
'''

STATE = r'''
var root = document.getElementById('curvefig');
return { runs: Number(root.dataset.runs), draft: root.dataset.draft,
         busy: root.dataset.busy, log: window.__lanes.log.slice(),
         workers: window.__lanes.workers, live: window.__lanes.live,
         error: !document.getElementById('cf-error').hidden,
         shown: window.__shown.slice(),
         released: window.__releasedAt || null,
         svg: document.getElementById('cf-figure-' + arguments[0])
           .querySelector('svg').outerHTML };
'''


def state(drv):
    return drv.execute_script(STATE, NAME)


def wait_for(drv, cond, what, timeout=20):
    end = time.time() + timeout
    while time.time() < end:
        s = state(drv)
        if cond(s):
            return s
        time.sleep(0.02)
    lb.check(False, 'timed out waiting for ' + what)
    return state(drv)


def release_in_flight(drv, kind, n, hold_ms):
    """One drag of kind released while its last draft is held back
    hold_ms."""
    x, y = drv.execute_script(rd.WHERE, kind)
    drv.execute_script('window.__lanes.hold = 0;')
    rd.mouse(drv, 'mouseMoved', x, y, 0)
    rd.mouse(drv, 'mousePressed', x, y, 1)
    time.sleep(0.6)
    n = lb.settle(drv, n - 1)
    for k in range(3):
        x += 6
        rd.mouse(drv, 'mouseMoved', x, y, 1)
        n = lb.settle(drv, n)
    before = state(drv)
    lb.check(before['draft'] == '1', '%s: moved, the drawing is a draft'
             % kind)
    drv.execute_script('window.__lanes.hold = arguments[0];', hold_ms)
    sent = len(before['log'])
    x += 6
    rd.mouse(drv, 'mouseMoved', x, y, 1)
    s = wait_for(drv, lambda s: any(e[0] == 'send' and e[3]
                                    for e in s['log'][sent:]),
                 '%s: the last move\'s draft sent' % kind)
    draft = [e for e in s['log'][sent:] if e[0] == 'send' and e[3]][-1]
    rd.mouse(drv, 'mouseReleased', x, y, 0)
    # the exact drawing shown
    s = wait_for(drv, lambda s: s['runs'] > before['runs'] and
                 s['draft'] == '0' and s['busy'] == '0',
                 '%s: the exact drawing after the release' % kind)
    exact = [e for e in s['log'][sent:] if e[0] == 'send' and not e[3]]
    got = [e for e in s['log'] if e[0] == 'reply' and e[2] == draft[2]]
    shown = [e for e in s['shown'] if e[0] > before['runs']]
    lb.check(len(exact) == 1 and exact[0][1] != draft[1] and
             exact[0][4] - s['released'] < hold_ms / 3,
             '%s: released while its draft runs, the exact run is sent at '
             'once (%.0f ms after the release), to another worker (%s) '
             'than the draft\'s (%d)'
             % (kind, exact[0][4] - s['released'] if exact else -1,
                [e[1] for e in exact], draft[1]))
    lb.check(not got and len(shown) == 1 and shown[0][1] == '0',
             '%s: the exact drawing is shown (%.0f ms after the release) '
             'before the draft\'s reply comes, and is the only drawing '
             'since (%d)' % (kind, shown[0][2] - s['released']
                             if shown else -1, len(shown)))
    # the held draft's reply: dropped
    s2 = wait_for(drv, lambda t: any(e[0] == 'reply' and e[2] == draft[2]
                                     for e in t['log']),
                  '%s: the draft\'s reply' % kind, hold_ms / 1000 + 20)
    time.sleep(0.5)
    s2 = state(drv)
    stopped = [e for e in s2['log'] if e[0] == 'terminate' and
               e[1] == draft[1]]
    over = hold_ms > LIMIT_S * 1000
    lb.check(s2['runs'] == s['runs'] and s2['draft'] == '0' and
             s2['svg'] == s['svg'] and s2['busy'] == '0' and
             not s2['error'],
             '%s: the draft\'s late reply is dropped: no drawing more '
             '(runs %d -> %d), the same SVG, data-draft %s, no error shown'
             % (kind, s['runs'], s2['runs'], s2['draft']))
    lb.check(bool(stopped) == over,
             '%s: held %d ms (the time limit %d s), the draft\'s worker %s'
             % (kind, hold_ms, LIMIT_S, 'was stopped' if stopped else
                'went on'))
    lb.check(s2['live'] <= 2, '%s: the page has %d workers (at most '
             'two; %d started in all)' % (kind, s2['live'], s2['workers']))
    drv.execute_script('window.__lanes.hold = 0;')
    time.sleep(0.6)   # (the next press is no double click)
    return s2['runs']


def main():
    tool, src = os.path.abspath(sys.argv[1]), sys.argv[2]
    lb.need_browser()
    script, text = lb.example(src, NAME)
    drv = lb.make_driver()
    try:
        with tempfile.TemporaryDirectory() as outdir:
            out = subprocess.run([tool, 'render', script, '-f', 'html',
                                  '--timeout', str(LIMIT_S), '-o', outdir],
                                 capture_output=True, text=True)
            if 'needs the WebAssembly module' in out.stderr:
                print('SKIP: this build has no WebAssembly module')
                sys.exit(77)
            lb.check(out.returncode == 0, '-f html %s' % out.stderr)
            drv.execute_cdp_cmd('Page.addScriptToEvaluateOnNewDocument',
                                {'source': WRAP})
            drv.get('file://' + os.path.join(outdir, NAME + '.html'))
            drv.set_script_timeout(30)
            n = lb.settle(drv, 0)
            drv.execute_script(ARM)
            # the rotation's draft held back within the time limit, the
            # point's beyond it (the page stops the drafts' worker; the
            # slider's drafts then run on a fresh one)
            for kind, hold_ms in (('rotate', 1500), ('point', 3000),
                                  ('slider', 1500)):
                drv.execute_cdp_cmd('Emulation.setCPUThrottlingRate',
                                    {'rate': 6})
                try:
                    n = release_in_flight(drv, kind, n, hold_ms)
                finally:
                    drv.execute_cdp_cmd('Emulation.setCPUThrottlingRate',
                                        {'rate': 1})
                if kind != 'rotate':
                    continue
                # turned (the values are the script's): curvefig render's
                # drawing at the view the page reports
                v = tr.view(drv)
                bad = tr.same_drawing(drv, 'rotate', tr.static_svg(
                    tool, text, v[0], v[1], outdir), False)
                lb.check(bad == 0, 'rotate: the drawing after the release '
                         'is curvefig render\'s at the view %s (%s pixels '
                         'differ)' % (v, bad))
            lb.check_console(drv)
    finally:
        drv.quit()
    lb.exit_on_failures()


main()
