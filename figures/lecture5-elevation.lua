-- lecture5-elevation (seed 001, lecture 5, "Увеличение числа опорных
-- точек без изменения формы кривой Безье": "q_i = (n+1−i)/(n+1) p_i
-- (1 − δ_{(n+1)i}) + i/(n+1) p_{i−1} (1 − δ_{0i}), i = 0, ..., n+1").
-- A cubic Bézier curve with its control points p_0 ... p_3 (grey
-- polygon) and the n + 2 = 5 points q_0 ... q_4 of the same curve
-- written with one control point more (blue polygon): q_0 = p_0,
-- q_4 = p_3, each inner q_i on the side p_{i−1}p_i.  The curve of the q_i
-- (thin white dashes) lies exactly on the curve of the p_i: the shape
-- does not change.
-- Data chosen (the seed gives none): p_0 ... p_3 = (0,0) (1.6,3.4)
-- (5.8,2.6) (5,-0.6), an asymmetric arch.

local c = bezier{ {0, 0}, {1.6, 3.4}, {5.8, 2.6}, {5, -0.6} }
local q = bezier(c:elevate(1):points())   -- built from the q_i themselves
local blue = "#1f5fbf"
for j = 0, 20 do   -- the shape does not change
  local a, b = c:eval(j / 20), q:eval(j / 20)
  if math.abs(a[1] - b[1]) + math.abs(a[2] - b[2]) > 1e-9 then
    error("elevated curve differs at t = " .. j / 20)
  end
end

local f = figure{
  name = "lecture5-elevation",
  caption = "Adding a control point without changing the curve: the cubic's "
    .. "points p_0 ... p_3 (grey) and q_0 ... q_4 with q_i = (n+1−i)/(n+1) p_i "
    .. "+ i/(n+1) p_{i−1} (blue); the curve of the q_i (dashed) coincides",
  width = "10cm", height = "5.5cm",
}
f:polygon(c)
f:polygon(q, { color = blue, marker_color = blue, width = 1 })
f:curve(c)
f:curve(q, { color = "white", dash = { 3, 4 }, width = 0.8 })
local P = c:points()
local pp = { "w", "n", "ne", "e" }
for i = 1, 4 do
  local text = string.format("p_%d", i - 1)
  if i == 1 then text = "p_0 = q_0" elseif i == 4 then text = "p_3 = q_4" end
  f:label(P[i], text, { place = pp[i] })
end
local Q = q:points()
local qp = { nil, "se", "s", "sw", nil }
for i = 2, 4 do
  f:label(Q[i], string.format("q_%d", i - 1), { place = qp[i], color = blue })
end
