-- deboor: de Boor's algorithm with a u slider on Marková's sample curve
-- (seed 002, "B-spline křivky", §3.2 "De Boorův algoritmus"; the data of
-- figures/overlay-deboor.lua and markova-3.5.lua): P_0 ... P_7, degree
-- p = 3, the clamped knots U = {0, 0, 0, 0, 0.25, 0.4, 0.7, 0.85, 1, 1,
-- 1, 1}.  The net of the span that holds u: the p + 1 points acting on
-- it, the columns P_{i,1} (blue), P_{i,2} (orange) and P_{k,3} = C(u)
-- (red star).  The control points can be dragged; u starts at 0.5.
--
--   curvefig live figures/interactive/deboor.lua

local P = points{
  name = "P",
  default = { {3, 1}, {3.75, 2}, {5, 3}, {4, 4}, {3, 3}, {2, 4}, {1, 3},
              {2.25, 2} },
}
local u = slider{ name = "u", min = 0, max = 1, default = 0.5, step = 0.01 }
-- as an animation (docs/animations.md): u from 0 to 1 in 4 s
animate{ slider = "u", from = 0, to = 1, seconds = 4, fps = 25 }
local U = { 0, 0, 0, 0, 0.25, 0.4, 0.7, 0.85, 1, 1, 1, 1 }
local s = bspline{ degree = 3, knots = U, points = P }

local f = figure{
  name = "deboor",
  page = "fixed", clip = true,  -- one view while points are dragged
  caption = "De Boor's algorithm at the slider's u on the sample curve "
    .. "(p = 3): the points of the span, P_{i,1} (blue), P_{i,2} (orange), "
    .. "C(u) (red star)",
  width = "10cm", height = "8cm", window = { 0.4, 5.6, 0.5, 4.6 },
}
f:polygon(s, { color = "grey", marker_color = "grey" })
f:curve(s, { color = "#7f93c0", width = 1.2 })
f:deboor(s, u, {
  colors = { "black", "blue", "orange", "red" },
  width = 1.0,
  point = { marker = "star", color = "red", marker_color = "red",
            marker_size = 10 },
})
f:label({ 0.5, 4.5 }, string.format("u = %.2f", u), { place = "se" })
