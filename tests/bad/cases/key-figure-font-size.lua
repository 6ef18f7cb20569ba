-- expect: 1 "figure: font_size must be positive"
-- figure{} takes the size of its labels; a negative one is refused
local f = figure{ name = 'z', font_size = -12 }
