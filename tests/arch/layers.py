#!/usr/bin/env python3
"""The object files of a library call downward only.

Usage: layers.py NM ARCHIVE [--folders DIR LAYER,LAYER,...]
                  [--cairo-in FOLDER,FOLDER,...]

Runs NM over the object files of ARCHIVE (a library's objects) and
builds the graph "A calls B" (a symbol undefined in A is defined in B).
Fails, naming the objects and the symbols, when two objects call each other
directly or around a circle; prints the layers (each object with the objects
it calls) when there is none.

With --folders, DIR holds one folder per layer, the LAYERs named from the
bottom up (the renderer: render/ with base, labels, dlist, ...; see
docs/library.md, "How the renderer is built").  Then it also fails when
an object of one folder calls an object of a folder above it (objects are
named FOLDER_FILE.c.o, as meson names them), and when a source or header of
a folder includes a header of a folder above it.

With --cairo-in (after --folders), only the sources and headers of the
named folders of DIR may include cairo's or pango's headers (<cairo*.h>,
<pango/...>): a file of any other folder of DIR fails, whether it
includes them itself or through a header of DIR that does (a quoted
include, followed to any depth).
"""
import os
import re
import subprocess
import sys


def symbols(nm, archive):
    out = subprocess.run([nm, '-A', archive], check=True,
                         capture_output=True, text=True).stdout
    defined, undefined = {}, {}
    for line in out.splitlines():
        name, _, rest = line.rpartition(':')
        obj = os.path.basename(name.rsplit(':', 1)[-1])
        if not obj.endswith('.o'):
            continue
        defined.setdefault(obj, set())
        undefined.setdefault(obj, set())
        parts = rest.split()
        if len(parts) == 2 and parts[0] == 'U':
            undefined[obj].add(parts[1])
        elif len(parts) == 3 and parts[1] in 'TDRBCVW':
            defined[obj].add(parts[2])
    return defined, undefined


def call_graph(defined, undefined):
    owner = {}
    for obj, syms in defined.items():
        for s in syms:
            owner[s] = obj
    graph = {obj: {} for obj in defined}
    for obj, syms in undefined.items():
        for s in sorted(syms):
            callee = owner.get(s)
            if callee is not None and callee != obj:
                graph[obj].setdefault(callee, []).append(s)
    return graph


def cycles(graph):
    """Strongly connected components with more than one object (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def folder_of(obj, layers):
    head = obj.split('_', 1)[0]
    return head if head in layers else None


def upward_calls(graph, layers):
    """Calls from an object of one layer folder to one of a higher one."""
    rank = {name: i for i, name in enumerate(layers)}
    out = []
    for a in sorted(graph):
        fa = folder_of(a, layers)
        for b, syms in sorted(graph[a].items()):
            fb = folder_of(b, layers)
            if fa is not None and fb is not None and rank[fb] > rank[fa]:
                out.append('%s (%s) calls %s (%s, above it): %s'
                           % (a, fa, b, fb, ', '.join(syms)))
    return out


INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def upward_includes(top, layers):
    """Includes of a header of a higher layer folder (by the header's file
    name: the folders are include directories, their names unique)."""
    rank = {name: i for i, name in enumerate(layers)}
    home, files = {}, []
    for d in layers:
        folder = os.path.join(top, d)
        if not os.path.isdir(folder):
            raise SystemExit('layers.py: no folder %s' % folder)
        for f in sorted(os.listdir(folder)):
            if f.endswith(('.c', '.h')):
                files.append((d, os.path.join(folder, f)))
                if f.endswith('.h'):
                    if f in home:
                        raise SystemExit('layers.py: %s in %s and %s'
                                         % (f, home[f], d))
                    home[f] = d
    out = []
    for d, path in files:
        with open(path, encoding='utf-8') as f:
            text = f.read()
        for m in INCLUDE.finditer(text):
            h = os.path.basename(m.group(1))
            hd = home.get(h)
            if hd is not None and rank[hd] > rank[d]:
                line = text.count('\n', 0, m.start()) + 1
                out.append('%s:%d (%s) includes %s (%s, above it)'
                           % (os.path.relpath(path, top), line, d, h, hd))
    return out


SYSTEM = re.compile(r'^\s*#\s*include\s+<((?:cairo|pango)[^>]*)>', re.M)


def cairo_includes(top, allowed):
    """Files of top's folders other than allowed that include cairo's or
    pango's headers, directly or through headers of top (by file name)."""
    headers, files = {}, []
    for d in sorted(os.listdir(top)):
        folder = os.path.join(top, d)
        if not os.path.isdir(folder):
            continue
        for f in sorted(os.listdir(folder)):
            if f.endswith(('.c', '.h')):
                path = os.path.join(folder, f)
                files.append((d, path))
                if f.endswith('.h'):
                    headers.setdefault(f, path)
    text = {}
    for _, path in files:
        with open(path, encoding='utf-8') as f:
            text[path] = f.read()
    memo = {}

    def reaches(path, seen):
        """The chain of includes from path to a cairo or pango header,
        or None."""
        if path in memo:
            return memo[path]
        m = SYSTEM.search(text[path])
        found = None
        if m is not None:
            found = ['<%s>' % m.group(1)]
        else:
            for inc in INCLUDE.finditer(text[path]):
                h = headers.get(os.path.basename(inc.group(1)))
                if h is None or h in seen:
                    continue
                chain = reaches(h, seen | {h})
                if chain is not None:
                    found = [os.path.basename(h)] + chain
                    break
        memo[path] = found
        return found

    out = []
    for d, path in files:
        if d in allowed:
            continue
        chain = reaches(path, {path})
        if chain is not None:
            out.append('%s (%s) includes %s: only %s may include cairo or '
                       'pango' % (os.path.relpath(path, top), d,
                                  ' -> '.join(chain), ', '.join(allowed)))
    return out


def main():
    args = sys.argv[1:]
    layers, top, cairo_in = None, None, None
    if '--cairo-in' in args:
        i = args.index('--cairo-in')
        cairo_in = args[i + 1].split(',')
        del args[i:i + 2]
    if '--folders' in args:
        i = args.index('--folders')
        top, layers = args[i + 1], args[i + 2].split(',')
        del args[i:i + 3]
    nm, archive = args[0], args[1]
    defined, undefined = symbols(nm, archive)
    if len(defined) < 2:
        print('no object files found in', archive)
        return 1
    graph = call_graph(defined, undefined)
    if layers is not None:
        unknown = sorted(o for o in graph if folder_of(o, layers) is None)
        upward = upward_calls(graph, layers) + upward_includes(top, layers)
        if cairo_in is not None:
            upward += cairo_includes(top, cairo_in)
        for line in ['object %s is in no layer folder' % o
                     for o in unknown] + upward:
            print(line)
        if unknown or upward:
            return 1
    bad = cycles(graph)
    for comp in bad:
        print('call cycle among', ', '.join(comp))
        for a in comp:
            for b, syms in sorted(graph[a].items()):
                if b in comp:
                    print('  %s -> %s: %s' % (a, b, ', '.join(syms)))
    if bad:
        return 1
    for a in sorted(graph):
        print('%s -> %s' % (a, ' '.join(sorted(graph[a])) or '(libc, libm)'))
    return 0


if __name__ == '__main__':
    sys.exit(main())
