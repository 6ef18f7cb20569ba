#!/usr/bin/env python3
"""Fail when a shared library exports anything but the functions its
public headers declare with CF_API, or misses one of them.

usage: exports.py NM LIBRARY.so HEADER...
"""
import re
import subprocess
import sys


def main():
    nm, lib, headers = sys.argv[1], sys.argv[2], sys.argv[3:]
    out = subprocess.run([nm, '-D', '--defined-only', lib], check=True,
                         capture_output=True, text=True).stdout
    exported = {line.split()[-1] for line in out.splitlines()
                if len(line.split()) == 3}
    declared = set()
    for h in headers:
        with open(h, encoding='utf-8') as f:
            text = f.read()
        declared |= set(re.findall(r'^CF_API[^(;]*?\b(cf_\w+)\(', text,
                                   re.M))
    extra, missing = sorted(exported - declared), sorted(declared - exported)
    for s in extra:
        print('exported but not declared with CF_API: ' + s)
    for s in missing:
        print('declared with CF_API but not exported: ' + s)
    print('%d exported, %d declared' % (len(exported), len(declared)))
    return 1 if extra or missing or not declared else 0


if __name__ == '__main__':
    sys.exit(main())
