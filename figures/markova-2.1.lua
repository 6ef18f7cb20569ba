-- markova-2.1 ... markova-2.3 (seed 002, "B-spline křivky", §2.2
-- "Základní typy B-spline křivek", Obr. 2.1 "Otevřená", Obr. 2.2
-- "Plovoucí", Obr. 2.3 "Uzavřená").
-- The three basic kinds of B-spline curve on the same eight control points
-- (the sample curve's P_0 ... P_7, §2.10), each with its knot points
-- C(u_i) marked:
--   2.1 open ("otevřená"): p = 4, uniform knots, U = {0, 1/12, ..., 1}
--       (13 knots), drawn on its domain [u_4, u_8] = [4/12, 8/12]; the
--       curve "nedosáhne k prvnímu a poslednímu úseku řídicího polygonu":
--       it starts at C(u_4) = (4.30, 2.5) and ends at C(u_8), both marked
--       and clearly off the end legs (with p = 3 it would start 0.08 from
--       P_1, under its marker, and seem to reach it);
--   2.2 clamped ("plovoucí"): U = {0, 0, 0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1,
--       1, 1}, first and last knot of multiplicity p + 1: the curve starts
--       at P_0 tangent to P_0P_1 and ends at P_7 tangent to P_6P_7;
--   2.3 closed ("uzavřená"): the first p = 3 points wrapped
--       (P_0 ... P_7, P_0, P_1, P_2: eleven points), uniform knots
--       U = {-3/8, -2/8, ..., 11/8} (15 knots) drawn on [u_3, u_11] =
--       [0, 1]; the polygon is drawn closed.
-- Degree: the seed gives none for these figures; p = 3 for 2.2 and 2.3,
-- p = 4 for the open curve (see above; with p = 2 it would start at the
-- midpoint of P_0P_1, on the first leg); the three figures share window
-- and size.

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local place = { "s", "se", "e", "n", "s", "n", "w", "sw" }
local p = 3

local function page(name, caption)
  return figure{ name = name, caption = caption, width = "6.5cm",
                 height = "5.4cm", window = { 0.45, 5.55, 0.55, 4.45 } }
end

local function polygon(f, closed)
  f:polyline(P, { closed = closed, color = "#8c8c8c", width = 0.6 })
  f:points(P, { color = "#3c3c3c", marker_color = "#3c3c3c" })
  for i, q in ipairs(P) do
    f:label(q, string.format("P_%d", i - 1), { place = place[i] })
  end
end

local kinds = {
  { "markova-2.1", "uniform", false,
    "Open B-spline (p = 4, uniform knots i/12): it starts at C(u_4) and "
    .. "ends at C(u_8), touching neither end leg of the polygon "
    .. "(Obr. 2.1: Otevřená)", 4 },
  { "markova-2.2", "clamped", false,
    "Clamped B-spline (p = 3, end knots of multiplicity 4): it starts at "
    .. "P_0 and ends at P_7, tangent to the end legs (Obr. 2.2: Plovoucí)" },
  { "markova-2.3", "closed", true,
    "Closed B-spline (p = 3, P_0, P_1, P_2 repeated after P_7, uniform "
    .. "knots) (Obr. 2.3: Uzavřená)" },
}
for _, k in ipairs(kinds) do
  local s = bspline{ degree = k[5] or p, points = P, kind = k[2] }
  if k[2] == "closed" then
    -- the closed curve really closes: C(u_3) = C(u_11)
    local a, b = s:domain()
    local ca, cb = s:eval(a), s:eval(b)
    assert(math.abs(ca[1] - cb[1]) + math.abs(ca[2] - cb[2]) < 1e-12)
  end
  local f = page(k[1], k[4])
  polygon(f, k[3])
  f:curve(s)
  f:knots(s)
  if k[2] == "uniform" then
    -- where the open curve starts and ends: off the end legs
    local a, b = s:domain()
    f:points({ s:eval(a), s:eval(b) }, { marker = "dot", color = "darkred",
                                         marker_color = "darkred" })
    f:label(s:eval(a), "C(u_4)", { color = "darkred", font_size = 8.5 })
    f:label(s:eval(b), "C(u_8)", { color = "darkred", font_size = 8.5 })
  end
end
