-- surfaces/bezier-patch: a bicubic Bézier patch, two figures.
-- surfaces-bezier-patch: the 4 x 4 net P_ij (thin grey, dots), the
-- patch's boundary and silhouette (thick), iso-lines u, v = 1/4, 1/2, 3/4
-- (thin); what the patch hides is dashed.
-- surfaces-decasteljau: de Casteljau's algorithm on the patch at (u, v) =
-- (0.4, 0.6): the nets of levels 1, 2, 3 of the scheme in u (one colour
-- each), the scheme in v on the four points reached (the control polygon
-- of the iso-curve u = 0.4, and its levels), and S(u, v) (star).

local P = {
  { {0, 0, 0},   {0, 1, 0.6}, {0, 2, 0.6}, {0, 3, 0} },
  { {1, 0, 0.7}, {1, 1, 1.8}, {1, 2, 1.6}, {1, 3, 0.4} },
  { {2, 0, 0.6}, {2, 1, 1.5}, {2, 2, 2.0}, {2, 3, 0.7} },
  { {3, 0, 0},   {3, 1, 0.5}, {3, 2, 0.8}, {3, 3, 0.2} },
}
local s = bezier_surface{ points = P }

local f = figure{
  name = "surfaces-bezier-patch",
  caption = "A bicubic Bézier patch with its control net; hidden lines dashed",
  width = "9cm", height = "7cm",
  view = { -55, 28 },
}
f:surface(s, { isolines = { 3, 3 }, hidden = "dashed",
               net = { color = "grey" }, labels = "P_{%d%d}",
               label_style = { font_size = 7 } })

local g = figure{
  name = "surfaces-decasteljau",
  caption = "de Casteljau's algorithm on a bicubic patch at (u, v) = "
    .. "(0.4, 0.6): the nets of the levels in u, then the scheme in v",
  width = "9cm", height = "7cm",
  view = { -55, 28 },
}
g:surface(s, { hidden = "remove", silhouette = false, width = 0.8,
               color = "#9aa5b5", net = { color = "grey" },
               isolines = { u = { 0.4 }, v = { 0.6 } },
               iso_style = { color = "#9aa5b5", dash = "dashed" } })
g:decasteljau_surface(s, 0.4, 0.6, { width = 0.6 })
