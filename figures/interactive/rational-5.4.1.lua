-- rational-5.4.1: Example 5.4.1 of seed 001 (lecture 5, "Рациональные
-- кривые Безье"), the Mathematica Manipulate made interactive: the
-- rational Bézier curve on the example's eight points, the points dragged
-- with the mouse and their eight weights ω_0 ... ω_7 set with sliders
-- 1 ... 100, drawn with the ordinary Bézier curve on the same points.  All
-- weights start at 1, so the two curves coincide until a weight moves
-- ("Первоначально все веса сделаны одинаковыми, поэтому после запуска
-- программы обе кривые совпадают").  The window is the example's
-- PlotRange {{-30, 15}, {-10, 15}}; the point numbers in red, beside
-- their points (its Text[ToString[# - 1], pts[[#]] + {1.2, 0.2}] puts
-- them at one offset; here they take the clearest side).
--
--   curvefig live figures/interactive/rational-5.4.1.lua

local P = points{
  name = "P",
  default = { {-10.0, 0.0}, {-3.0, 7.0}, {1.1, -7.2}, {4.3, -8.5},
              {-16.0, 12.0}, {-2.1, 1.7}, {-8.2, 1.4}, {12.2, 5.4} },
}
local w = {}
for i = 0, 7 do
  -- a log slider: 1 to 2 takes as much of it as 50 to 100
  w[i + 1] = slider{ name = "w" .. i, label = "\\omega_" .. i, min = 1,
                     max = 100, default = 1, step = 0.1, scale = "log" }
end

local f = figure{
  name = "rational-5.4.1",
  page = "fixed", clip = true,  -- one view while points are dragged
  caption = "Example 5.4.1: the rational Bézier curve with weights ω_i "
    .. "(red) and the ordinary Bézier curve (blue, dashed) on the same "
    .. "eight points",
  width = "15cm", height = "8.5cm",
  window = { -30, 15, -10, 15 },
}
-- no tick label at the origin: either axis would strike its "0"
f:plot{ x = { -30, 15 }, y = { -10, 15 },
        xticks = { -30, -25, -20, -15, -10, -5, 5, 10, 15 },
        yticks = { -10, -5, 5, 10, 15 } }
f:polyline(P, { color = "#8c8c8c", width = 0.5 })
f:curve(bezier(P), { color = "#1f5fbf", dash = "dashed", width = 1.2 })
f:curve(bezier{ points = P, weights = w }, { color = "#c0392b", width = 1.4 })
f:points(P, { color = "#3c3c3c", marker_color = "#3c3c3c" })
-- the numbers placed automatically, clear of the curves as the points
-- move (the page chooses the same places as the tool)
for i, p in ipairs(P) do
  f:label(p, tostring(i - 1), { color = "red" })
end
