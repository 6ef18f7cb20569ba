-- expect: 1 "arrow 2 (line 5) lies 7819 mm outside the drawing's 60.0 x 40.0 mm page, on the top: the page cropped to the ink would be larger than the largest page (14400 pt = 5.08 m a side)"
-- a page cropped to its ink that would be larger than any page (PDF's limit of 200 in a side): refused, naming the element that lies farthest out
local f = figure{ name = "far", width = "6cm", height = "4cm", window = {0, 1, 0, 1} }
f:polyline({ {0, 0}, {1, 1} })
f:arrow_to({ 1000, 1000 }, { 0.5, 0.5 })
