-- expect: 1 "bezier: unknown field 'wieghts' (did you mean 'weights'?)"
-- two letters of weights swapped
local c = bezier{ points = { {0, 0}, {1, 2}, {2, 0}, {3, 1} }, wieghts = {1, 2, 2, 1} }
