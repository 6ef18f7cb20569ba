#!/usr/bin/env python3
"""The shared library exports exactly its documented API.

Usage: exports.py NM LIBRARY HEADER...

The names NM -D --defined-only lists for LIBRARY must be exactly the
functions the installed HEADERs declare with CF_API: nothing internal
(cf__) leaks out, and nothing declared is missing.
"""
import re
import subprocess
import sys

DECL = re.compile(r'^CF_API\b[^;{]*?\b(cf_[a-z0-9_]+)\s*\(', re.M)


def declared(headers):
    names = set()
    for h in headers:
        with open(h, encoding='utf-8') as f:
            names.update(DECL.findall(f.read()))
    return names


def exported(nm, lib):
    out = subprocess.run([nm, '-D', '--defined-only', lib], check=True,
                         capture_output=True, text=True).stdout
    names = set()
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3:
            names.add(parts[2])
    return names


def main():
    nm, lib, headers = sys.argv[1], sys.argv[2], sys.argv[3:]
    dec, exp = declared(headers), exported(nm, lib)
    ok = True
    for name in sorted(exp - dec):
        print('exported but not declared with CF_API:', name)
        ok = False
    for name in sorted(dec - exp):
        print('declared with CF_API but not exported:', name)
        ok = False
    if not dec:
        print('no CF_API declarations found')
        ok = False
    if ok:
        print('%d functions exported, all declared' % len(exp))
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
