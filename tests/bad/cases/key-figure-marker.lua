-- expect: 1 "figure: 'marker' is not an option: a style belongs to what is drawn"
-- figure{} has no marker: it would be ignored
local f = figure{ name = 'z', marker = 'dot' }
