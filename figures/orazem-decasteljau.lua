-- orazem-decasteljau (seed 003, Oražem, "Bezierjeva krivulja in njen
-- odmik", section 2.1 "Primer poteka algoritma", the figure after "Slika
-- spodaj prikazuje potek zgornjega postopka").
--
-- De Casteljau's algorithm on the report's control points P_0..P_4 =
-- (0,5) (1,-1) (3,0) (4,3) (6,10) at t = 3/4:
-- b_j^0 = P_j, b_j^k = (1 - t) b_j^{k-1} + t b_{j+1}^{k-1}, k = 1..4;
-- b_0^4(t) is the point on the curve.  Colours exactly as the report
-- describes them: "Črna barva predstavlja začetne točke (kontrolni
-- poligon) ..., rdeča barva končno Bezierjevo krivuljo, naslednji koraki
-- si sledijo z modro barvo, oranžno in rumeno. Z zeleno zvezdico je
-- označena končna izračunana točka." -- the control polygon black,
-- levels 1, 2, 3 blue, orange, yellow, the Bézier curve red, the final
-- point b_0^4(3/4) (level 4, a single point) a green star.  The yellow
-- is a deep yellow (#e8b800) so that it stays visible on white paper.
-- Labels (not given by the report): P_0..P_4 and b_0^4(3/4).

-- The levels told apart by dash and marker as well as by colour, which
-- colour-blind readers and greyscale print need (docs/accessibility.md):
-- the colours stay the report's.
theme{ redundant = true }

local P = { {0, 5}, {1, -1}, {3, 0}, {4, 3}, {6, 10} }
local c = bezier(P)
local t = 3 / 4

local f = figure{
  name = "orazem-decasteljau",
  caption = "De Casteljau's algorithm at t = 3/4 on P_0 ... P_4: control " ..
            "polygon black, levels 1-3 blue, orange, yellow, the curve " ..
            "red, the point b_0^4(3/4) a green star",
  width = "8cm", height = "10.5cm",
}
f:curve(c, { color = "red" })
f:decasteljau(c, t, {
  colors = { "black", "blue", "orange", "#e8b800", "green" },
  width = 1.0,
  point = { marker = "star", color = "green", marker_color = "green",
            marker_size = 11 },
})
local place = { "w", "s", "se", "e", "w" }
for i = 0, 4 do
  f:label(P[i + 1], string.format("P_%d", i), { place = place[i + 1] })
end
f:label(c:eval(t), "b_0^4(3/4)", { place = "w", offset = 8, color = "green" })
