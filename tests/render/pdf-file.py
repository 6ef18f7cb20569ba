#!/usr/bin/env python3
"""The PDF writer's files hold together, and the same input gives the same
bytes.

    pdf-file.py CURVEFIG SCRIPT...

Each figure of each script is rendered as PDF twice (in two directories):
  - the two files are the same bytes;
  - startxref is the offset of the xref table; every in-use entry of the
    table points at "N 0 obj" of its own number; the table has an entry
    for every object and every object is in the table;
  - every stream's /Length is the number of bytes between "stream\\n" and
    "\\nendstream", and each (Flate) stream inflates;
  - the page count is pdfinfo's, and pdfinfo reads the file without a
    syntax error.
"""
import glob
import os
import re
import subprocess
import sys
import tempfile
import zlib

OBJ = re.compile(rb'(\d+) 0 obj\n')


def check_file(path, fails):
    data = open(path, 'rb').read()
    name = os.path.basename(path)

    def check(cond, what):
        if not cond:
            fails.append('%s: %s' % (name, what))
        return cond

    check(data.startswith(b'%PDF-1.'), 'header')
    check(data.endswith(b'%%EOF\n'), 'ends with %%EOF')
    m = re.search(rb'startxref\n(\d+)\n%%EOF\n$', data)
    if not check(m is not None, 'startxref'):
        return
    x = int(m.group(1))
    t = re.match(rb'xref\n0 (\d+)\n', data[x:])
    if not check(t is not None, 'startxref is the xref table\'s offset'):
        return
    n, at = int(t.group(1)), x + t.end()
    offsets = {}
    for i in range(n):
        e = data[at + 20 * i: at + 20 * i + 20]
        check(len(e) == 20 and e[10:11] == b' ' and e[16:17] == b' '
              and e[18:20] == b' \n', 'xref entry %d is 20 bytes' % i)
        if e[17:18] == b'n':
            off = int(e[:10])
            offsets[i] = off
            check(data[off:].startswith(b'%d 0 obj\n' % i),
                  'xref entry %d points at its object' % i)
    objects = {int(o.group(1)): o.start() for o in OBJ.finditer(data[:x])
               if o.start() == 0 or data[o.start() - 1:o.start()] == b'\n'}
    check(sorted(objects) == sorted(offsets),
          'the objects are those of the table')
    check(re.search(rb'/Size %d\b' % n, data[x:]) is not None,
          'trailer /Size')
    # streams
    streams = 0
    for o, off in objects.items():
        end = data.index(b'endobj', off)
        body = data[off:end]
        s = body.find(b'>>\nstream\n')
        if s < 0:
            continue
        streams += 1
        length = re.search(rb'/Length (\d+)', body[:s])
        if not check(length is not None, 'object %d: /Length' % o):
            continue
        start = s + len(b'>>\nstream\n')
        k = body.find(b'\nendstream\n', start)
        check(k - start == int(length.group(1)),
              'object %d: /Length %s is its %d bytes'
              % (o, length.group(1).decode(), k - start))
        if b'/FlateDecode' in body[:s]:
            try:
                zlib.decompress(body[start:k])
            except zlib.error as e:
                check(False, 'object %d: inflates: %s' % (o, e))
    check(streams > 0, 'has streams')
    info = subprocess.run(['pdfinfo', path], capture_output=True, text=True)
    pages = len(re.findall(rb'/Type /Page\b', data))
    m = re.search(r'Pages:\s+(\d+)', info.stdout)
    check(info.returncode == 0 and 'Syntax' not in info.stderr
          and m is not None and int(m.group(1)) == pages,
          'pdfinfo reads it: %s %s' % (info.stdout, info.stderr))


def main(argv):
    tool, scripts = os.path.abspath(argv[1]), argv[2:]
    fails, files = [], 0
    with tempfile.TemporaryDirectory() as tmp:
        for script in scripts:
            dirs = []
            for k in range(2):
                d = os.path.join(tmp, '%d-%s' % (k, os.path.basename(script)))
                subprocess.run([tool, 'render', script, '-f', 'pdf', '-o', d],
                               check=True, capture_output=True)
                dirs.append(d)
            for path in sorted(glob.glob(os.path.join(dirs[0], '*.pdf'))):
                files += 1
                other = os.path.join(dirs[1], os.path.basename(path))
                if open(path, 'rb').read() != open(other, 'rb').read():
                    fails.append('%s: two renders differ' % path)
                check_file(path, fails)
    for f in fails:
        print('FAIL', f)
    print('%d files checked, %d failures' % (files, len(fails)))
    return 1 if fails or files == 0 else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
