-- markova-2.16 (seed 002, "B-spline křivky", §2.8 "Změna uzlů",
-- Obrázek 2.16 "Křivky se liší pouze v hodnotách uzlů u_4 a u_6").
-- Two curves on the sample polygon (p = 2, P_0 ... P_7) that differ only
-- in the knots u_4 and u_6: the sample curve, U = {0,0,0,0.17,0.33,0.5,
-- 0.67,0.83,1,1,1} (dark, solid), and the same points with u_4 = 0.2 and
-- u_6 = 0.8 (orange, dashed) -- the changed values are our choice (the
-- seed gives none): u_4 and u_6 are moved away from u_5 = 0.5, almost to
-- their neighbours u_3 = 0.17 and u_7 = 0.83.  The shape changes in a way
-- that is hard to foresee ("změna pozice uzlu není ani předvídatelná, ani
-- vyhovující"): the curve is pulled towards P_2 and P_5.  The knot points
-- of both curves are marked in their colours; the legend (placed where
-- nothing is drawn, or beside the drawing) names the two knot vectors.
-- Same window and size as markova-2.1 ... 2.15.

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local V = { 0, 0, 0, 0.17, 0.2, 0.5, 0.8, 0.83, 1, 1, 1 }
for j = 1, #U do
  assert(U[j] == V[j] or j == 5 or j == 7)       -- only u_4 and u_6 differ
end
local s = bspline{ degree = 2, knots = U, points = P }
local t = bspline{ degree = 2, knots = V, points = P }
local orange = "#e8821e"

local f = figure{
  name = "markova-2.16",
  caption = "Two curves on the same points that differ only in the knots "
    .. "u_4 and u_6: the sample curve (u_4 = 0.33, u_6 = 0.67, solid) and "
    .. "u_4 = 0.2, u_6 = 0.8 (dashed) (Obrázek 2.16)",
  width = "6.5cm", height = "5.4cm", window = { 0.45, 5.55, 0.55, 4.45 },
}
local dark = "#14306e"
f:polygon(P)
f:curve(s, { legend = "u_4 = 0.33, u_6 = 0.67" })
f:curve(t, { color = orange, dash = "dashed",
             legend = "u_4 = 0.2, u_6 = 0.8" })
f:knots(s, { color = dark, marker_color = dark })
f:knots(t, { color = orange, marker_color = orange })
f:points(P, { color = "#3c3c3c", marker_color = "#3c3c3c" })
local place = { "s", "se", "e", "n", "s", "n", "w", "sw" }
for i, q in ipairs(P) do
  f:label(q, string.format("P_%d", i - 1), { place = place[i] })
end
