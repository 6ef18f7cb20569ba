-- sir-elevation (seed 000, Šír, "Bézierovy křivky", slide "Bézierovy
-- křivky": "Věta: Křivky c(t) s řídicími body P_i ... lze také vyjádřit
-- jako křivku s řídicími body Q_i, i = 0, ..., n+1 a
-- Q_i = i/(n+1) P_{i−1} + (1 − i/(n+1)) P_i").
-- Left: degree elevation n = 3 → 4 of one cubic: the polygon P_0 ... P_3
-- (grey), the new polygon Q_0 ... Q_4 (blue; Q_0 = P_0, Q_4 = P_3, the
-- inner Q_i cut the corners of the old polygon), the unchanged curve.
-- Right: the same curve (translated by (6, 0)) and the polygons of
-- repeated elevation to degrees 3, 4, 6, 10, 20, 60: the polygons
-- approach the curve.
-- Data chosen (the seed gives none): P_0 ... P_3 = (0,0) (0.6,3)
-- (3.6,3.2) (4.4,0.2).

local P = { {0, 0}, {0.6, 3}, {3.6, 3.2}, {4.4, 0.2} }
local c = bezier(P)
local e = c:elevate(1)

local f = figure{
  name = "sir-elevation",
  caption = "Degree elevation: left, the cubic's polygon P_0 ... P_3 and "
    .. "the polygon Q_0 ... Q_4 of the same curve as a quartic; right, "
    .. "repeated elevation to degrees 4, 6, 10, 20, 60: the polygons "
    .. "converge to the curve",
  width = "14cm", height = "5.6cm",
}
-- left panel
f:polygon(c)
f:polygon(e, { color = "blue", marker_color = "blue", width = 1 })
f:curve(c)
local pp = { "sw", "nw", "ne", "se" }
for i = 1, 4 do
  local text = string.format("P_%d", i - 1)
  if i == 1 then text = "P_0 = Q_0" elseif i == 4 then text = "P_3 = Q_4" end
  f:label(P[i], text, { place = pp[i] })
end
local Q = e:points()
local qp = { nil, "se", "s", "sw", nil }
for i = 2, 4 do
  f:label(Q[i], string.format("Q_%d", i - 1), { place = qp[i], color = "blue" })
end

-- right panel: repeated elevation
local shift = { 6.5, 0 }
local function moved(curve) return curve:transform({ {1, 0}, {0, 1} }, shift) end
local cm = moved(c)
local degrees = { 3, 4, 6, 10, 20, 60 }
local colours = { "grey", 1, 2, 3, 4, 5 }
for k, n in ipairs(degrees) do
  local d = cm
  if n > 3 then d = cm:elevate(n - 3) end
  local marker = n <= 10 and "dot" or "none"
  f:polygon(d, { color = colours[k], marker_color = colours[k], width = 0.8,
                 marker = marker, marker_size = n <= 6 and 4 or 2.5 })
end
f:curve(cm)
-- a small key in the right panel's empty lower middle
for k, n in ipairs(degrees) do
  f:label({ shift[1] + 2.2, 1.55 - 0.34 * (k - 1) }, string.format("n = %d", n),
          { place = "center", color = colours[k], font_size = 8 })
end
