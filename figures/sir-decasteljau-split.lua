-- sir-decasteljau-split (seed 000, Šír, "Bézierovy křivky", last slide:
-- the de Casteljau points "P_{0,j} := P_j, P_{i,j} := (1 − t)P_{i−1,j} +
-- tP_{i−1,j+1}"; "Věta: P_{n,0} = c(t) a úsečka P_{n−1,0}P_{n−1,1} je
-- tečnou v tomto bodě"; "Věta: P_{i,0}, i = 0, ..., n jsou řídicími body
-- části křivky c na intervalu [0, t] a body P_{n−i,i} ... na intervalu
-- [t, 1]").
-- The de Casteljau triangle of a cubic at t = 0.4 (thin grey lines, all
-- points P_{i,j} labelled in the seed's notation: i the level, j the
-- index), the point c(t) = P_{3,0}, the polygon P_{0,0} P_{1,0} P_{2,0}
-- P_{3,0} of the part on [0, t] (blue) and P_{3,0} P_{2,1} P_{1,2}
-- P_{0,3} of the part on [t, 1] (red), each with its arc in the same
-- colour, and the tangent at c(t): the segment P_{2,0}P_{2,1} (a broad
-- green band under the two polygons' legs, continued as a dashed line).
-- Data chosen (the seed gives none): P_0 ... P_3 = (0,0) (1,3.2) (4.4,3.6)
-- (5.4,0.4), t = 0.4.

local c = bezier{ {0, 0}, {1, 3.2}, {4.4, 3.6}, {5.4, 0.4} }
local t = 0.4
local L = c:decasteljau(t)           -- L[i + 1][j + 1] = P_{i,j}
local n = c:degree()
local left, right = c:split(t)
local blue, red, green = "#1f5fbf", "#c0392b", "#2e8b3a"

local f = figure{
  name = "sir-decasteljau-split",
  caption = "de Casteljau at t = 0.4: the points P_{i,j}; P_{i,0} (blue) "
    .. "and P_{n−i,i} (red) are the control polygons of the parts on [0, t] "
    .. "and [t, 1]; the segment P_{2,0}P_{2,1} is the tangent at c(t) = P_{3,0}",
  width = "11cm", height = "7.2cm",
}
-- the whole triangle, thin grey
for i = 0, n - 1 do
  f:polyline(L[i + 1], { color = "grey", width = 0.6 })
end
-- the tangent line through c(t), dashed beyond the segment
local a, b = L[n][1], L[n][2]
local d = { b[1] - a[1], b[2] - a[2] }
f:line({ a[1] - 0.35 * d[1], a[2] - 0.35 * d[2] }, { b[1] + 0.12 * d[1], b[2] + 0.12 * d[2] },
       { color = green, dash = "dashed", width = 0.8 })
f:line(a, b, { color = green, width = 5, opacity = 0.55 })
-- the two halves: polygons and arcs
f:curve(left, { color = blue, width = 2.2 })
f:curve(right, { color = red, width = 2.2 })
f:polygon(left, { color = blue, marker_color = blue, width = 1.1 })
f:polygon(right, { color = red, marker_color = red, width = 1.1 })
f:points(L[1], { marker = "dot", color = "grey", marker_color = "#333333" })
f:points(L[2][2], { marker = "dot", color = "grey", marker_color = "grey" })
f:points(L[n + 1][1], { marker = "dot", marker_size = 6, color = "black",
                        marker_color = "black" })

-- labels P_{i,j}: places chosen one by one (i = level, j = index)
local place = {
  [0] = { "sw", "nw", "ne", "se" },
  [1] = { "w", "n", "e" },
  [2] = { "nw", "n" },
  [3] = { "se" },
}
for i = 0, n do
  for j = 0, n - i do
    local text = string.format("P_{%d,%d}", i, j)
    if i == n then text = text .. " = c(0.4)" end
    local at = L[i + 1][j + 1]
    f:label(at, text,
            { place = place[i][j + 1], offset = i == n and 3 or nil })
  end
end
