-- lec05-decasteljau (seed 004, image/4.png): the de Casteljau
-- construction of a cubic in R^3, projected to the page (view from
-- azimuth 30, elevation 20 degrees).  Data chosen: a space cubic whose
-- control points do not lie in a plane, t = 1/2.

local c = bezier{ {0, 0, 0}, {1, 3, 1}, {4, 3, 3}, {5, 0, 1} }
local f = figure{
  name = "lec05-decasteljau",
  caption = "de Casteljau's construction of a space cubic at t = 1/2 (points in R^3, projected)",
  width = "8cm", height = "6cm", view = { 30, 20 },
}
f:curve(c)
f:decasteljau(c, 0.5, { labels = "P_{%d,%d}",
                        point = { marker = "star", marker_size = 8 } })
