-- surfaces/coons: a bilinearly blended Coons patch from four boundary
-- curves meeting at the corners, two cubic Bézier curves (c0, c1) and two
-- clamped cubic B-splines of five points (d0, d1), the curves drawn in
-- colour over the patch's iso-lines.

local c0 = bezier{ {0, 0, 0}, {1, -0.3, 0.8}, {2, 0.3, 0.8}, {3, 0, 0} }
local c1 = bezier{ {0, 3, 0.3}, {1, 3.3, 1.2}, {2, 2.7, 1.0}, {3, 3, 0.2} }
local d0 = bspline{ degree = 3, points = { {0, 0, 0}, {-0.15, 0.5, 0.5},
  {0, 1.5, 1.0}, {0.15, 2.5, 0.7}, {0, 3, 0.3} } }
local d1 = bspline{ degree = 3, points = { {3, 0, 0}, {3.15, 0.5, 0.35},
  {3, 1.5, 0.85}, {2.85, 2.5, 0.55}, {3, 3, 0.2} } }
local s = coons_patch{ c0, c1, d0, d1 }

local f = figure{
  name = "surfaces-coons",
  caption = "A Coons patch and its four boundary curves",
  width = "9cm", height = "7cm",
  view = { -60, 30 },
}
f:surface(s, { boundary = false, isolines = { 5, 5 }, hidden = "dashed" })
local colors = { "#1f5fbf", "#1f5fbf", "#e07b00", "#e07b00" }
for k, c in ipairs({ c0, c1, d0, d1 }) do
  f:curve(c, { color = colors[k], width = 1.4 })
end
f:label(c0:eval(0.5), "c_0", { place = "s" })
f:label(c1:eval(0.5), "c_1", { place = "n" })
f:label(d0:eval(0.5), "d_0", { place = "nw" })
f:label(d1:eval(0.5), "d_1", { place = "e" })
