-- Dash patterns the measuring of ink and labels cannot walk dash by dash:
-- periods of 1e-300 and 1e-6 bp (cairo draws them as one of the same
-- coverage), and a dashed line through the window to a point 1e12 away
-- (200,000 billion dashes beyond the page).  Each took the tool for ever.
local f = figure{ name = "fine", width = "6cm", height = "4cm", window = { 0, 2, 0, 2 } }
f:polyline({ { 0, 0 }, { 1, 1 }, { 2, 0 } }, { dash = { 1e-300, 1e-300 } })
f:polyline({ { 0, 0.5 }, { 1, 1.5 }, { 2, 0.5 } }, { dash = { 1e-6, 1e-6 } })
f:polyline({ { 0, 1 }, { 1e12, 1.5 }, { 1, 2 } }, { dash = { 0.01, 0.01 } })
f:label({ 1, 1 }, "P")
