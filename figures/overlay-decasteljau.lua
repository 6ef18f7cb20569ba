-- overlay-decasteljau (seed 003, Oražem, "Bezierjeva krivulja in njen
-- odmik", section 2.1 "Primer poteka algoritma"; the construction of
-- orazem-decasteljau shown level by level, as overlay steps for slides).
--
-- De Casteljau's algorithm on the report's control points P_0..P_4 =
-- (0,5) (1,-1) (3,0) (4,3) (6,10) at t = 3/4, one level per step:
--   step 1  the control polygon (black) with P_0..P_4;
--   step 2  level 1, b_j^1 = (1 - t) P_j + t P_{j+1} (blue);
--   step 3  level 2 (orange);
--   step 4  level 3 (the report's yellow, deep #e8b800);
--   step 5  the point b_0^4(3/4) (green star) and the curve (red).
-- Colours as the report describes them (see orazem-decasteljau.lua).
-- Every step keeps the levels before it (visible = "k-").  One script
-- gives a PDF of five pages, PGF with \visible<k->, an animated SVG and
-- overlay-decasteljau-1.png .. -5.png (docs/overlays.md).

local P = { {0, 5}, {1, -1}, {3, 0}, {4, 3}, {6, 10} }
local c = bezier(P)
local t = 3 / 4
local L = c:decasteljau(t)
assert(#L == 5 and #L[5] == 1)
local colors = { "black", "blue", "orange", "#e8b800" }
-- the levels told apart by dash and marker as well as by colour (as
-- theme{ redundant = true } does for a net; docs/accessibility.md), for
-- colour-blind readers and greyscale print: the colours stay the report's
local dashes = { "solid", { 4, 2 }, { 1, 1.5 }, { 5, 1.5, 1, 1.5 } }
local marks = { "dot", "square", "diamond", "triangle" }

local f = figure{
  name = "overlay-decasteljau",
  caption = "De Casteljau's algorithm at t = 3/4 on P_0 ... P_4, level " ..
            "by level in five overlay steps: the control polygon, levels " ..
            "1-3, then the point b_0^4(3/4) on the red curve",
  width = "8cm", height = "10.5cm",
}
f:curve(c, { color = "red", visible = "5-" })
for j = 1, 4 do
  f:polygon(L[j], { color = colors[j], marker_color = colors[j],
                    dash = dashes[j], marker = marks[j],
                    width = 1.0, visible = j .. "-" })
end
f:points(L[5], { marker = "star", color = "green", marker_color = "green",
                 marker_size = 11, visible = "5-" })
local place = { "w", "s", "se", "e", "w" }
for i = 0, 4 do
  f:label(P[i + 1], string.format("P_%d", i), { place = place[i + 1] })
end
f:label(L[5][1], "b_0^4(3/4)", { place = "w", offset = 8, color = "green",
                                 visible = "5-" })
