-- orazem-decasteljau, orazem-curve (seed 003, "Bezierjeva krivulja in
-- njen odmik"): the report's control points P0..P4 = (0,5) (1,-1) (3,0)
-- (4,3) (6,10).
-- orazem-decasteljau: de Casteljau at t = 3/4 with the report's colours:
-- polygon black, levels 1-4 blue, orange, yellow, purple, the curve red,
-- the final point a green star.

local P = { {0, 5}, {1, -1}, {3, 0}, {4, 3}, {6, 10} }
local c = bezier(P)

local f = figure{
  name = "orazem-decasteljau",
  caption = "de Casteljau's algorithm at t = 3/4 on P_0 ... P_4",
  width = "8cm", height = "9cm",
}
f:curve(c, { color = "red" })
f:decasteljau(c, 0.75, {
  colors = { "black", "blue", "orange", "#e6c000", "purple" },
  point = { marker = "star", color = "green", marker_color = "green",
            fill = "green", marker_size = 9 },
})
f:polygon(c, { color = "black", labels = "P_%d", label_place = "w" })
f:label(c:eval(0.75), "c(3/4)", { place = "se" })

local g = figure{
  name = "orazem-curve",
  caption = "The Bézier curve of P_0 ... P_4 sampled by de Casteljau",
  width = "8cm", height = "9cm",
}
g:polygon(c, { labels = "P_%d", label_place = "w" })
local ts = {}
for k = 0, 20 do ts[#ts + 1] = k / 20 end
g:curve(c)
g:points(c:eval(ts), { marker = "dot", marker_size = 3, color = "red",
                       marker_color = "red" })
