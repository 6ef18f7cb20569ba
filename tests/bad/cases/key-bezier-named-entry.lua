-- expect: 1 "bezier: unknown field 'wieght' (did you mean 'weight"
-- a misspelt key beside a list of points
local c = bezier{ {0, 0}, {1, 2}, {2, 0}, wieght = {1, 2, 1} }
