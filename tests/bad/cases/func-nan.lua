-- expect: 1 "func: the plotted function is not finite on [0, 1]"
-- a plotted function returning NaN everywhere
local f = figure{ name = 'z' }
f:func(function(x) return 0/0 end, 0, 1)
