-- surfaces/saddle: the saddle z = x^2 - y^2 on [-1, 1]^2 (biquadratic:
-- the control values of x^2 on [-1, 1] are 1, -1, 1) seen from low down
-- across its rising edges, so that its silhouette (the contour where the
-- surface turns away from the eye) hides part of the surface behind it;
-- hidden lines dashed.

local P = {
  { {-1, -1, 0}, {-1, 0, 2},  {-1, 1, 0} },
  { {0, -1, -2}, {0, 0, 0},   {0, 1, -2} },
  { {1, -1, 0},  {1, 0, 2},   {1, 1, 0} },
}
local s = bezier_surface{ points = P }

local f = figure{
  name = "surfaces-saddle",
  caption = "A saddle whose silhouette hides part of itself",
  width = "8cm", height = "6cm",
  view = { 20, 12 },
}
f:surface(s, { isolines = { 7, 7 }, hidden = "dashed" })
