-- expect: 1 "interpolate: unknown field 'methd' (did you mean 'method'?)"
-- a misspelt interpolation option
local s = interpolate{ points = { {0, 0}, {1, 2}, {2, 0}, {3, 1} }, methd = 'periodic' }
