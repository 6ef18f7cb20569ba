-- markova-2.17 (seed 002, "B-spline křivky", §2.10 "Příklad na závěr",
-- Obr. 2.17 "Vzorová křivka").
-- The thesis' sample curve, used in most examples of chapters 2 and 3:
-- degree p = 2, P_0 ... P_7 = (3,1) (3.75,2) (5,3) (4,4) (3,3) (2,4) (1,3)
-- (2.25,2), U = {0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1} (seed
-- data).  A clamped curve: it starts at P_0 and ends at P_7; its knot
-- points C(u_3) ... C(u_7) (and the end points) are marked.  Same window
-- and size as markova-2.1 ... 2.16.

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local s = bspline{ degree = 2, knots = U, points = P }
local a, b = s:eval(0), s:eval(1)
assert(a[1] == 3 and a[2] == 1 and b[1] == 2.25 and b[2] == 2)

local f = figure{
  name = "markova-2.17",
  caption = "The sample curve: p = 2, P_0 ... P_7, U = {0, 0, 0, 0.17, 0.33, "
    .. "0.5, 0.67, 0.83, 1, 1, 1}, knot points marked (Obr. 2.17: Vzorová "
    .. "křivka)",
  width = "6.5cm", height = "5.4cm", window = { 0.45, 5.55, 0.55, 4.45 },
}
f:polygon(s)
f:curve(s)
f:knots(s)
f:points(s, { color = "#3c3c3c", marker_color = "#3c3c3c" })
local place = { "s", "se", "e", "n", "s", "n", "w", "sw" }
for i, q in ipairs(P) do
  f:label(q, string.format("P_%d", i - 1), { place = place[i] })
end
