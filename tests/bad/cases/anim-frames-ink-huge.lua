-- expect: 1 "arrow 2 (line 8) lies 3534 mm outside the drawing's 60.0 x 40.0 mm page, on the left: the page cropped to the ink would be larger than the largest page (14400 pt = 5.08 m a side)"
-- an animation on a page cropped to its ink whose frames each fit the largest page but together do not (an arrow from 300 units left in the first frame, 300 right in the last): refused, naming the element of the frame that lies farthest out
-- args: --animate -f pdf
local s = slider{ name = "s", min = 0, max = 1, default = 0 }
animate{ slider = "s", from = 0, to = 1, seconds = 0.2, fps = 10 }
local f = figure{ name = "far", width = "6cm", height = "4cm", window = {0, 1, 0, 1} }
f:polyline({ {0, 0}, {1, 1} })
f:arrow_to({ -300 + 600 * s, 0.5 }, { 0.5, 0.5 })
