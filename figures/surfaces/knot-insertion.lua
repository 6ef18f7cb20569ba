-- surfaces/knot-insertion: knot insertion at u = 0.5 on the bicubic
-- B-spline surface of surfaces/bspline (7 x 6 points, clamped non-uniform
-- knots U and V): the old net grey, the new net orange -- one more row
-- of points, three rows of the old one replaced by four -- and the
-- surface, drawn once from each, the same.

local P = {}
for i = 0, 6 do
  local row = {}
  for j = 0, 5 do
    local z = 0.8 * math.sin(i * 0.8) * math.cos(j * 0.9) + 0.1 * i
    row[#row + 1] = { 0.75 * i, j, z }
  end
  P[#P + 1] = row
end
local U = { 0, 0, 0, 0, 1, 1.5, 3, 4, 4, 4, 4 }
local V = { 0, 0, 0, 0, 1, 2.5, 4, 4, 4, 4 }
local s = bspline_surface{ degree = { 3, 3 }, knots = { U, V }, points = P }
local t = s:insert_knot("u", 0.5)

local f = figure{
  name = "surfaces-knot-insertion",
  caption = "Knot insertion at u = 0.5 on the bicubic B-spline surface: "
    .. "old net (grey), new net (orange), the surface unchanged",
  width = "9cm", height = "7cm",
  view = { -60, 35 },
}
-- the surface with its iso-lines; the two nets over it, whole (a net
-- lies partly under its surface, and here it is what the figure shows)
f:surface(s, { isolines = { 8, 6 }, width = 0.5, hidden = "remove" })
f:surface(s, { boundary = false, silhouette = false, occludes = false,
               isolines = { 0, 0 }, hidden = "show",
               net = { color = "#8c8c8c", width = 0.6 } })
f:surface(t, { boundary = false, silhouette = false, occludes = false,
               isolines = { 0, 0 }, hidden = "show",
               net = { color = "#e07b00", width = 0.8 } })
