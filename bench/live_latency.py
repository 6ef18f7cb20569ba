#!/usr/bin/env python3
"""Latency of `curvefig live`: from an input event to the new drawing.

usage: live_latency.py CURVEFIG SOURCE_DIR [RUNS [PAUSE_MS]]

For every shipped interactive example (figures/interactive/*.lua), on a
server of its own on 127.0.0.1:
  http     the time from sending the new values (one POST of the run, as
           the page sends it on a slider's input event or a drag's pointer
           move) to the whole reply received: the script run in a fresh
           sandbox, every figure rendered to SVG, the JSON;
  browser  (with /usr/bin/python3 + selenium + chromedriver) the time in
           the page from dispatching the slider's input event to the new
           SVG in the document (performance.now() around it).
RUNS requests each (default 60), alternating slider values and point
moves (and, in a 3D figure, turns of its view: "@view:NAME"), after 5
warm-up requests, each sent as soon as the last reply came
(a drag: the page sends the latest values when a run returns) or, with
PAUSE_MS, that long after it (moves with pauses between them: the server
uses the pause to fork and ready the next run's process).  "cpu per
run": the server's processor time (user + system, its worker processes
included) per exact run, from a server that answered RUNS + 1 runs less
one that answered one.  Each is
measured twice: "http" the exact runs (a key press, a drag's release),
"http draft" the runs a drag sends while the pointer is down ("@draft":
1, docs/interactive.md, "Drafts").  Prints one JSON line per example and
measurement: median and 95th percentile in ms; the target (issue #28) is
a median within 30 ms and a 95th percentile within 60 ms.
"""
import json
import os
import re
import statistics
import subprocess
import sys
import time
import urllib.request

TARGET_MEDIAN, TARGET_P95 = 30, 60


def start(tool, script):
    p = subprocess.Popen([tool, 'live', script, '--port', '0'],
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                         text=True)
    for _ in range(3):
        m = re.search(r'http://127\.0\.0\.1:\d+/[0-9a-f]+/',
                      p.stdout.readline())
        if m:
            return p, m.group(0)
    p.kill()
    sys.exit('curvefig live printed no URL (a build without the live '
             'view?)')


def post(url, values):
    req = urllib.request.Request(url + 'run', data=json.dumps(values)
                                 .encode(), method='POST')
    req.add_header('Content-Type', 'application/json')
    with urllib.request.urlopen(req, timeout=60) as r:
        return json.loads(r.read())


def inputs(params, k, views=None, draft=False):
    """The values of input event k: a slider moved, a point dragged, or
    (every third event of a 3D figure) the figure turned."""
    vals = {'@draft': 1} if draft else {}
    sliders = [p for p in params if p['kind'] == 'slider']
    pts = [p for p in params if p['kind'] == 'points']
    if views and k % 3 == 2:
        for name, v in views.items():
            vals['@view:' + name] = [[v[0] + 2 * (k % 20), v[1] + (k % 7)]]
    elif k % 2 == 0 and sliders:
        s = sliders[(k // 2) % len(sliders)]
        vals[s['name']] = s['min'] + (s['max'] - s['min']) * \
            ((k * 0.137) % 1.0)
    elif pts:
        p = pts[0]
        q = [list(xy) for xy in p['default']]
        i = (k // 2) % len(q)
        q[i][0] += 0.3 * ((k % 5) - 2) / 2
        q[i][1] += 0.2 * ((k % 3) - 1)
        vals[p['name']] = q
    return vals


def percentile(xs, q):
    xs = sorted(xs)
    return xs[min(len(xs) - 1, int(round(q * (len(xs) - 1))))]


def report(name, what, ms):
    med, p95 = statistics.median(ms), percentile(ms, 0.95)
    met = med <= TARGET_MEDIAN and p95 <= TARGET_P95
    print(json.dumps({'example': name, 'measure': what, 'runs': len(ms),
                      'median_ms': round(med, 2), 'p95_ms': round(p95, 2),
                      'met': met}), flush=True)
    return met


def http_latency(url, params, views, runs, pause, draft):
    for k in range(5):
        post(url, inputs(params, k, views, draft))
    ms = []
    for k in range(runs):
        v = inputs(params, k, views, draft)
        time.sleep(pause)
        t0 = time.perf_counter()
        reply = post(url, v)
        ms.append((time.perf_counter() - t0) * 1000)
        if reply['error'] is not None:
            sys.exit('script error: ' + reply['error']['message'])
    return ms


def server_cpu(tool, script, params, views, runs):
    """The server's CPU (user + system, with its reaped processes) per
    exact run: a server that answers 1 + runs runs less one that answers
    one, over runs."""
    cpu = []
    for n in (1, 1 + runs):
        p, url = start(tool, script)
        for k in range(n):
            post(url, inputs(params, k, views))
        p.terminate()
        p.stdout.close()
        _, _, ru = os.wait4(p.pid, 0)
        p.returncode = 0
        cpu.append(ru.ru_utime + ru.ru_stime)
    return (cpu[1] - cpu[0]) / runs * 1000


# In the page: dispatch a slider's input event, resolve when the page has
# shown the reply (data-runs grows): the time between, in ms.
BROWSER_STEP = r'''
var done = arguments[arguments.length - 1];
var root = document.getElementById('curvefig');
var input = document.getElementById('cf-slider-' + arguments[0]);
var before = Number(root.dataset.runs);
var obs = new MutationObserver(function () {
  if (Number(root.dataset.runs) > before && root.dataset.busy === '0') {
    obs.disconnect();
    done(performance.now() - t0);
  }
});
obs.observe(root, { attributes: true });
input.value = arguments[1];
var t0 = performance.now();
input.dispatchEvent(new Event('input'));
'''


def browser_driver():
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        return None
    if not (os.access('/usr/bin/chromium', os.X_OK) and
            os.access('/usr/bin/chromedriver', os.X_OK)):
        return None
    opts = webdriver.ChromeOptions()
    opts.binary_location = '/usr/bin/chromium'
    for a in ('--headless', '--no-sandbox', '--disable-gpu',
              '--disable-dev-shm-usage', '--window-size=1400,1000'):
        opts.add_argument(a)
    return webdriver.Chrome(service=Service('/usr/bin/chromedriver'),
                            options=opts)


def browser_latency(drv, url, params, runs):
    drv.get(url)
    end = time.time() + 20
    while time.time() < end and drv.execute_script(
            'return document.getElementById("curvefig").dataset.busy') != '0':
        time.sleep(0.05)
    sliders = [p for p in params if p['kind'] == 'slider']
    ms = []
    for k in range(runs + 5):
        s = sliders[k % len(sliders)]
        v = s['min'] + (s['max'] - s['min']) * ((k * 0.137) % 1.0)
        t = drv.execute_async_script(BROWSER_STEP, s['name'], v)
        if k >= 5:
            ms.append(t)
    return ms


def main():
    tool, src = sys.argv[1], sys.argv[2]
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 60
    pause = float(sys.argv[4]) / 1000 if len(sys.argv) > 4 else 0.0
    d = os.path.join(src, 'figures', 'interactive')
    names = sorted(f[:-4] for f in os.listdir(d) if f.endswith('.lua'))
    drv = browser_driver()
    if drv is not None:
        drv.set_script_timeout(60)
    else:
        print('# no selenium/chromium for ' + sys.executable +
              ': the browser measurement is left out', flush=True)
    try:
        for name in names:
            p, url = start(tool, os.path.join(d, name + '.lua'))
            try:
                first = post(url, {})
                params = first['params']
                views = {f['name']: f['view'] for f in first['figures']
                         if f.get('view')}
                for draft in (False, True):
                    report(name, ('http' if pause == 0 else
                                  'http, %g ms apart' % (pause * 1000)) +
                           (' draft' if draft else ''),
                           http_latency(url, params, views, runs, pause,
                                        draft))
                if drv is not None:
                    report(name, 'browser', browser_latency(drv, url, params,
                                                            runs))
            finally:
                p.terminate()
                p.wait(30)
            cpu = server_cpu(tool, os.path.join(d, name + '.lua'), params,
                             views, runs)
            print(json.dumps({'example': name, 'measure': 'cpu per run',
                              'runs': runs, 'ms': round(cpu, 2)}),
                  flush=True)
    finally:
        if drv is not None:
            drv.get('about:blank')
            drv.quit()


main()
