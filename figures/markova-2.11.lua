-- markova-2.11 (seed 002, "B-spline křivky", §2.6 "Posouvání řídicích
-- bodů", Obr. 2.11 "Změna P_4").
-- Both curves of markova-2.9/2.10 in one figure: the sample curve C(u)
-- (p = 2, U = {0,0,0,0.17,0.33,0.5,0.67,0.83,1,1,1}; dashed) and the curve
-- D(u) = C(u) + N_4^2(u) v after P_4 is moved to P_4 + v (solid), with the
-- translation vector v drawn as an arrow at P_4.  v = (0, -1) (P_4 = (3, 3)
-- -> (3, 2)) is this script's choice, the same as in markova-2.10.  The
-- arc of D on [u_4, u_{4+p+1}) = [u_4, u_7) = [0.33, 0.83) -- the only
-- part that moves -- is orange, its end points C(u_4) = D(u_4) and
-- C(u_7) = D(u_7) are marked.  Old polygon dashed, new polygon solid.
-- Checked with `curvefig run` on 10001 samples of [0, 1]: max |C - D| is
-- exactly 0 outside [0.33, 0.83) and 0.746 (= max N_4^2 * |v|) inside, and
-- D(u) - C(u) - N_4^2(u) v is below 1e-15 everywhere; the script asserts
-- both (tolerance 1e-12).  Same window as markova-2.9/2.10, drawn larger
-- (8 cm instead of 6.5 cm) so the labels around P_4 find room.

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local place = { "s", "se", "e", "n", "w", "n", "w", "sw" }
local c = bspline{ degree = 2, knots = U, points = P }
local v = { 0, -1 }
local d = c:move_point(4, v)
local lo, hi = c:support(4)
assert(lo == U[5] and hi == U[8])
for j = 0, 1000 do
  local u = j / 1000
  local a, b, N = c:eval(u), d:eval(u), basis(U, 4, 2, u)
  assert(math.abs(a[1] + N * v[1] - b[1])
         + math.abs(a[2] + N * v[2] - b[2]) < 1e-12)
  assert(N == 0 or (u >= lo and u < hi))
end

local f = figure{
  name = "markova-2.11",
  caption = "Moving P_4 by v = (0, -1): the new curve D(u) = C(u) + N_4^2(u) v "
    .. "(solid) differs from the sample curve C(u) (dashed) only on "
    .. "[u_4, u_7) = [0.33, 0.83) (orange) (Obr. 2.11: Změna P_4)",
  width = "8cm", height = "6.65cm", window = { 0.45, 5.55, 0.55, 4.45 },
}
local Q = d:points()
f:polyline(P, { color = "#8c8c8c", width = 0.6, dash = "dashed" })
f:polyline(Q, { color = "#8c8c8c", width = 0.6 })
f:curve(c, { dash = "dashed", width = 1.2, color = "#5a7bbf" })
f:curve(d)
f:curve(d, { range = { lo, hi }, color = "#e8821e", width = 3 })
f:arrow(P[5], v)
f:label({ P[5][1], P[5][2] - 0.24 }, "v", { place = "e", offset = 2, color = "#b22222" })
local ends = { c:eval(lo), c:eval(hi) }
f:points(ends, { marker = "dot", marker_size = 4.5, marker_color = "black" })
f:label(ends[1], "C(u_4)", { place = "e" })
f:label(ends[2], "C(u_7)", { place = "w" })
f:points(P, { color = "#3c3c3c", marker_color = "#3c3c3c" })
f:points(Q[5], { color = "#3c3c3c", marker_color = "#3c3c3c" })
for i, q in ipairs(P) do
  f:label(q, string.format("P_%d", i - 1), { place = place[i] })
end
f:label(Q[5], "P_4 + v", { place = "s" })
