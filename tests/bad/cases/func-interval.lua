-- expect: 1 "func: function range [1, 0] is empty"
-- a function plotted on [1, 0]
local f = figure{ name = 'z' }
f:func(function(x) return x end, 1, 0)
