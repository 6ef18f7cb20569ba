-- A point near the largest double inside an explicit window: its place on
-- the page overflows to infinity.  The label placement's rasteriser crashed
-- on it (a round join between NaN directions wrote past its array).
local f = figure{ name = "far", width = "6cm", height = "4cm", window = { 0, 1, 0, 1 } }
f:polyline({ { 0, 0 }, { 1.7e308, 1 }, { 1, 2 } }, { dash = { 1, 1 } })
f:label({ 0.5, 0.5 }, "P")
