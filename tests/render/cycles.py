#!/usr/bin/env python3
"""Fail when object files of a static library call each other in a circle.

usage: cycles.py NM LIBRARY.a

Each member's undefined symbols are matched with the members that define
them; the strongly connected components of that graph with more than one
member are cycles ("layers call downward only").  Prints the edges of
every cycle with the symbols that make them.
"""
import os
import re
import subprocess
import sys

# "archive:member.o:0000 T name" or "archive:member.o:      U name"
LINE = re.compile(r'^(?:.*?:)?([^:]*\.o):\s*(?:[0-9a-f]+\s+)?([A-Za-z])\s+(\S+)$')


def members(nm, lib):
    out = subprocess.run([nm, '--print-file-name', lib], check=True,
                         capture_output=True, text=True).stdout
    defs, uses = {}, {}
    for line in out.splitlines():
        m = LINE.match(line)
        if m is None:
            continue
        member = os.path.basename(m.group(1))
        kind, name = m.group(2), m.group(3)
        uses.setdefault(member, set())
        if kind == 'U':
            uses[member].add(name)
        elif kind in 'TDRBVW':
            defs[name] = member
    return defs, uses


def sccs(graph):
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
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
            out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def main():
    nm, lib = sys.argv[1], sys.argv[2]
    defs, uses = members(nm, lib)
    graph = {m: set() for m in uses}
    why = {}
    for m, syms in uses.items():
        for s in syms:
            d = defs.get(s)
            if d is not None and d != m:
                graph[m].add(d)
                why.setdefault((m, d), []).append(s)
    if len(graph) < 2 or not any(graph.values()):
        print('no calls between members: is this the right library?')
        return 1
    bad = [c for c in sccs(graph) if len(c) > 1]
    for comp in bad:
        print('cycle among: ' + ' '.join(comp))
        for a in comp:
            for b in sorted(graph[a]):
                if b in comp:
                    print('  %s -> %s (%s)' % (a, b,
                                              ', '.join(sorted(why[(a, b)]))))
    edges = sum(len(v) for v in graph.values())
    print('%d objects, %d calling edges, %d cycles' % (len(graph), edges,
                                                       len(bad)))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
