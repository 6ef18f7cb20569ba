-- markova-2.12, markova-2.13 (seed 002, "B-spline křivky", §2.7
-- "Důsledky silné vlastnosti konvexního obalu", goal "Změna části křivky
-- na přímku", Obr. 2.12 "Původní řídicí body", Obr. 2.13 "P_3, P_4 a P_5
-- kolineární").
-- "Pokud všech p + 1 řídicích bodů leží na přímce, konvexní obal se
-- zredukuje na část přímky a to samé se stane s částí křivky."  The
-- sample curve (p = 2, U = {0,0,0,0.17,0.33,0.5,0.67,0.83,1,1,1}); the
-- points P_3, P_4, P_5 act on the span [u_5, u_6) = [0.5, 0.67).
--   2.12: the original points: the hull of P_3, P_4, P_5 (a triangle)
--         shaded, the curve piece on [u_5, u_6) orange.
--   2.13: P_3, P_4, P_5 made collinear -- our choice, the seed gives no
--         data: P_4 = (3, 3) is moved onto the segment P_3P_5, to its
--         midpoint (3, 4).  The hull collapses to the segment P_3P_5 and
--         the piece on [u_5, u_6) is the straight segment y = 4 from
--         C(u_5) = (3.5, 4) to C(u_6) = (2.5, 4) (orange); the script
--         asserts y = 4 on that span (|y - 4| < 1e-12).
-- Knot points marked.  Same window and size as markova-2.1 ... 2.10.

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local s = bspline{ degree = 2, knots = U, points = P }
local t = s:move_point(4, { 0, 1 })          -- P_4 -> (3, 4)
local first, lo, hi = s:active_points(0.6)
assert(first == 3 and lo == U[6] and hi == U[7])
for j = 0, 100 do
  local q = t:eval(lo + (hi - lo) * j / 100)
  assert(math.abs(q[2] - 4) < 1e-12, "the piece is straight")
end

local figs = {
  { "markova-2.12", s, { "s", "se", "e", "n", "s", "n", "w", "sw" },
    "The sample curve: P_3, P_4, P_5 act on [u_5, u_6) = [0.5, 0.67); "
    .. "their hull shaded, that piece orange (Obr. 2.12: Původní řídicí body)" },
  { "markova-2.13", t, { "s", "se", "e", "n", "n", "n", "w", "sw" },
    "P_4 moved onto the segment P_3P_5: the hull of P_3, P_4, P_5 is a "
    .. "segment and the piece on [u_5, u_6) is straight (Obr. 2.13: P_3, P_4 "
    .. "a P_5 kolineární)" },
}
for _, g in ipairs(figs) do
  local c = g[2]
  local Q = c:points()
  local f = figure{ name = g[1], caption = g[4], width = "6.5cm",
                    height = "5.4cm", window = { 0.45, 5.55, 0.55, 4.45 } }
  -- the collapsed hull (a segment) is drawn with a wide outline to stay visible
  f:hull({ Q[4], Q[5], Q[6] }, { width = c == t and 2.5 or 0.5 })
  f:polygon(c)
  f:curve(c)
  f:curve(c, { range = { lo, hi }, color = "#e8821e", width = 3 })
  f:knots(c)
  f:points(c, { color = "#3c3c3c", marker_color = "#3c3c3c" })
  for i, q in ipairs(Q) do
    f:label(q, string.format("P_%d", i - 1), { place = g[3][i] })
  end
  -- the ends of the piece, named as in the text
  f:label(c:eval(lo), "C(u_5)", { color = "#b35f00", font_size = 8 })
  f:label(c:eval(hi), "C(u_6)", { color = "#b35f00", font_size = 8 })
end
