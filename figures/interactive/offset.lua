-- offset: the inward offset of Oražem's Bézier curve with a d slider
-- (seed 003, "Bezierjeva krivulja in njen odmik", section 4 "Odmik
-- krivulje", Figures 1-3 "Normala obrnjena navznoter"; the data and the
-- styles of figures/orazem-offset-1.lua).  P_0 ... P_4 = (0,5) (1,-1)
-- (3,0) (4,3) (6,10); inward is the left normal (the curve turns left
-- everywhere), d > 0 in c:offset(d).  Below the smallest radius of
-- curvature, 0.687, the offset is regular; beyond it the raw offset
-- (orange, dashed) gets two cusps (red crosses) and, up to about d = 2.5,
-- a loop (the swallow-tail); the trimmed offset (green) leaves them out.
-- d starts at 1.5, where both show; the control points can be dragged.
--
--   curvefig live figures/interactive/offset.lua

local P = points{
  name = "P",
  default = { {0, 5}, {1, -1}, {3, 0}, {4, 3}, {6, 10} },
}
local d = slider{ name = "d", min = 0.05, max = 3, default = 1.5,
                  step = 0.05 }
local c = bezier(P)

local f = figure{
  name = "offset",
  caption = "The inward offset at distance d of the slider: raw offset "
    .. "orange dashed with its cusps red, trimmed offset green",
  width = "9cm", height = "9.65cm", window = { -3.3, 9.2, -2.3, 11.1 },
}
f:polygon(c, { })
for t = 0.1, 0.95, 0.2 do
  f:arrow_to(c:eval(t), c:offset_point(t, d),
             { color = "grey", width = 0.5, arrow_size = 4 })
end
f:curve(c)
f:curve((c:offset(d)), { color = "orange", width = 0.9, dash = "dashed" })
for _, t in ipairs(c:offset_cusps(d)) do
  f:points({ c:offset_point(t, d) }, { marker = "cross", color = "red",
                                        marker_color = "red",
                                        marker_size = 6 })
end
f:curve(c:offset(d, { trim = true }), { color = "darkgreen", width = 1.8 })
f:label({ -3.1, 10.9 }, string.format("d = %.2f", d), { place = "se" })
