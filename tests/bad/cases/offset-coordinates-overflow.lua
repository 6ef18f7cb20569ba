-- expect: 1 "offset: offset coordinates of size 1e+200 (distance 1e+200) are too large"
-- an offset whose size the fits cannot square and cube (it used to run
-- forever; found by a seed of degenerate values)
local c = bezier{ {0, 0}, {1, 2}, {3, 2}, {4, 0} }
local o = c:offset(1e200, { tolerance = 1e200, trim = true })
