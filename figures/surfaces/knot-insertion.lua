-- surfaces/knot-insertion: knot insertion in u on a biquadratic B-spline
-- surface: u = 1.5 inserted once; the old net (grey) and the new net
-- (orange), whose new row replaces two rows of the old one; the surface is
-- the same.

local P = {}
for i = 0, 3 do
  local row = {}
  for j = 0, 3 do
    row[#row + 1] = { i, j, ((i + j) % 2 == 0) and 1.2 or 0.2 }
  end
  P[#P + 1] = row
end
local s = bspline_surface{ degree = { 2, 2 },
                           knots = { {0, 0, 0, 1, 2, 2, 2},
                                     {0, 0, 0, 1, 2, 2, 2} },
                           points = P }
local t = s:insert_knot("u", 1.5)

local f = figure{
  name = "surfaces-knot-insertion",
  caption = "Knot insertion in u: u = 1.5 inserted once; old net (grey), "
    .. "new net (orange), knot lines of the new surface",
  width = "9cm", height = "7cm",
  view = { -60, 30 },
}
f:surface(s, { hidden = "remove", net = { color = "#8c8c8c", width = 0.5 } })
f:surface(t, { boundary = false, silhouette = false, occludes = false,
               knot_lines = true, hidden = "remove",
               net = { color = "#e07b00", width = 0.7 } })
