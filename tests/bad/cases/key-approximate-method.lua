-- expect: 1 "approximate: unknown field 'method'"
-- approximate has no method (it would be ignored)
local s = approximate{ points = { {0, 0}, {1, 2}, {2, 0}, {3, 1} }, count = 3, method = 'natural' }
