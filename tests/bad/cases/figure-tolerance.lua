-- expect: 1 "figure: tolerance 0 must be finite and positive"
-- a zero fitting tolerance
local f = figure{ name = 'z', tolerance = 0 }
