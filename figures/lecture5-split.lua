-- lecture5-split (seed 001, lecture 5, "Деление кривой Безье на две
-- кривые Безье того же порядка в отношении t* : (1 − t*)").
-- The construction of the lecture: the polygon of level 0 (the control
-- polygon p_0 ... p_n, p_i^{(0)} = p_i) and the polygons of levels 1, 2, ..., n whose
-- vertices divide the sides of the previous level in the ratio
-- t* : (1 − t*), "p_i^{(k)} = (1 − t*)p_i^{(k−1)} + t* p_{i+1}^{(k−1)}";
-- the first vertices are the control points of the first arc,
-- p_i^a = p_0^{(i)}, and the last vertices those of the second arc,
-- p_i^b = p_i^{(n−i)} ("надо брать последовательность последних, а не
-- первых вершин многоугольников k-го уровня").  Level 0 grey, level 1
-- blue, level 2 orange, level 3 = the point r(t*); the two arcs (both
-- cubic Bézier curves again) in two colours, their polygons p^a, p^b
-- (which run along the net) as broad light bands in the arcs' colours.
-- Data chosen (the seed gives none): n = 3, p_0 ... p_3 = (0,0) (1.2,3.4)
-- (4.6,3.8) (6,0.6), t* = 0.6.

local c = bezier{ {0, 0}, {1.2, 3.4}, {4.6, 3.8}, {6, 0.6} }
local ts = 0.6
local L = c:decasteljau(ts)   -- L[k + 1][i + 1] = p_i^{(k)}
local n = c:degree()
local ra, rb = c:split(ts)
local ca, cb = "#1b7a3a", "#8e2c8e"

local f = figure{
  name = "lecture5-split",
  caption = "Dividing a cubic Bézier curve at t* = 0.6 into two cubic Bézier "
    .. "curves: the polygons of levels 0 ... 3 (vertices dividing the sides in "
    .. "the ratio t* : (1 − t*)); p_i^a = p_0^{(i)}, p_i^b = p_i^{(n−i)}",
  width = "14cm", height = "8.5cm",
}
f:curve(ra, { color = ca, width = 2.2 })
f:curve(rb, { color = cb, width = 2.2 })
-- the arcs' polygons p^a and p^b (they run along the net): broad light bands
f:polyline(ra:points(), { color = ca, width = 7, opacity = 0.25 })
f:polyline(rb:points(), { color = cb, width = 7, opacity = 0.25 })
f:decasteljau(c, ts, { colors = { "grey", "blue", "orange", "black" },
                       point = { marker = "dot", marker_size = 6 } })

local text = {
  [0] = { "p_0 = p_0^a", "p_1", "p_2", "p_3 = p_3^b" },
  [1] = { "p_0^{(1)} = p_1^a", "p_1^{(1)}", "p_2^{(1)} = p_2^b" },
  [2] = { "p_0^{(2)} = p_2^a", "p_1^{(2)} = p_1^b" },
  [3] = { "r(0.6) = p_0^{(3)} = p_3^a = p_0^b" },
}
local place = {
  [0] = { "e", "nw", "ne", "w" },
  [1] = { "w", "n", "e" },
  [2] = { "nw" },
}
for k = 0, n - 1 do
  for i = 0, n - k - (k == 2 and 1 or 0) do
    f:label(L[k + 1][i + 1], text[k][i + 1], { place = place[k][i + 1] })
  end
end
-- p_1^{(2)} and r(t*): their long names do not fit at their crowded points
-- (legs, arcs and bands all round); each stands in the nearest free room
-- with a leader (pin) to its point
local function pinned(p, d, from, name)
  f:arrow_to({ p[1] + from[1], p[2] + from[2] }, p,
             { color = "grey", width = 0.5, arrow_size = 4 })
  f:label({ p[1] + d[1], p[2] + d[2] }, name, { place = "center" })
end
pinned(L[3][2], { 0.78, 0.5 }, { 0.5, 0.3 }, text[2][2])
pinned(L[4][1], { 0, -0.55 }, { 0, -0.4 }, text[3][1])
f:label(ra:eval(0.35), "r^a", { place = "se", color = ca })
f:label(rb:eval(0.6), "r^b", { place = "sw", color = cb })
