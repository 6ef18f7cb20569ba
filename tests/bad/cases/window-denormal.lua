-- expect: 1 "the window spans 9.99989e-321 x 9.99989e-321, too small to draw: its scale on the page (the page's size over the span) overflows"
-- a window 1e-320 a side (a denormal): the page's scale was infinite, and the error blamed the polyline ("its place on the page overflows to NaN")
local f = figure{ name = "tiny", width = "6cm", height = "4cm", window = {0, 1e-320, 0, 1e-320} }
f:polyline({ {0, 0}, {1e-320, 1e-320} })
