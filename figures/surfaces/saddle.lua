-- surfaces/saddle: a biquadratic saddle seen from low down, so that its
-- silhouette (the contour where the surface turns away from the eye)
-- hides part of the surface behind it; hidden lines dashed.

local P = {
  { {-1, -1, 1.2}, {-1, 0, -0.4}, {-1, 1, 1.2} },
  { {0, -1, -1.0}, {0, 0, 0.0},   {0, 1, -1.0} },
  { {1, -1, 1.2},  {1, 0, -0.4},  {1, 1, 1.2} },
}
local s = bezier_surface{ points = P }

local f = figure{
  name = "surfaces-saddle",
  caption = "A saddle whose silhouette hides part of itself",
  width = "8cm", height = "6cm",
  view = { -30, 8 },
}
f:surface(s, { isolines = { 7, 7 }, hidden = "dashed" })
