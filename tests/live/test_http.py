#!/usr/bin/env python3
"""The HTTP behaviour of `curvefig live`, without a browser.

usage: test_http.py CURVEFIG SOURCE_DIR

A server on a free port of 127.0.0.1 for a copy of an interactive example:
the page needs the token (403 without it, also for a wrong token of the
same length and for the token with bytes after it), unknown paths are 404,
bad values are 400 with the JSON error, an oversized body is 413, other
methods 405; a script error comes back in the JSON and the server runs on;
saving the script ends the long poll of /wait with a new version;
concurrent runs all answer; garbage on the socket does not stop it; the
socket listens on 127.0.0.1 only.  The page carries a Content-Security-
Policy, and a Host header other than this server's is refused (403).

Hostile neighbours and scripts (issue #35): 100 idle connections that
never finish their headers neither delay a real request (answered within
a second) nor stay open past the header timeout; a run that spins (a
slider drives `xpcall(error, function() while true do end end)`) is
killed at --timeout with its error in the JSON while the server answers
everything else, and the next run works; SIGTERM stops the server within
two seconds while a run spins, and the run's process is gone; the script
replaced by a directory or a FIFO is an error in the JSON, not an empty
run or a server blocked for ever.  The runs' worker process is started
(the program again, not a fork) ahead of need (before the first request, and after a run that ended
it), runs the script as it is when the run starts, serves the next runs
each in a fresh sandbox (a global, the string table and its metatable
changed by one run are as new in the next), is replaced after a script
error or a run past --max-memory (or --timeout, which kills it), and goes
with the server on SIGTERM.  With --worker-runs N a worker serves N runs
and a fresh one the next, each run's answer that of a run in a process of
its own (--once); a bad N is a usage error.
"""
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time
import urllib.error
import urllib.request

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print('FAIL', what)
    else:
        print('ok  ', what)


def request(url, data=None, method=None, timeout=30):
    req = urllib.request.Request(url, data=data, method=method)
    if data is not None:
        req.add_header('Content-Type', 'application/json')
    try:
        with urllib.request.urlopen(req, timeout=timeout) as r:
            return r.status, r.headers.get('Content-Type'), r.read()
    except urllib.error.HTTPError as e:
        return e.code, e.headers.get('Content-Type'), e.read()


def answer(url, data=None, timeout=30):
    """request(), with no answer at all (a timeout, a closed connection)
    as status None and the body of an empty JSON object."""
    try:
        return request(url, data=data, timeout=timeout)
    except OSError as e:
        print('     (no answer: %s)' % e)
        return None, None, b'{}'


def start(tool, script, *options):
    p = subprocess.Popen([tool, 'live', script, '--port', '0'] +
                         list(options),
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
    for _ in range(3):
        line = p.stdout.readline()
        if not line:
            err = p.stderr.read()
            if 'no live view' in err:
                print('SKIP: this build has no live view')
                sys.exit(77)
            sys.exit('FAIL: curvefig live ended: ' + err)
        m = re.search(r'(http://127\.0\.0\.1:(\d+)/([0-9a-f]+)/)', line)
        if m:
            return p, m.group(1), int(m.group(2)), m.group(3)
    p.kill()
    sys.exit('FAIL: curvefig live printed no URL: ' + p.stderr.read())


def stop(p, seconds):
    """SIGTERM to the server, SIGKILL when it is not gone within seconds."""
    p.terminate()
    try:
        p.wait(seconds)
    except subprocess.TimeoutExpired:
        p.kill()
        p.wait()


def raw_status(port, text):
    """The status of a request sent as it is (headers of our choosing)."""
    s = socket.create_connection(('127.0.0.1', port), timeout=10)
    try:
        s.sendall(text.encode())
        head = s.recv(200).decode('latin-1')
    finally:
        s.close()
    m = re.match(r'HTTP/1\.[01] (\d+)', head)
    return int(m.group(1)) if m else None


def test_idle_connections(url, port):
    """Connections that never finish their headers cost the server
    nothing: a real request is answered at once, and they are closed."""
    socks = []
    try:
        for _ in range(100):
            s = socket.create_connection(('127.0.0.1', port), timeout=10)
            s.sendall(b'GET /')
            socks.append(s)
        t = time.time()
        st, _, body = answer(url, timeout=10)
        took = time.time() - t
        check(st == 200 and b'CurvefigPage' in body and took < 1,
              '100 idle connections: the page answered in %.2f s' % took)
        t = time.time()
        st, _, body = answer(url + 'run', data=b'{}', timeout=10)
        took = time.time() - t
        check(st == 200 and json.loads(body).get('error', 1) is None and took < 3,
              '... and a run in %.2f s' % took)
        socks[0].settimeout(15)
        t = time.time()
        try:
            closed = socks[0].recv(100) == b''
        except OSError:
            closed = True
        check(closed and time.time() - t < 10, '... an idle connection is '
              'closed after %.1f s' % (time.time() - t))
    finally:
        for s in socks:
            s.close()


SPIN = ('local spin = slider{ name = "spin", label = "spin", min = 0, '
        'max = 1, default = 0 }\n'
        'if spin > 0.5 then xpcall(error, function() while true do end '
        'end) end\n')


def test_spinning_run(tool, tmp, good):
    """A run that never ends is killed at --timeout; meanwhile the server
    answers; the next run works; SIGTERM stops all promptly."""
    script = os.path.join(tmp, 'spin.lua')
    with open(script, 'w') as f:
        f.write(good.replace('local c = bezier(P)',
                             SPIN + 'local c = bezier(P)'))
    # the instruction limit out of reach: only the clock can stop it
    p, url, port, token = start(tool, script, '--timeout', '2',
                                '--max-instructions', '1e15')
    try:
        done = {}
        before = wait_children(p.pid, 1)

        def spin():
            t = time.time()
            done['reply'] = answer(url + 'run', data=b'{"spin": 1}',
                                   timeout=30)
            done['took'] = time.time() - t
        w = threading.Thread(target=spin)
        w.start()
        time.sleep(0.5)
        t = time.time()
        st, _, _ = answer(url, timeout=10)
        st2, _, _ = answer(url + 'wait', timeout=10)
        took = time.time() - t
        check(st == 200 and st2 == 200 and took < 1, 'while a run spins the '
              'page and /wait answer (%.2f s)' % took)
        w.join(30)
        st, _, body = done.get('reply', (None, None, b'{}'))
        j = json.loads(body)
        msg = (j.get('error') or {}).get('message', '')
        check(st == 200 and 'exceeded the time limit of 2 s' in msg and
              j['figures'] == [] and done.get('took', 99) < 4,
              'the spinning run is stopped at --timeout 2 in %.1f s: %r'
              % (done.get('took', -1), msg))
        after = wait_children(p.pid, 1)
        check(len(before) == 1 and len(after) == 1 and after != before and
              not alive(before[0]), 'the spinning run\'s worker was killed '
              'and a new one waits (%s, then %s)' % (before, after))
        st, _, body = answer(url + 'run', data=b'{"spin": 0}')
        check(st == 200 and json.loads(body).get('error', 1) is None,
              'the next run works')
    finally:
        p.terminate()
        p.wait(10)
    # SIGTERM while a run spins (a time limit far away)
    p, url, port, token = start(tool, script, '--timeout', '100',
                                '--max-instructions', '1e15')
    try:
        def spin_on():
            try:
                request(url + 'run', data=b'{"spin": 1}', timeout=30)
            except OSError:
                pass    # the server stopped: no answer
        w = threading.Thread(target=spin_on)
        w.start()
        time.sleep(1)
        kids = subprocess.run(['pgrep', '-P', str(p.pid)],
                              capture_output=True, text=True).stdout.split()
        check(len(kids) == 1, 'the run is a child process (%s)' % kids)
        t = time.time()
        p.terminate()
        # the server stops listening and kills the run at once (its own
        # exit may take longer under a sanitizer's leak check)
        gone = None
        while time.time() - t < 5 and gone is None:
            try:
                socket.create_connection(('127.0.0.1', port), timeout=1) \
                    .close()
                time.sleep(0.05)
            except OSError:
                gone = time.time() - t
        check(gone is not None and gone < 2, 'SIGTERM: the server stops '
              'listening in %.2f s while a run spins' % (gone or -1))
        check(all(not os.path.exists('/proc/' + k) or
                  open('/proc/%s/stat' % k).read().split(')')[1].split()[0]
                  == 'Z' for k in kids),
              '... and the run\'s process is gone (%.2f s)'
              % (time.time() - t))
        try:
            p.wait(30)
        except subprocess.TimeoutExpired:
            pass
        check(p.returncode == 0, '... and the server exits cleanly in %.1f s'
              % (time.time() - t))
        w.join(10)
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()


def children(pid):
    return subprocess.run(['pgrep', '-P', str(pid)], capture_output=True,
                          text=True).stdout.split()


def wait_children(pid, want, seconds=5):
    t = time.time()
    kids = children(pid)
    while len(kids) != want and time.time() - t < seconds:
        time.sleep(0.05)
        kids = children(pid)
    return kids


def alive(pid):
    try:
        with open('/proc/%s/stat' % pid) as f:
            return f.read().split(')')[1].split()[0] != 'Z'
    except OSError:
        return False


# Appended to a good script: it fails when a run before it in the same
# process left a global, a field of the string table or the string
# metatable's __index behind, and leaves all three.
LEAK = """
assert(rawget(_G, "leaked_global") == nil, "a global of the run before")
assert(rawget(string, "leaked") == nil,
       "the string table of the run before")
assert(rawget(getmetatable(""), "leaked_too") == nil,
       "the string metatable of the run before")
rawset(_G, "leaked_global", true)
rawset(string, "leaked", true)
rawset(getmetatable(""), "leaked_too", true)
"""


def run_ok(url, values=b'{}'):
    st, _, body = answer(url + 'run', data=values)
    j = json.loads(body) if st == 200 else {}
    return st == 200 and j.get('error', 1) is None, j


def test_worker(tool, tmp, good):
    """The runs' process is started ahead of need (this program again,
    `live-worker SCRIPT`, not a fork): one waits before the first request
    and runs the script as it is then (not as it was when it started); it serves the next runs too, each in a fresh sandbox
    (what a run leaves in Lua does not reach the next); a run that fails
    (a script error, a limit) ends it and a new one serves the next run;
    SIGTERM takes the waiting one with the server."""
    script = os.path.join(tmp, 'worker.lua')
    with open(script, 'w') as f:
        f.write(good)
    p, url, port, token = start(tool, script, '--max-memory', '64')
    try:
        kids = wait_children(p.pid, 1)
        check(len(kids) == 1, 'a worker waits before the first request '
              '(%s)' % kids)
        # a program started afresh, not a fork of the server (a fork of a
        # process with threads holds their locks: under ASan such a
        # worker hung now and then, and its page waited for ever)
        argv = open('/proc/%s/cmdline' % kids[0], 'rb').read().split(b'\0')
        check(argv[1:3] == [b'live-worker', script.encode()],
              'the worker is the program started again, "live-worker '
              'SCRIPT" (%s)' % argv)
        # started by hand, without the server's setup: said, nothing run
        helper = os.path.join(os.path.dirname(os.path.abspath(tool)),
                              'curvefig-live')
        r = subprocess.run([helper, 'live-worker', script],
                           capture_output=True, timeout=30)
        check(r.returncode == 2 and r.stdout == b'' and b'not by hand'
              in r.stderr, 'live-worker by hand: no run, status 2, said '
              '(%d, %r)' % (r.returncode, r.stderr[-100:]))
        rd, wr = os.pipe()
        os.write(wr, b'\xff' * 64)
        os.close(wr)
        r = subprocess.run(['sh', '-c', 'exec "$0" live-worker "$1" 4<&%d'
                            % rd, helper, script], pass_fds=(rd,),
                           capture_output=True, timeout=30)
        os.close(rd)
        check(r.returncode in (1, 2) and r.stdout == b'',
              'live-worker with a garbage setup: no run (%d, %r)'
              % (r.returncode, r.stderr[-100:]))
        # saved after that process was started: the run reads it anew
        with open(script, 'w') as f:
            f.write(good.replace('name = "decasteljau"', 'name = "saved"')
                    + LEAK)
        ok, j = run_ok(url)
        names = [g['name'] for g in j.get('figures', [])]
        check(ok and names == ['saved'], 'the waiting process runs the '
              'script as saved since it was started (%s)' % names)
        results = [run_ok(url, b'{"t": %g}' % (0.1 * k)) for k in range(4)]
        later = wait_children(p.pid, 1)
        check(all(r[0] for r in results),
              'four more runs in the same process: none sees the global, '
              'the string table or its metatable the run before left (%s)'
              % [(r[1].get('error') or {}).get('message') for r in results])
        check(later == kids and alive(kids[0]), 'the same worker served '
              'them all (%s, then %s)' % (kids, later))
        # a script error ends the worker; the next run has a new one
        with open(script, 'w') as f:
            f.write(good + '\nerror("on purpose")\n')
        ok, j = run_ok(url)
        msg = (j.get('error') or {}).get('message', '')
        check('on purpose' in msg, 'the script error comes back (%r)' % msg)
        after_error = wait_children(p.pid, 1)
        check(len(after_error) == 1 and after_error != kids and
              not alive(kids[0]), 'a run that failed ended its worker; a '
              'new one waits (%s, then %s)' % (kids, after_error))
        # a run past --max-memory: the same
        with open(script, 'w') as f:
            f.write('local t = {} for i = 1, 1e8 do t[i] = {i} end\n')
        ok, j = run_ok(url)
        msg = (j.get('error') or {}).get('message', '')
        check('memory' in msg, 'a run past --max-memory 64 is an error '
              '(%r)' % msg)
        after_memory = wait_children(p.pid, 1)
        check(len(after_memory) == 1 and after_memory != after_error,
              'it ended its worker too (%s, then %s)'
              % (after_error, after_memory))
        with open(script, 'w') as f:
            f.write(good + LEAK)
        ok, j = run_ok(url, b'{"t": 0.5}')
        ok2, j2 = run_ok(url, b'{"t": 0.25}')
        check(ok and ok2 and wait_children(p.pid, 1) == after_memory,
              'the runs after it work, in the new worker')
        kids = wait_children(p.pid, 1)
        t = time.time()
        p.terminate()
        p.wait(30)
        while kids and alive(kids[0]) and time.time() - t < 2:
            time.sleep(0.05)
        check(p.returncode == 0 and kids and not alive(kids[0]),
              'SIGTERM: the server exits and its waiting worker is gone '
              '(%.2f s)' % (time.time() - t))
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()


def once(tool, script, values):
    """The JSON of `curvefig live SCRIPT --once VALUES`: a run in a process
    of its own."""
    r = subprocess.run([tool, 'live', script, '--once', values],
                       capture_output=True, text=True, timeout=120)
    return json.loads(r.stdout) if r.returncode == 0 else {}


def test_worker_runs(tool, tmp, good):
    """--worker-runs N: a worker serves N runs, then retires and a fresh
    one serves the next (the default, 1000, is the same rule); every run,
    before and after the change of worker, answers exactly what a run in a
    process of its own (--once) does.  A bad N is a usage error."""
    script = os.path.join(tmp, 'runs.lua')
    with open(script, 'w') as f:
        f.write(good)
    for bad in ['0', '-1', '2.5', 'many', '1e10']:
        r = subprocess.run([tool, 'live', script, '--worker-runs', bad],
                           capture_output=True, text=True, timeout=30)
        check(r.returncode == 2 and "--worker-runs '%s': give a whole "
              'number of runs from 1' % bad in r.stderr,
              '--worker-runs %s: a usage error (%d, %r)'
              % (bad, r.returncode, r.stderr.strip()))
    n = 3
    p, url, port, token = start(tool, script, '--worker-runs', str(n))
    try:
        first = wait_children(p.pid, 1)
        check(len(first) == 1, 'a worker waits (%s)' % first)
        workers = []
        for k in range(n + 1):
            values = '{"t": %g}' % (0.2 * (k + 1))
            ok, j = run_ok(url, values.encode())
            want = once(tool, script, values)
            check(ok and j.get('figures') and
                  j.get('figures') == want.get('figures'),
                  'run %d (t = %g) answers as a run of its own does'
                  % (k + 1, 0.2 * (k + 1)))
            workers.append(wait_children(p.pid, 1))
        check(workers[:n - 1] == [first] * (n - 1),
              'runs 1 to %d in the first worker (%s: %s)'
              % (n - 1, first, workers[:n - 1]))
        check(len(workers[n - 1]) == 1 and workers[n - 1] != first and
              not alive(first[0]),
              'after run %d it retired and a fresh worker waits (%s, then '
              '%s)' % (n, first, workers[n - 1]))
        check(workers[n] == workers[n - 1] and alive(workers[n][0]),
              'run %d in the fresh worker, which waits on (%s)'
              % (n + 1, workers[n]))
    finally:
        stop(p, 30)


def test_replaced_script(tool, tmp, good):
    """The script replaced while served, by a directory or a FIFO: an error
    in the page, promptly; the server runs on."""
    script = os.path.join(tmp, 'swap.lua')
    with open(script, 'w') as f:
        f.write(good)
    p, url, port, token = start(tool, script)
    try:
        for kind in ('directory', 'FIFO'):
            os.unlink(script)
            if kind == 'directory':
                os.mkdir(script)
            else:
                os.mkfifo(script)
            t = time.time()
            st, _, body = answer(url + 'run', data=b'{}', timeout=10)
            took = time.time() - t
            msg = (json.loads(body).get('error') or {}).get('message', '')
            check(st == 200 and 'cannot read the script' in msg and
                  ('directory' in msg if kind == 'directory' else
                   'not a regular file' in msg) and took < 2,
                  'the script replaced by a %s: %r in %.2f s'
                  % (kind, msg, took))
            if kind == 'directory':
                os.rmdir(script)
            else:
                os.unlink(script)
            with open(script, 'w') as f:
                f.write(good)
        st, _, body = answer(url + 'run', data=b'{}')
        check(st == 200 and json.loads(body).get('error', 1) is None,
              'the script back: the run works')
    finally:
        stop(p, 5)
    check(p.returncode == 0, 'SIGTERM stops it after a FIFO')


def main():
    tool, src = sys.argv[1], sys.argv[2]
    tmp = tempfile.mkdtemp(prefix='cf-live-')
    script = os.path.join(tmp, 'decasteljau.lua')
    shutil.copy(os.path.join(src, 'figures', 'interactive',
                             'decasteljau.lua'), script)
    p, url, port, token = start(tool, script)
    try:
        base = 'http://127.0.0.1:%d' % port
        check(len(token) >= 32, 'the token has at least 128 bits')

        st, ct, body = request(url)
        check(st == 200 and b'CurvefigPage' in body and
              ct.startswith('text/html'), 'GET /TOKEN/ is the page')
        with urllib.request.urlopen(url, timeout=30) as r:
            csp = r.headers.get('Content-Security-Policy') or ''
        check("default-src 'none'" in csp and "connect-src 'self'" in csp
              and "frame-ancestors 'none'" in csp,
              'the page has a Content-Security-Policy: %r' % csp)
        for host, want in [('127.0.0.1:%d' % port, 200),
                           ('localhost:%d' % port, 200),
                           ('[::1]:%d' % port, 200),
                           ('evil.example:%d' % port, 403),
                           ('127.0.0.1:%d' % (port + 1), 403),
                           ('127.0.0.1', 403), ('', 403)]:
            st = raw_status(port, 'GET /%s/ HTTP/1.1\r\nHost: %s\r\n'
                            'Connection: close\r\n\r\n' % (token, host))
            check(st == want, 'Host %r: %d (got %s)' % (host, want, st))
        for path in ['/', '/run', '/' + token[:-1] + ('1' if token[-1] == '0' else '0') + '/',
                     '/' + 'f' * len(token) + '/',
                     '/' + token + 'x/', '/' + token[:8] + '/']:
            st, _, _ = request(base + path)
            check(st == 403, 'GET %s without the token: 403 (got %d)'
                  % (path[:20], st))
        st, _, _ = request(base + '/', data=b'{}')
        check(st == 403, 'POST without the token: 403')
        st, _, _ = request(url + 'nothing')
        check(st == 404, 'an unknown path with the token: 404')
        st, _, _ = request(url + 'run')
        check(st == 405, 'GET of run: 405')
        st, _, _ = request(url, data=b'x', method='PUT')
        check(st == 405, 'PUT: 405')

        st, ct, body = request(url + 'run', data=b'{"t": 0.5')
        j = json.loads(body)
        check(st == 400 and ct == 'application/json' and
              j['error']['message'].startswith('values:'),
              'bad values: 400 with the JSON error')
        st, _, body = request(url + 'run', data=b'{"t": [1, 2]}')
        check(st == 400, 'values of the wrong shape: 400')
        st, _, body = request(url + 'run', data=b'{"t": 1' + b' ' * (2 << 20)
                              + b'}')
        check(st == 413, 'a body over 1 MiB: 413 (got %d)' % st)

        st, _, body = request(url + 'run', data=b'{"t": 0.3}')
        j = json.loads(body)
        check(st == 200 and j['error'] is None and
              j['params'][1]['value'] == 0.3 and
              j['figures'][0]['svg'].startswith('<?xml'),
              'a run: 200, the values taken, the SVG')

        # a script error, shown, and the server goes on
        with open(script) as f:
            good = f.read()
        st, _, body = request(url + 'wait')
        v0 = json.loads(body)['version']
        done = {}

        def waiter():
            done['reply'] = request(url + 'wait?v=' + v0, timeout=40)
        w = threading.Thread(target=waiter)
        w.start()
        time.sleep(0.5)
        check('reply' not in done, 'the long poll waits while the script '
              'is unchanged')
        time.sleep(0.05)
        with open(script, 'w') as f:
            f.write(good.replace('local c = bezier(P)',
                                 'local c = bezier(P)\nerror("broken")'))
        w.join(10)
        check('reply' in done and json.loads(done['reply'][2])['version']
              != v0, 'saving the script ends the long poll with a new '
              'version')
        st, _, body = request(url + 'run', data=b'{}')
        j = json.loads(body)
        line = good.split('\n').index('local c = bezier(P)') + 2
        check(st == 200 and j['error'] is not None and
              'broken' in j['error']['message'] and
              j['error']['line'] == line and j['figures'] == [],
              'a script error: in the JSON, with its line %d' % line)
        with open(script, 'w') as f:
            f.write(good)
        st, _, body = request(url + 'run', data=b'{}')
        check(st == 200 and json.loads(body)['error'] is None,
              'the server runs on after the error')

        # concurrent runs
        replies = []

        def run(k):
            replies.append(request(url + 'run',
                                   data=('{"t": %g}' % (k / 10)).encode()))
        ts = [threading.Thread(target=run, args=(k,)) for k in range(8)]
        for t in ts:
            t.start()
        for t in ts:
            t.join(60)
        ok = len(replies) == 8 and all(
            r[0] == 200 and json.loads(r[2])['error'] is None
            for r in replies)
        check(ok, 'eight concurrent runs all answer')

        # garbage and a half request on raw sockets
        for junk in [b'\x00\xff garbage\r\n\r\n', b'GET /' + token.encode(),
                     b'POST /%s/run HTTP/1.1\r\nContent-Length: 99999999\r\n'
                     b'\r\n{' % token.encode()]:
            s = socket.create_connection(('127.0.0.1', port), timeout=5)
            s.sendall(junk)
            s.close()
        time.sleep(0.3)
        st, _, _ = request(url)
        check(p.poll() is None and st == 200, 'garbage on the socket: the '
              'server runs on')

        # listening on 127.0.0.1 only (/proc/net/tcp: local address)
        with open('/proc/net/tcp') as f:
            rows = [l.split() for l in f.read().splitlines()[1:]]
        mine = [r[1] for r in rows if r[3] == '0A' and
                int(r[1].split(':')[1], 16) == port]
        check(mine == ['0100007F:%04X' % port], 'it listens on 127.0.0.1 '
              'only (%s)' % mine)
        test_idle_connections(url, port)
    finally:
        p.terminate()
        try:
            p.wait(10)
        except subprocess.TimeoutExpired:
            p.kill()
    check(p.returncode == 0, 'SIGTERM stops the server cleanly')
    try:
        test_spinning_run(tool, tmp, good)
        test_replaced_script(tool, tmp, good)
        test_worker(tool, tmp, good)
        test_worker_runs(tool, tmp, good)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        sys.exit('%d failures' % len(failures))


main()
