-- lec05-decasteljau (seed 004, "Lec05 Bezier曲线 B样条曲线", §De Casteljau
-- algorithm, image/4.png: "输入：点 b_0, b_1, ..., b_n ∈ R^3 ...
-- b_i^0(t) = b_i, b_i^r(t) = (1−t) b_i^{r−1}(t) + t b_{i+1}^{r−1}(t),
-- r = 1, ..., n, i = 0, ..., n − r").
-- The de Casteljau construction of a space cubic at t = 0.4, drawn in
-- oblique parallel projection (x to the right, z up, y receding at
-- about 35° with factor 0.6, as in textbook drawings of R^3): the control
-- points b_0 ... b_3 in R^3 with their polygon, the points b_i^1 (blue)
-- and b_i^2 (orange) of levels 1 and 2 with their polygons, the point
-- x(t) = b_0^3 (star) on the curve x(t).  To show that the points are
-- in space, the coordinate axes x, y, z are drawn at the origin and each
-- control point has a dotted drop line to its foot in the plane z = 0
-- (small grey marks), the feet joined by a thin dotted polygon.
-- Data chosen (the seed's image is missing): b_0 ... b_3 = (2,0,0)
-- (2.5,3,2.6) (5.7,3.4,3) (6.5,0.4,0.6), not in one plane; t = 0.4.

local c = bezier{ {2, 0, 0}, {2.5, 3, 2.6}, {5.7, 3.4, 3}, {6.5, 0.4, 0.6} }
local t = 0.4
local L = c:decasteljau(t)       -- L[r + 1][i + 1] = b_i^r
local n = c:degree()
local blue, orange = "#1f5fbf", "#e07b00"

local f = figure{
  name = "lec05-decasteljau",
  caption = "de Casteljau's algorithm for a cubic in R^3 at t = 0.4, in "
    .. "parallel projection: control points b_i, the points b_i^r of levels "
    .. "1, 2 and x(t) = b_0^3 on the curve; axes and drop lines to z = 0 for depth",
  width = "10cm", height = "7.5cm",
  projection = { { 1, 0.5, 0 }, { 0, 0.35, 1 } },
}
-- axes
local axes = { { {7.6, 0, 0}, "x" }, { {0, 3, 0}, "y" }, { {0, 0, 3.6}, "z" } }
for _, a in ipairs(axes) do
  f:arrow_to({ 0, 0, 0 }, a[1], { color = "grey", width = 0.6 })
end
f:label(axes[1][1], "x", { place = "s", color = "grey" })
f:label(axes[2][1], "y", { place = "e", color = "grey" })
f:label(axes[3][1], "z", { place = "w", color = "grey" })
-- drop lines and feet
local feet = {}
for i, p in ipairs(c:points()) do
  feet[i] = { p[1], p[2], 0 }
  if p[3] > 0 then
    f:line(p, feet[i], { color = "grey", dash = "dotted", width = 0.6 })
  end
end
f:polyline(feet, { color = "lightgrey", dash = "dotted", width = 0.6 })
f:points(feet, { marker = "cross", marker_size = 4, color = "grey" })
-- the construction
f:curve(c)
f:decasteljau(c, t, { colors = { "grey", blue, orange, "black" },
                      point = { marker = "star", marker_size = 10, color = "black",
                                marker_color = "black" } })
local place = {
  [0] = { "s", "nw", "ne", "auto" },
  [1] = { "w", "n", "sw" },
  [2] = { "auto", "ne" },
  [3] = { "se" },
}
for r = 0, n do
  for i = 0, n - r do
    local text
    if r == 0 then text = string.format("b_%d", i)
    elseif r == n then text = "x(0.4) = b_0^3"
    else text = string.format("b_%d^%d", i, r) end
    -- b_2^1 sits in the narrow gap between the leg b_2 b_3 and the
    -- dotted line below b_2: south-west of its point, a little farther
    f:label(L[r + 1][i + 1], text, { place = place[r][i + 1],
                                     offset = (r == n and 2.5)
                                              or ((r == 1 and i == 2) and 6)
                                              or nil })
  end
end
