-- surfaces/bspline: a bicubic B-spline surface on 5 x 6 control points
-- with clamped uniform knots; the knot lines (the iso-lines at the
-- interior knots, where the Bézier patches meet) are drawn thin, the
-- boundary and silhouette thick, the net grey.  Hidden lines dashed.

local P = {}
for i = 0, 4 do
  local row = {}
  for j = 0, 5 do
    local z = 0.8 * math.sin(i * 1.1) * math.cos(j * 0.9) + 0.15 * i
    row[#row + 1] = { i, j, z }
  end
  P[#P + 1] = row
end
local s = bspline_surface{ degree = { 3, 3 },
                           knots = { {0, 0, 0, 0, 1, 2, 2, 2, 2},
                                     {0, 0, 0, 0, 1, 2, 3, 3, 3, 3} },
                           points = P }

local f = figure{
  name = "surfaces-bspline",
  caption = "A bicubic B-spline surface with its knot lines and control net",
  width = "9cm", height = "7cm",
  view = { -60, 35 },
}
f:surface(s, { knot_lines = true, hidden = "dashed",
               net = { color = "grey", width = 0.4 } })
