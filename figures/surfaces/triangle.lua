-- surfaces/triangle: a cubic triangular Bézier patch with its net b_ijk
-- (i + j + k = 3) and the de Casteljau scheme at (u, v, w) = (1/3, 1/3,
-- 1/3): the points of levels 1 and 2 in colours, T(u, v, w) marked.

local b = {
  {0, 0, 0},                                        -- b300
  {1, 0.5, 1.2}, {1, -0.5, 0.8},                    -- b210 b201
  {2, 1, 1.0}, {2, 0, 1.6}, {2, -1, 0.6},           -- b120 b111 b102
  {3, 1.5, 0}, {3, 0.5, 0.9}, {3, -0.5, 0.7}, {3, -1.5, 0},  -- b030 .. b003
}
local t = bezier_triangle{ degree = 3, points = b }

local f = figure{
  name = "surfaces-triangle",
  caption = "A cubic triangular Bézier patch with its net and the de "
    .. "Casteljau scheme at u = v = w = 1/3",
  width = "9cm", height = "7cm",
  view = { -100, 35 },
}
f:surface(t, { isolines = { 3, 3 }, hidden = "dashed",
               net = { color = "grey" }, labels = "b_{%d%d%d}",
               label_style = { font_size = 7 } })
f:triangle_scheme(t, 1/3, 1/3, { width = 0.6 })
