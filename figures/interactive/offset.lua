-- offset: the inward offset of Oražem's Bézier curve with a d slider
-- (seed 003, "Bezierjeva krivulja in njen odmik", section 4 "Odmik
-- krivulje", Figures 1-3 "Normala obrnjena navznoter"; the data, window
-- and colours of figures/orazem-offset-1.lua).  P_0 ... P_4 = (0,5) (1,-1)
-- (3,0) (4,3) (6,10); inward is the left normal (the curve turns left
-- everywhere), d > 0 in c:offset(d).  Below the smallest radius of
-- curvature, 0.687, the offset is regular; beyond it the raw offset
-- (orange, dashed) gets two cusps (red crosses) and, up to about d = 2.25,
-- a loop (the swallow-tail); the trimmed offset (light green, wide, under
-- the raw one so that both show where they coincide) leaves them out.
-- d starts at 1.5, where both show; the control points can be dragged.
-- For the live view's speed the raw offset is drawn through 241 of its
-- exact points (c:offset_point) and the trimmed offset is fitted to 0.01
-- (0.2 bp on the page) instead of the default 0.001: one certified offset
-- of the default tolerance takes 0.1 to 0.5 s on this curve.
--
--   curvefig live figures/interactive/offset.lua

local P = points{
  name = "P",
  default = { {0, 5}, {1, -1}, {3, 0}, {4, 3}, {6, 10} },
}
local d = slider{ name = "d", min = 0.05, max = 3, default = 1.5,
                  step = 0.05 }
-- as an animation (docs/animations.md): the distance out and back
animate{ slider = "d", from = 0.05, to = 3, seconds = 4, fps = 25,
         ease = "in-out", bounce = true }
local c = bezier(P)

local f = figure{
  name = "offset",
  page = "fixed", clip = true,  -- one view while points are dragged
  caption = "The inward offset at distance d of the slider: raw offset "
    .. "orange dashed with its cusps red, over the trimmed offset, light "
    .. "green",
  width = "9cm", height = "9.65cm", window = { -3.3, 9.2, -2.3, 11.1 },
}
f:polygon(c, { })
for t = 0.1, 0.95, 0.2 do
  f:arrow_to(c:eval(t), c:offset_point(t, d),
             { color = "grey", width = 0.5, arrow_size = 4 })
end
f:curve(c)
f:curve(c:offset(d, { trim = true, tolerance = 0.01 }),
        { color = "#92d192", width = 2.6 })
local raw = {}
for i = 0, 240 do raw[i + 1] = c:offset_point(i / 240, d) end
f:polyline(raw, { color = "#c8500a", width = 0.9, dash = "dashed" })
for _, t in ipairs(c:offset_cusps(d)) do
  f:points({ c:offset_point(t, d) }, { marker = "cross", color = "red",
                                        marker_color = "red",
                                        marker_size = 6 })
end
f:label({ -3.1, 10.9 }, string.format("d = %.2f", d), { place = "se" })
