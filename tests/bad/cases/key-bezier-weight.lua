-- expect: 1 "bezier: unknown field 'weight' (did you mean 'weights'?)"
-- weights under a singular name
local c = bezier{ points = { {0, 0}, {1, 2}, {2, 0}, {3, 1} }, weight = {1, 2, 2, 1} }
