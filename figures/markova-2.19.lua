-- markova-2.19 (seed 002, "B-spline křivky", §2.10 "Příklad na závěr",
-- Obr. 2.19 "Výsledná křivka").
-- The heart of markova-2.18 "rounded" ("Na závěr ještě křivku
-- \"zakulatíme\" posunutím [3, 1] do [3, 1.5] a [3, 3] do [3, 3.5]"):
-- both copies of (3,1) (P_7 = P_8) moved to (3, 1.5) and both copies of
-- (3,3) (P_2 = P_3) moved to (3, 3.5); p = 2 and U = {0, 0.07, ..., 0.93,
-- 1} as in 2.18 (seed data), drawn on [u_2, u_12] = [0.14, 0.86].
-- The curve still passes through the doubled points (asserted, 1e-12),
-- but the flatter polygon angles there make the heart rounder.  Same
-- window and size as markova-2.18.

local P = { {5,3}, {4,4}, {3,3}, {3,3}, {2,4}, {1,3}, {2.25,2}, {3,1},
            {3,1}, {3.75,2}, {5,3}, {4,4} }
local U = { 0, 0.07, 0.14, 0.21, 0.28, 0.35, 0.42, 0.5, 0.58, 0.65, 0.72,
            0.79, 0.86, 0.93, 1 }
local R = {}
for i, q in ipairs(P) do
  R[i] = { q[1], q[2] }
  if q[1] == 3 and q[2] == 1 then R[i][2] = 1.5 end
  if q[1] == 3 and q[2] == 3 then R[i][2] = 3.5 end
end
local s = bspline{ degree = 2, knots = U, points = R }
local a, b = s:domain()
local top, bottom = s:eval(U[5]), s:eval(U[10])           -- C(u_4), C(u_9)
assert(math.abs(top[1] - 3) + math.abs(top[2] - 3.5) < 1e-12)
assert(math.abs(bottom[1] - 3) + math.abs(bottom[2] - 1.5) < 1e-12)

local f = figure{
  name = "markova-2.19",
  caption = "The heart rounded: (3,1) moved to (3,1.5) and (3,3) to (3,3.5) "
    .. "(both copies); it still passes through them (Obr. 2.19: Výsledná "
    .. "křivka)",
  width = "7.5cm", height = "5cm", window = { 0.3, 6.2, 0.55, 4.45 },
}
f:polyline(R, { color = "#8c8c8c", width = 0.6 })
f:curve(s, { range = { a, b } })
f:knots(s)
f:points(R, { color = "#3c3c3c", marker_color = "#3c3c3c" })
local labels = {
  { R[1], "P_0 = P_{10}", "e" }, { R[2], "P_1 = P_{11}", "ne" },
  { R[3], "P_2 = P_3", "s" }, { R[5], "P_4", "n" }, { R[6], "P_5", "w" },
  { R[7], "P_6", "w" }, { R[8], "P_7 = P_8", "s" }, { R[10], "P_9", "se" },
}
for _, l in ipairs(labels) do f:label(l[1], l[2], { place = l[3] }) end
