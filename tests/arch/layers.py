#!/usr/bin/env python3
"""The object files of a library call downward only.

Usage: layers.py NM ARCHIVE

Runs NM over the object files of ARCHIVE (a library's objects) and
builds the graph "A calls B" (a symbol undefined in A is defined in B).
Fails, naming the objects and the symbols, when two objects call each other
directly or around a circle; prints the layers (each object with the objects
it calls) when there is none.
"""
import os
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


def main():
    nm, archive = sys.argv[1], sys.argv[2]
    defined, undefined = symbols(nm, archive)
    if len(defined) < 2:
        print('no object files found in', archive)
        return 1
    graph = call_graph(defined, undefined)
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
