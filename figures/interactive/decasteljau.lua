-- decasteljau: de Casteljau's algorithm with a t slider, on Oražem's
-- control points P_0 ... P_4 = (0,5) (1,-1) (3,0) (4,3) (6,10) (seed 003,
-- "Bezierjeva krivulja in njen odmik", section 2.1, as in
-- figures/orazem-decasteljau.lua, whose colours it keeps: the polygon
-- black, the levels blue, orange and yellow, the curve red, the point
-- b_0^4(t) a green star).  The points can be dragged; t starts at 3/4,
-- the parameter of the printed figure.
--
--   curvefig live figures/interactive/decasteljau.lua

local P = points{
  name = "P",
  default = { {0, 5}, {1, -1}, {3, 0}, {4, 3}, {6, 10} },
}
local t = slider{ name = "t", min = 0, max = 1, default = 0.75,
                  step = 0.01 }
-- as an animation (`curvefig render ... -f gif`, docs/animations.md):
-- t from 0 to 1 in 4 s
animate{ slider = "t", from = 0, to = 1, seconds = 4, fps = 25 }
local c = bezier(P)

-- The levels told apart by dash and marker as well as by colour, which
-- colour-blind readers and greyscale print need (docs/accessibility.md):
-- the colours stay the report's.
theme{ redundant = true }

local f = figure{
  name = "decasteljau",
  page = "fixed", clip = true,  -- one view while points are dragged
  caption = "De Casteljau's algorithm on P_0 ... P_4 at the slider's t: "
    .. "control polygon black, levels 1-3 blue, orange, yellow, the curve "
    .. "red, the point b_0^4(t) a green star",
  width = "9cm", height = "10.5cm", window = { -1.5, 7.5, -2.5, 11 },
}
f:curve(c, { color = "red" })
f:decasteljau(c, t, {
  colors = { "black", "blue", "orange", "#e8b800", "green" },
  width = 1.0,
  point = { marker = "star", color = "green", marker_color = "green",
            marker_size = 11 },
})
for i = 0, 4 do
  f:label(P[i + 1], string.format("P_%d", i), { place = "auto" })
end
f:label({ -1.3, 10.8 }, string.format("t = %.2f", t), { place = "se" })
