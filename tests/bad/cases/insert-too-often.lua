-- expect: 1 "insert_knot: knot 0.5 has multiplicity 0; inserting it 4 more"
-- insertion beyond multiplicity p + 1
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
local t = s:insert_knot(0.5, 4)
