-- surfaces/revolution: a shaded surface of revolution (a vase) from a
-- cubic B-spline profile in the xz-plane turned about the z axis
-- (smooth shading, the inside paler), with the profile in colour and the
-- axis.

local profile = bspline{ degree = 3,
  points = { {1.0, 0, 0}, {1.6, 0, 0.6}, {0.6, 0, 1.6}, {0.7, 0, 2.3},
             {1.1, 0, 3.0} } }
local s = revolve(profile, { axis = { 0, 0, 1 }, center = { 0, 0, 0 } })

local f = figure{
  name = "surfaces-revolution",
  caption = "A shaded surface of revolution and its profile curve",
  width = "7cm", height = "8cm",
  view = { -60, 20 },
}
f:surface(s, { isolines = { 0, 8 }, hidden = "remove", width = 0.8,
               fill = "#8fb8de", shade = "smooth" })
f:curve(profile, { color = "#e07b00", width = 1.5 })
-- the axis, a curve in space: hidden where the vase is in front of it
f:curve(bezier{ { 0, 0, -0.3 }, { 0, 0, 3.4 } },
        { color = "grey", dash = "dashdot", width = 0.5, hidden = "remove" })
-- the profile named at its upper end, right of the vase's neck where
-- nothing is drawn: beside the rest of the curve the vase reaches out
-- past it and the word would lie on the shaded surface
f:label(profile:eval(1), "\\text{profile}", { place = "se" })
