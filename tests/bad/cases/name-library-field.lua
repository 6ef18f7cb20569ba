-- expect: 1 "knots has no field 'unifrom' (did you mean 'uniform'?)"
-- a misspelt library function
local u = knots.unifrom(2, 4)
