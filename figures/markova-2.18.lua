-- markova-2.18 (seed 002, "B-spline křivky", §2.10 "Příklad na závěr",
-- Obr. 2.18 "Uzavřená křivka").
-- The closed heart built from the sample curve: degree p = 2, twelve
-- points P_0 ... P_11 = (5,3) (4,4) (3,3) (3,3) (2,4) (1,3) (2.25,2) (3,1)
-- (3,1) (3.75,2) (5,3) (4,4) -- (3,3) and (3,1) taken twice (p times) so
-- that the curve passes through them, the first two repeated at the end
-- so that it closes -- and U = {0, 0.07, 0.14, 0.21, 0.28, 0.35, 0.42,
-- 0.5, 0.58, 0.65, 0.72, 0.79, 0.86, 0.93, 1} (seed data; 15 knots,
-- m = 14 = n + p + 1 with n = 11), drawn on [u_p, u_{m-p}] = [u_2, u_12]
-- = [0.14, 0.86] (the seed's "n = 12" counts the points).  Coincident
-- points share one marker and one label ("P_2 = P_3").  Knot points
-- marked.  The script asserts that the curve closes (C(u_2) = C(u_12),
-- and C'(u_2) = C'(u_12)) and passes through (3,3) = C(u_4) and
-- (3,1) = C(u_9), at 1e-12.
-- Not in the seed: window and size (shared with markova-2.19, wider than
-- the sample-curve figures so the double labels fit).

local P = { {5,3}, {4,4}, {3,3}, {3,3}, {2,4}, {1,3}, {2.25,2}, {3,1},
            {3,1}, {3.75,2}, {5,3}, {4,4} }
local U = { 0, 0.07, 0.14, 0.21, 0.28, 0.35, 0.42, 0.5, 0.58, 0.65, 0.72,
            0.79, 0.86, 0.93, 1 }
local s = bspline{ degree = 2, knots = U, points = P }
local a, b = s:domain()
assert(a == U[3] and b == U[13])
local da, db = s:derivs(a, 1), s:derivs(b, 1)
for k = 1, 2 do
  assert(math.abs(da[1][k] - db[1][k]) < 1e-12)          -- closed
  assert(math.abs(da[2][k] - db[2][k]) < 1e-9)           -- C^1 closed
end
local top, bottom = s:eval(U[5]), s:eval(U[10])           -- C(u_4), C(u_9)
assert(math.abs(top[1] - 3) + math.abs(top[2] - 3) < 1e-12)
assert(math.abs(bottom[1] - 3) + math.abs(bottom[2] - 1) < 1e-12)

local f = figure{
  name = "markova-2.18",
  caption = "Closed heart: p = 2, twelve points with (3,3) and (3,1) doubled "
    .. "and the first two repeated, U = {0, 0.07, ..., 0.93, 1}, drawn on "
    .. "[u_2, u_12] (Obr. 2.18: Uzavřená křivka)",
  width = "7.5cm", height = "5cm", window = { 0.3, 6.2, 0.55, 4.45 },
}
f:polyline(P, { color = "#8c8c8c", width = 0.6 })
f:curve(s, { range = { a, b } })
f:knots(s)
f:points(P, { color = "#3c3c3c", marker_color = "#3c3c3c" })
local labels = {
  { P[1], "P_0 = P_{10}", "e" }, { P[2], "P_1 = P_{11}", "ne" },
  { P[3], "P_2 = P_3", "s" }, { P[5], "P_4", "n" }, { P[6], "P_5", "w" },
  { P[7], "P_6", "sw" }, { P[8], "P_7 = P_8", "s" }, { P[10], "P_9", "se" },
}
for _, l in ipairs(labels) do f:label(l[1], l[2], { place = l[3] }) end
