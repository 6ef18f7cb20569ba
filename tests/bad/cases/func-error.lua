-- expect: 1 "bad x"
-- a plotted function that fails
local f = figure{ name = 'z' }
f:func(function(x) error('bad x') end, 0, 1)
