#!/usr/bin/env python3
"""Compile and link a standalone WebAssembly module with emcc.

usage: emcc-build.py EMCC OUT.wasm OBJDIR [options] -- FLAGS -- SOURCES
  --cxx-dir DIR  the sources under DIR are compiled as C++ (Lua: its
                 errors become wasm exceptions instead of setjmp/longjmp);
                 the others as C11
  --export NAME  a function the module exports
Each source is compiled once (a name given twice, once) into OBJDIR, two
at a time, then linked.
"""
import concurrent.futures
import os
import subprocess
import sys


def main(argv):
    emcc, out, objdir = argv[1:4]
    rest = argv[4:]
    split = rest.index('--')
    opts, rest = rest[:split], rest[split + 1:]
    split = rest.index('--')
    flags, paths = rest[:split], rest[split + 1:]
    cxx_dirs, exports, sources = [], [], []
    i = 0
    while i < len(opts):
        key, val = opts[i], opts[i + 1]
        if key == '--cxx-dir':
            cxx_dirs.append(os.path.realpath(val) + os.sep)
        elif key == '--export':
            exports.append(val)
        else:
            sys.exit('emcc-build.py: unknown option ' + key)
        i += 2
    for p in dict.fromkeys(os.path.realpath(p) for p in paths):
        cxx = any(p.startswith(d) for d in cxx_dirs)
        sources.append(('cxx' if cxx else 'c', p))
    os.makedirs(objdir, exist_ok=True)
    common = ['-O2', '-fwasm-exceptions'] + flags

    def compile_one(src):
        lang, path = src
        base = os.path.basename(path)[:-2]
        obj = os.path.join(objdir, lang + '-' + base + '.o')
        if lang == 'c':
            cmd = [emcc, '-std=c11', '-D_POSIX_C_SOURCE=200809L']
        else:
            cmd = [emcc, '-x', 'c++', '-Wno-deprecated']
        cmd += common + ['-c', path, '-o', obj]
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            return obj, ' '.join(cmd) + '\n' + r.stderr
        return obj, None

    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(compile_one, sources))
    failed = [err for _, err in results if err]
    if failed:
        sys.stderr.write('\n'.join(failed))
        return 1
    link = [emcc, '-O2', '-fwasm-exceptions', '-sSTANDALONE_WASM',
            '--no-entry', '-sALLOW_MEMORY_GROWTH=1',
            '-sEXPORTED_FUNCTIONS=' + ','.join(
                ['_malloc', '_free'] + ['_' + e for e in exports]),
            '-o', out] + [obj for obj, _ in results]
    r = subprocess.run(link, capture_output=True, text=True)
    if r.returncode != 0:
        sys.stderr.write(' '.join(link) + '\n' + r.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
