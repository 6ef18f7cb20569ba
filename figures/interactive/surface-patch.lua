-- interactive/surface-patch: a bicubic Bézier patch and the point S(u, v)
-- on its two iso-curves through it, u and v on sliders; a label the
-- reader drags (a point of the page: it stays where it was put while the
-- figure turns) points at S(u, v).  In `curvefig live` and the
-- page of -f html, dragging the figure's background turns it (azimuth
-- and elevation); the printed figure is the view below.

local L = points{ name = "L", default = { { -1.7, 1.2 } } }
local u = slider{ name = "u", min = 0, max = 1, default = 0.4, step = 0.01 }
local v = slider{ name = "v", min = 0, max = 1, default = 0.6, step = 0.01 }

-- the patch of figures/surfaces/bezier-patch.lua, moved so that the
-- middle of its box, (1.5, 1.5, 0.9), is the origin
local P = {
  { {0, 0, 0},   {0, 1, 0.6}, {0, 2, 0.6}, {0, 3, 0} },
  { {1, 0, 0.7}, {1, 1, 1.8}, {1, 2, 1.6}, {1, 3, 0.4} },
  { {2, 0, 0.6}, {2, 1, 1.5}, {2, 2, 2.0}, {2, 3, 0.7} },
  { {3, 0, 0},   {3, 1, 0.5}, {3, 2, 0.8}, {3, 3, 0.2} },
}
for _, row in ipairs(P) do
  for _, p in ipairs(row) do
    p[1], p[2], p[3] = p[1] - 1.5, p[2] - 1.5, p[3] - 0.9
  end
end
local s = bezier_surface{ points = P }
local S = s:eval(u, v)

-- a window about the origin that holds the patch in every view (the
-- box's half diagonal is 2.3)
local f = figure{
  name = "surface-patch",
  caption = "A bicubic Bézier patch and S(u, v) on its iso-curves; "
    .. "drag the background to turn it",
  width = "8cm", height = "8cm",
  window = { -2.3, 2.3, -2.3, 2.3 },
  view = { -55, 28 },
}
-- (no control net: its 24 edges, each split where the patch hides it,
-- would double the time of a run, which a turn repeats at every step)
f:surface(s, { isolines = { 3, 3 }, hidden = "dashed" })
f:surface(s, { boundary = false, silhouette = false, occludes = false,
               hidden = "dashed", isolines = { u = { u }, v = { v } },
               iso_style = { color = "#c0392b", width = 1 } })
f:points({ S }, { color = "#c0392b", marker_size = 4 })
-- the arrow stops short of S(u, v), which stays visible
local Q = f:project({ S })[1]
local R = { L[1][1] + 0.9 * (Q[1] - L[1][1]), L[1][2] + 0.9 * (Q[2] - L[1][2]) }
f:arrow_to(L[1], R, { color = "#555555", width = 0.5 })
f:label(L[1], "S(u, v)", { place = "n" })
