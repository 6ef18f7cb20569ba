-- expect: 1 "bspline: degree must be an integer, got string"
-- degree given as a word
local s = bspline{ degree = 'two', points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
