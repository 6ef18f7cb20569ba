-- expect: 1 "interpolate: method "natral" is unknown (did you mean "natural"?)"
-- a misspelt enumerated value
local s = interpolate{ points = { {0, 0}, {1, 2}, {2, 0}, {3, 1} }, method = 'natral' }
