-- markova-2.17 (seed 002, "B-spline křivky"): the thesis' sample curve
-- ("vzorová křivka"), degree p = 2, P0..P7 and U as given in the thesis,
-- with its knot points C(u_i) marked.

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local s = bspline{ degree = 2, knots = U, points = P }

local f = figure{
  name = "markova-2.17",
  caption = "The sample curve: p = 2, eight control points, U = {0,0,0,0.17,0.33,0.5,0.67,0.83,1,1,1}",
  width = "7cm", height = "6cm",
}
f:polygon(s, { labels = "P_%d", label_place = "ne" })
f:curve(s)
f:knots(s)
