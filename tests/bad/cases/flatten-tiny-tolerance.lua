-- expect: 1 "flatten: more than 1048576 points at tolerance 1e-300"
-- a tolerance far below the curve's size (the flattening's buffer was freed twice)
local c = bezier{ {0, 0}, {1, 2}, {2, 0} }
c:flatten(1e-300)
