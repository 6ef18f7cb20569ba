-- expect: 1 "plot: xlabel must be a string, got table"
-- an axis label that is not text names the option
local f = figure{ name = 'z' }
f:plot{ x = {0, 1}, y = {0, 1}, xlabel = { 'u' } }
