-- surfaces/bspline: a bicubic B-spline surface on 7 x 6 control points
-- with clamped non-uniform knots, written under it; the knot lines (the
-- iso-lines at the interior knots, where the Bézier patches meet) are
-- drawn thin, the boundary and silhouette thick, the net grey.  Hidden
-- lines dashed.

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

local f = figure{
  name = "surfaces-bspline",
  caption = "A bicubic B-spline surface on 7 x 6 control points with "
    .. "clamped non-uniform knots, its knot lines and control net",
  width = "9cm", height = "7cm",
  view = { -60, 35 },
}
f:surface(s, { knot_lines = true, hidden = "dashed",
               net = { color = "grey", width = 0.4 } })
-- the knot vectors, under the surface
local function vec(name, k)
  local t = {}
  for i, x in ipairs(k) do t[i] = string.format("%g", x) end
  return name .. " = (" .. table.concat(t, ", ") .. ")"
end
f:label({ 2.25, 2.5, -3.3 }, vec("U", U), { place = "s" })
f:label({ 2.25, 2.5, -3.9 }, vec("V", V), { place = "s" })
