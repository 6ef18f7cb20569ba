-- expect: 1 "figure: 'dash' is not an option: a style belongs to what is drawn"
-- figure{} has no dash: it would be ignored
local f = figure{ name = 'z', dash = 'dashed' }
