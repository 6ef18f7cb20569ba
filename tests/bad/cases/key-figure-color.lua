-- expect: 1 "figure: 'color' is not an option: a style belongs to what is drawn"
-- figure{} has no color: it would be ignored
local f = figure{ name = 'z', color = 'red' }
