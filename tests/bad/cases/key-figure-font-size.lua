-- expect: 1 "figure: 'font_size' is not an option: a style belongs to what is drawn"
-- figure{} has no font_size: it would be ignored
local f = figure{ name = 'z', font_size = 12 }
