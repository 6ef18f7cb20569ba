-- expect: 1 "figure: 'fill' is not an option: a style belongs to what is drawn"
-- figure{} has no fill: it would be ignored
local f = figure{ name = 'z', fill = 'red' }
