-- orazem-curve (seed 003, Oražem, "Bezierjeva krivulja in njen odmik",
-- section 3 "Bezierjeva krivulja").
--
-- The Bézier curve of the report's control points P_0..P_4 = (0,5)
-- (1,-1) (3,0) (4,3) (6,10), obtained as the report does it: the
-- parameter interval [0, 1] is divided into many pieces and de
-- Casteljau's algorithm is called at every division point ("izračunamo
-- točke na krivulji za čimveč različnih parametrov").  Here 40 equal
-- pieces: the 41 points b_0^4(t_i) from c:decasteljau(t_i) are drawn as
-- red dots joined by a red polyline (the report's colour for the curve),
-- with the control polygon in black as in its de Casteljau figure.

local P = { {0, 5}, {1, -1}, {3, 0}, {4, 3}, {6, 10} }
local c = bezier(P)
local N = 40

local pts = {}
for i = 0, N do
  local levels = c:decasteljau(i / N)
  pts[#pts + 1] = levels[#levels][1]
end

local f = figure{
  name = "orazem-curve",
  caption = "The Bézier curve of P_0 ... P_4 sampled by de Casteljau's " ..
            "algorithm at 41 equally spaced parameters t_i = i/40, with " ..
            "its control polygon",
  width = "8cm", height = "10.5cm",
}
f:polygon(P, { color = "black", marker_color = "black", width = 0.8 })
f:polyline(pts, { color = "red", width = 1.2 })
f:points(pts, { marker = "dot", color = "red", marker_color = "red",
                marker_size = 2.6 })
local place = { "w", "s", "se", "e", "w" }
for i = 0, 4 do
  f:label(P[i + 1], string.format("P_%d", i), { place = place[i + 1] })
end
