-- expect: 1 "k must be -1 .. -1"
-- a line reduced to a point cannot keep its end points (continuity 0, the default)
local c = bezier{{0,0},{2,4}}
local r = c:reduce()
