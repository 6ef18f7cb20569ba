-- markova-3.1, markova-3.2 (seed 002, "B-spline křivky", chapter 3,
-- section 3.1.1 "Vložení jednoduchého uzlu", Obr. 3.1 "Původní křivka"
-- and Obr. 3.2 "Nový uzel t = 0.6").
--
-- Knot insertion into the thesis' sample curve (p = 2, P_0..P_7, U as
-- given).  t = 0.6 lies in the knot span [u_5, u_6) = [0.5, 0.67), so
-- k = 5: the new points Q_i = (1 - a_i) P_{i-1} + a_i P_i,
-- a_i = (t - u_i) / (u_{i+p} - u_i), k - p + 1 <= i <= k, are Q_4 on the
-- leg P_3 P_4 and Q_5 on the leg P_4 P_5; the corner at P_4 is "cut off"
-- (p - 1 = 1 old point removed, p = 2 new points).
--   markova-3.1: the original curve, its polygon and its knot points
--                C(u_i), with the span [u_5, u_6) that receives t drawn
--                in green and a pointer to where t = 0.6 lies.
--   markova-3.2: the curve after inserting t = 0.6 (the same curve), the
--                new polygon P_0 P_1 P_2 P_3 Q_4 Q_5 P_5 P_6 P_7, the cut
--                corner P_3 P_4 P_5 of the old polygon dashed with P_4 as
--                a hollow marker, the new points Q_4, Q_5 in blue and the
--                knot points of the new knot vector, the new knot point
--                C(0.6) as a green dot labelled t = 0.6.
-- Both figures share one window and size.
-- The thesis gives no further data; the colours are this project's.

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local s = bspline{ degree = 2, knots = U, points = P }
local t = 0.6

local window = { 0.6, 5.4, 0.7, 4.45 }
local W, H = "10cm", "7.8cm"
-- label places of P_0..P_7 (outside the polygon, away from the curve)
local place = { "s", "w", "e", "n", "s", "n", "w", "e" }
local function Plabels(i)
  return string.format("P_%d", i)
end

-- markova-3.1 ----------------------------------------------------------------
local f = figure{
  name = "markova-3.1",
  caption = "Knot insertion, the original curve: the sample curve " ..
            "(p = 2) with its control polygon and knot points; t = 0.6 " ..
            "lies in the span [u_5, u_6) (Obr. 3.1: Původní křivka)",
  width = W, height = H, window = window,
}
f:polygon(s, { })
for i = 0, 7 do
  f:label(P[i + 1], Plabels(i), { place = place[i + 1] })
end
f:curve(s)
f:curve(s, { range = { U[6], U[7] }, color = "darkgreen", width = 2.2 })
f:knots(s)
-- the ends of the span, named as in the text
f:label(s:eval(U[6]), "C(u_5)", { color = "darkgreen", font_size = 8.5 })
f:label(s:eval(U[7]), "C(u_6)", { color = "darkgreen", font_size = 8.5 })
-- where t will go: a pointer from above the dip of the curve
local function mark_t(fig, c)
  local ct = c:eval(t)
  fig:arrow_to({ ct[1] + 0.05, 4.12 }, { ct[1], ct[2] + 0.06 },
               { color = "darkgreen", width = 0.7 })
  fig:label({ ct[1] + 0.05, 4.12 }, "t = 0.6", { place = "n", color = "darkgreen" })
end
mark_t(f, s)

-- markova-3.2 ----------------------------------------------------------------
local n, info = s:insert_knot(t)
local Q = n:points()
-- the curve is unchanged (to 1e-12 of the unit size, 101 parameters)
for i = 0, 100 do
  local a, b = s:eval(i / 100), n:eval(i / 100)
  assert(math.abs(a[1] - b[1]) < 1e-12 and math.abs(a[2] - b[2]) < 1e-12)
end
assert(info.span == 5 and info.cut_first == 4 and info.cut_count == 1
       and info.new_first == 4 and info.new_count == 2)

local g = figure{
  name = "markova-3.2",
  caption = "Knot insertion t = 0.6: the corner at P_4 of the old " ..
            "polygon (dashed) is cut off and replaced by the new points " ..
            "Q_4, Q_5 (blue, over the thinner curve); the curve is " ..
            "unchanged (Obr. 3.2: Nový uzel t = 0.6)",
  width = W, height = H, window = window,
}
-- the old polygon's cut corner P_3 P_4 P_5, dashed, P_4 hollow
g:polyline({ P[4], P[5], P[6] }, { color = "grey", dash = "dashed", width = 0.8 })
g:points({ P[5] }, { marker = "circle", color = "grey", marker_color = "grey",
                     fill = "white" })
g:label(P[5], "P_4", { place = "s", color = "grey" })
-- the new polygon
g:polygon(n, { })
for i = 0, 7 do
  if i ~= 4 then g:label(P[i + 1], Plabels(i), { place = place[i + 1] }) end
end
-- the curve thinner than in 3.1, and the replacing polyline
-- P_3 Q_4 Q_5 P_5 in blue over it: the new leg Q_4 Q_5 touches the curve
-- at C(0.6) and would lie under a thick stroke
g:curve(n, { width = 1.1 })
g:polyline({ P[4], Q[5], Q[6], P[6] }, { color = "blue", width = 1.2 })
g:knots(n)
-- the new points Q_4, Q_5 (new control points 4 and 5 of n)
g:points({ n:eval(t) }, { marker = "dot", color = "darkgreen",
                           marker_color = "darkgreen", marker_size = 4 })
mark_t(g, n)
g:points({ Q[5], Q[6] }, { marker = "dot", color = "blue", marker_color = "blue",
                            fill = "blue", marker_size = 5 })
g:label(Q[5], "Q_4", { place = "se", color = "blue" })
g:label(Q[6], "Q_5", { place = "sw", color = "blue" })
