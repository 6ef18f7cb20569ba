-- surfaces/bezier-patch: a bicubic Bézier patch with its control net.
-- The 4 x 4 net P_ij (thin grey, dots), the patch's boundary and
-- silhouette (thick), iso-lines u, v = 1/4, 1/2, 3/4 (thin); what the
-- patch hides is dashed.

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
