#!/usr/bin/python3
"""The animation target (docs/animations.md): the de Casteljau example as
a 120-frame GIF in under 2 s on a 2-core machine.

usage: anim.py CURVEFIG SOURCE_DIR [RUNS]

`curvefig render figures/interactive/decasteljau.lua --sweep t=0:1
--frames 120 -f gif` as whole processes, RUNS times (default 5), with the
frames drawn by as many processes as the machine has cores and, side by
side in the same loop, by one (--workers 1); one JSON line each with the
median wall time and the median CPU time of the process and its children
(user + system), and whether the median wall time meets the target.
"""
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

TARGET_S = 2.0


def one(tool, script, outdir, extra):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    r = subprocess.run([tool, 'render', script, '--sweep', 't=0:1',
                        '--frames', '120', '-f', 'gif', '-o', outdir] + extra,
                       capture_output=True, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        print('curvefig failed:', r.stderr, file=sys.stderr)
        sys.exit(1)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime
                                                - before.ru_stime)
    return wall, cpu


def main():
    tool, src = sys.argv[1], sys.argv[2]
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 5
    script = os.path.join(src, 'figures', 'interactive', 'decasteljau.lua')
    variants = [('cores', []), ('one-process', ['--workers', '1'])]
    times = {name: [] for name, _ in variants}
    with tempfile.TemporaryDirectory() as outdir:
        one(tool, script, outdir, [])   # warm the caches
        for _ in range(runs):
            for name, extra in variants:
                times[name].append(one(tool, script, outdir, extra))
        size = os.path.getsize(os.path.join(outdir, 'decasteljau.gif'))
    for name, _ in variants:
        wall = statistics.median(t[0] for t in times[name])
        cpu = statistics.median(t[1] for t in times[name])
        print(json.dumps({
            'benchmark': 'anim-gif-120', 'workers': name,
            'cores': os.cpu_count(), 'runs': runs,
            'median_wall_s': round(wall, 3), 'median_cpu_s': round(cpu, 3),
            'gif_bytes': size, 'target_s': TARGET_S,
            'meets_target': wall < TARGET_S}))


if __name__ == '__main__':
    main()
