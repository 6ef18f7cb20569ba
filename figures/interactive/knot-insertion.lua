-- knot-insertion: Boehm's knot insertion with a u slider on Marková's
-- sample curve (seed 002, "B-spline křivky", §3.1 "Vložení uzlu", Obr.
-- 3.1 and 3.2; the data of figures/overlay-knot-insertion.lua): P_0 ...
-- P_7, degree p = 2, U = {0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1}.
-- The knot u is inserted once: the old polygon dashed grey, the new one
-- dark with its p = 2 new points blue, the new knot point C(u) green.
-- The curve does not change.  The control points can be dragged; u starts
-- at 0.6, the thesis' "nový uzel t = 0.6".
--
--   curvefig live figures/interactive/knot-insertion.lua

local P = points{
  name = "P",
  default = { {3, 1}, {3.75, 2}, {5, 3}, {4, 4}, {3, 3}, {2, 4}, {1, 3},
              {2.25, 2} },
}
local u = slider{ name = "u", min = 0.01, max = 0.99, default = 0.6,
                  step = 0.01 }
-- as an animation (docs/animations.md): the new knot from 0.01 to 0.99
animate{ slider = "u", from = 0.01, to = 0.99, seconds = 4, fps = 25 }
local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local s = bspline{ degree = 2, knots = U, points = P }
local n, info = s:insert_knot(u)

local f = figure{
  name = "knot-insertion",
  page = "fixed", clip = true,  -- one view while points are dragged
  caption = "Knot insertion at the slider's u on the sample curve (p = 2): "
    .. "the old polygon dashed, the new one with its two new points blue, "
    .. "the knot point C(u) green; the curve stays",
  width = "10cm", height = "8cm", window = { 0.4, 5.6, 0.5, 4.6 },
}
f:curve(s, { color = "#7f93c0", width = 1.2 })
f:polyline(P, { color = "grey", dash = "dashed", width = 0.8 })
f:polygon(n)
local Q, new = n:points(), {}
for j = info.new_first, info.new_first + info.new_count - 1 do
  new[#new + 1] = Q[j + 1]
end
f:points(new, { marker = "dot", color = "blue", marker_color = "blue",
                marker_size = 5 })
f:points({ n:eval(u) }, { marker = "dot", color = "darkgreen",
                          marker_color = "darkgreen", marker_size = 5 })
f:label({ 0.5, 4.5 }, string.format("u = %.2f", u), { place = "se" })
