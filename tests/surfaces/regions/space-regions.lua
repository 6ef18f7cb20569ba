-- Filled regions in space among surfaces (tests/surfaces/
-- test_surface_regions.c checks the display list against the ray caster
-- at points sampled densely in each region, and the PNG of the second
-- figure): a filled quad that pierces a bent patch, a hull partly behind
-- it, a fill drawn whole; then a fill between two shaded surfaces; a
-- hull and a quad not in one plane through the patch in a perspective
-- view; a fill far larger than the figure's window.

local P = {
  { {-1, -1, 0},   {-1, 0, 0.8}, {-1, 1, 0} },
  { {0, -1, 0.4},  {0, 0, 1.2},  {0, 1, 0.4} },
  { {1, -1, 0},    {1, 0, 0.8},  {1, 1, 0} },
}
local s = bezier_surface{ points = P }

local f = figure{
  name = "space-regions",
  width = "8cm", height = "6cm",
  view = { -60, 30 },
}
f:surface(s, { isolines = { 4, 4 }, hidden = "dashed" })
-- a plane quad through the patch: its part behind the patch faded
f:fill({ {-1.3, -0.3, 0.3}, {1.3, -0.3, 0.3}, {1.3, 0.4, 0.9},
         {-1.3, 0.4, 0.9} }, { fill = "red", opacity = 0.6,
                               color = "black", width = 0.5 })
-- a hull of five points below the patch's corner: its hidden part left out
f:hull({ {0.3, 0.3, -0.6}, {1.2, 0.4, -0.5}, {0.4, 1.3, -0.4},
         {0.8, 0.8, 0.5}, {0.9, 0.2, 0.1} },
       { fill = "blue", opacity = 0.5, hidden = "remove" })
-- a small fill under the patch drawn whole
f:fill({ {-0.8, -0.8, -0.3}, {-0.3, -0.8, -0.3}, {-0.5, -0.4, -0.3} },
       { fill = "green", hidden = "show" })

-- between two shaded patches: the lower one seen through nothing, the
-- upper one hiding the fill's middle (left out), the fill opaque
local Q = {
  { {-1, -1, -0.6}, {-1, 1, -0.6} },
  { {1, -1, -0.6},  {1, 1, -0.6} },
}
local g = figure{
  name = "space-regions-shaded",
  width = "8cm", height = "6cm",
  view = { -60, 30 },
}
g:surface(s, { boundary = false, fill = "#c8c8c8", shade = "flat" })
g:surface(bezier_surface{ points = Q }, { boundary = false,
                                          fill = "#a0c0e8",
                                          shade = "flat" })
g:fill({ {-1.2, -0.2, -0.2}, {1.2, -0.2, -0.2}, {1.2, 0.3, 0.2},
         {-1.2, 0.3, 0.2} }, { fill = "#ff0000", opacity = 1,
                               hidden = "remove" })

-- a perspective view: a hull through the patch, its hidden part faded
local h = figure{
  name = "space-regions-perspective",
  width = "8cm", height = "6cm",
  view = { -40, 25 }, projection = "perspective", distance = 5,
}
h:surface(s, { isolines = { 3, 3 } })
h:hull({ {-0.6, -0.9, -0.2}, {0.7, -0.6, 0.1}, {0.2, 0.8, 0.0},
         {-0.1, -0.1, 1.5}, {0.3, 0.2, -0.5} },
       { fill = "purple", opacity = 0.5 })
-- a quad not in one plane (two flat triangles) through the patch
h:fill({ {-1.2, 0.2, 0.9}, {-0.2, 1.2, -0.3}, {1.1, 0.9, 0.8},
         {0.6, -0.4, 0.1} }, { fill = "green", opacity = 0.5 })

-- an explicit window and a fill thousands of times larger, behind and
-- through the patch: cut to the tolerance where it shows
local w = figure{
  name = "space-regions-window",
  width = "8cm", height = "6cm",
  view = { -60, 30 },
}
w:window(-2, 2, -1.5, 1.5)
w:surface(s, { isolines = { 4, 4 } })
w:fill({ {-3000, -3000, 0.3}, {3000, -3000, 0.3}, {0, 3000, 0.3} },
       { fill = "red", opacity = 0.5 })
