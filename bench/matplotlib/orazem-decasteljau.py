# orazem-decasteljau (figures/orazem-decasteljau.lua) drawn with matplotlib,
# for the one-figure speed comparison of bench/bench_figures.c: the same
# picture (the Bézier curve P_0..P_4 = (0,5) (1,-1) (3,0) (4,3) (6,10) in
# red, de Casteljau's levels at t = 3/4 in black, blue, orange and yellow
# with their points, b_0^4(3/4) as a green star, the labels P_0..P_4 and
# b_0^4(3/4) in Computer Modern math) on an 8 cm x 10.5 cm page, written as
# SVG, PDF and PNG (150 dpi) -- what `curvefig render -f svg,pdf,png` does.
#
#   python3 orazem-decasteljau.py OUTDIR
#
# matplotlib's fastest route is taken: matplotlib.figure.Figure without
# pyplot (no GUI backend is imported), the curve sampled once with numpy.
import sys

import matplotlib
import numpy as np
from matplotlib.figure import Figure

out = sys.argv[1] if len(sys.argv) > 1 else "."
P = np.array([(0, 5), (1, -1), (3, 0), (4, 3), (6, 10)], float)
t = 0.75

# the curve: Bernstein form at 256 parameters
n = len(P) - 1
u = np.linspace(0.0, 1.0, 256)[:, None]
binom = [1, 4, 6, 4, 1]
curve = sum(binom[i] * u**i * (1 - u)**(n - i) * P[i] for i in range(n + 1))

# de Casteljau's levels at t
levels = [P]
while len(levels[-1]) > 1:
    b = levels[-1]
    levels.append((1 - t) * b[:-1] + t * b[1:])

matplotlib.rcParams["mathtext.fontset"] = "cm"
fig = Figure(figsize=(8 / 2.54, 10.5 / 2.54))
ax = fig.add_axes([0.05, 0.03, 0.9, 0.94])
ax.set_aspect("equal")
ax.set_axis_off()
ax.plot(curve[:, 0], curve[:, 1], color="red", lw=1.5)
colors = ["black", "blue", "orange", "#e8b800"]
for k, col in enumerate(colors):
    b = levels[k]
    ax.plot(b[:, 0], b[:, 1], color=col, lw=1.0, marker="o", ms=3)
end = levels[-1][0]
ax.plot([end[0]], [end[1]], marker="*", color="green", ms=11)
offsets = {"w": (-11, 0), "s": (0, -11), "se": (8, -9), "e": (11, 0)}
for i, pl in enumerate(["w", "s", "se", "e", "w"]):
    ax.annotate(f"$P_{i}$", P[i], xytext=offsets[pl],
                textcoords="offset points", ha="center", va="center",
                fontsize=10)
ax.annotate(r"$b_0^4(3/4)$", end, xytext=(-22, 0), textcoords="offset points",
            ha="center", va="center", fontsize=10, color="green")
for ext in ("svg", "pdf", "png"):
    fig.savefig(f"{out}/orazem-decasteljau.{ext}", dpi=150)
