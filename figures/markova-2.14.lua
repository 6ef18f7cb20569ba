-- markova-2.14, markova-2.15 (seed 002, "B-spline křivky", §2.7, goal
-- "B-spline křivka prochází určitým řídicím bodem", Obr. 2.14 "Původní
-- řídicí body", Obr. 2.15 "$P_4 = P_5$").
-- "Je-li P_i = P_{i-1} = ... = P_{i-p+1} (p identických bodů), konvexní
-- obal se zredukuje na část přímky P_{i-p}P_i a tedy křivka musí
-- procházet P_i."  The sample curve (p = 2, U = {0,0,0,0.17,0.33,0.5,
-- 0.67,0.83,1,1,1}); P_4 and P_5 act together on [u_5, u_7) =
-- [0.5, 0.83).
--   2.14: the original points; the arc on [u_5, u_7) orange, the knot
--         point C(u_6) labelled.
--   2.15: P_4 = P_5 (p = 2 coincident points) -- our choice of where: P_5
--         is moved onto P_4 = (3, 3) (the point the heart of §2.10 doubles
--         for the same reason).  The hulls of P_3, P_4, P_5 and of P_4,
--         P_5, P_6 collapse to the segments P_3P_4 and P_4P_6 (drawn wide,
--         shaded), the pieces on [u_5, u_6) and [u_6, u_7) are straight
--         (orange), and the curve passes through P_4 = P_5 = C(u_6) with
--         a corner (C'(u_6) = 0).  The script asserts C(u_6) = (3, 3) and
--         that both pieces lie on their segments (1e-12).
-- Knot points marked.  Same window and size as markova-2.1 ... 2.13.

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local s = bspline{ degree = 2, knots = U, points = P }
local t = s:move_point(5, { P[5][1] - P[6][1], P[5][2] - P[6][2] })
local Q = t:points()
assert(Q[5][1] == Q[6][1] and Q[5][2] == Q[6][2])
local c6 = t:eval(U[7])
assert(math.abs(c6[1] - 3) + math.abs(c6[2] - 3) < 1e-12)
for j = 0, 100 do
  local a = t:eval(U[6] + (U[7] - U[6]) * j / 100)     -- on y = x
  local b = t:eval(U[7] + (U[8] - U[7]) * j / 100)     -- on y = 3
  assert(math.abs(a[1] - a[2]) < 1e-12 and math.abs(b[2] - 3) < 1e-12)
end

local figs = {
  { "markova-2.14", s, "The sample curve: P_4 and P_5 act together on "
    .. "[u_5, u_7) = [0.5, 0.83) (orange) (Obr. 2.14: Původní řídicí body)" },
  { "markova-2.15", t, "P_5 moved onto P_4 (p = 2 coincident points): the "
    .. "curve passes through P_4 = P_5 = C(u_6), straight on both sides "
    .. "(Obr. 2.15: P_4 = P_5)" },
}
for _, g in ipairs(figs) do
  local c = g[2]
  local R = c:points()
  local f = figure{ name = g[1], caption = g[3], width = "6.5cm",
                    height = "5.4cm", window = { 0.45, 5.55, 0.55, 4.45 } }
  if c == t then
    f:hull({ R[4], R[5] }, { width = 2.5 })
    f:hull({ R[5], R[7] }, { width = 2.5 })
  end
  f:polygon(c)
  f:curve(c)
  f:curve(c, { range = { U[6], U[8] }, color = "#e8821e", width = 3 })
  f:knots(c)
  f:points(c, { color = "#3c3c3c", marker_color = "#3c3c3c" })
  local place = { "s", "se", "e", "n", "s", "n", "w", "sw" }
  for i, q in ipairs(R) do
    if c ~= t or (i ~= 5 and i ~= 6) then
      f:label(q, string.format("P_%d", i - 1), { place = place[i] })
    end
  end
  if c == t then
    f:label(R[5], "P_4 = P_5", { place = "s" })
  else
    local k = c:eval(U[7])
    f:points(k, { marker = "dot", marker_size = 4.5, marker_color = "black" })
    f:label(k, "C(u_6)", { place = "ne" })
  end
end
