#!/usr/bin/env python3
"""Every public function that takes a diag resets it on entry.

Usage: diag-reset.py SOURCE_ROOT

The rule of curvefig/core.h: after any call that takes a cf_diag_t, the
diag describes that call (its failure, or no error), never an earlier one
and never uninitialised memory.  Every function declared with CF_API in
include/curvefig/ whose parameters end in `cf_diag_t *diag` must begin with
`cf_diag_clear(diag);` where it is defined (src/, render/).  cf_diag_clear
and cf_diag_set, which exist to fill a diag, are the exceptions.
"""
import glob
import os
import re
import sys

EXEMPT = {'cf_diag_clear', 'cf_diag_set'}
DECL = re.compile(r'CF_API\b[^;{]*?\b(cf_[a-z0-9_]+)\s*\(([^;]*?)\)\s*;', re.S)


def main(root):
    wanted = set()
    for h in glob.glob(os.path.join(root, 'include', 'curvefig', '*.h*')):
        with open(h, encoding='utf-8') as f:
            for m in DECL.finditer(f.read()):
                if re.search(r'cf_diag_t\s*\*\s*diag\s*$', m.group(2)):
                    wanted.add(m.group(1))
    wanted -= EXEMPT
    found, bad = set(), []
    for c in sorted(glob.glob(os.path.join(root, 'src', '*.c')) +
                    glob.glob(os.path.join(root, 'render', '*', '*.c'))):
        with open(c, encoding='utf-8') as f:
            text = f.read()
        for name in wanted:
            m = re.search(r'^%s\([^;{]*?\)\s*\n\{\n([^\n]*)' % name, text,
                          re.M | re.S)
            if m is None:
                continue
            found.add(name)
            if m.group(1).strip() != 'cf_diag_clear(diag);':
                bad.append('%s (%s): first statement is "%s"'
                           % (name, os.path.relpath(c, root),
                              m.group(1).strip()))
    for name in sorted(wanted - found):
        bad.append('%s: declared with a diag, definition not found' % name)
    for b in bad:
        print('diag-reset: ' + b)
    print('%d functions with a diag, %d reset it on entry'
          % (len(wanted), len(found) - len([b for b in bad if '(' in b])))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1]))
