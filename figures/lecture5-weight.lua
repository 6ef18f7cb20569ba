-- lecture5-weight (seed 001, lecture 5, Замечание 5.4.1, item 7: "При
-- увеличении веса ω_i опорной точки p_i все точки рациональной кривой
-- Безье испытывают смещение в направлении опорной точки p_i ... концы
-- кривой не смещаются при изменении весов").
-- A family of rational cubic Bézier curves on the same points p_0 ... p_3
-- in which only ω_2 changes: ω_2 = 0.2, 0.5, 1, 2, 5, 20 (the others 1),
-- each curve named in the legend; ω_2 = 1 is the ordinary Bézier curve (dark).
-- The points r(1/2) of all the curves lie on one line through p_2
-- (dotted): raising ω_2 moves them towards p_2, lowering it away; the end
-- points p_0, p_3 stay.
-- Data chosen (the seed gives none): p_0 ... p_3 = (0,0) (1,3.4) (4.6,3.6)
-- (6.4,0.4).

local P = { {0, 0}, {1, 3.4}, {4.6, 3.6}, {6.4, 0.4} }
local ws = { 0.2, 0.5, 1, 2, 5, 20 }
local colours = { 1, 2, "black", 3, 4, 5 }

local f = figure{
  name = "lecture5-weight",
  caption = "Raising the weight ω_2 pulls the rational Bézier curve towards "
    .. "p_2 (ω_2 = 0.2, 0.5, 1, 2, 5, 20; other weights 1); the points "
    .. "r(1/2) (dots) move along a line through p_2, the end points stay",
  width = "11cm", height = "7cm",
}
f:polygon(P)
local mids = {}
for k, w in ipairs(ws) do
  local r = bezier{ points = P, weights = { 1, 1, w, 1 } }
  mids[k] = r:eval(0.5)
  f:curve(r, { color = colours[k], width = w == 1 and 2 or 1.3,
               legend = string.format("ω_2 = %g", w) })
end
-- the line through p_2 that carries all the points r(1/2)
f:line(P[3], mids[1], { color = "grey", dash = "dotted", width = 0.8 })
f:points(mids, { marker = "dot", marker_size = 4, color = "black", marker_color = "black" })
local pp = { "sw", "nw", "ne", "se" }
for i = 1, 4 do
  f:label(P[i], string.format("p_%d", i - 1), { place = pp[i] })
end
