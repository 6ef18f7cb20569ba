-- expect: 1 "figure: 'opacity' is not an option: a style belongs to what is drawn"
-- figure{} has no opacity: it would be ignored
local f = figure{ name = 'z', opacity = 0.5 }
