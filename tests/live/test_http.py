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
socket listens on 127.0.0.1 only.
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


def start(tool, script):
    p = subprocess.Popen([tool, 'live', script, '--port', '0'],
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
    finally:
        p.terminate()
        try:
            p.wait(10)
        except subprocess.TimeoutExpired:
            p.kill()
        shutil.rmtree(tmp, ignore_errors=True)
    check(p.returncode == 0, 'SIGTERM stops the server cleanly')
    if failures:
        sys.exit('%d failures' % len(failures))


main()
