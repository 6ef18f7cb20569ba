-- expect: 1 "xticks"
-- negative tick step
local f = figure{ name = 'z' }
f:plot{ x = {0, 1}, y = {0, 1}, xticks = -0.1 }
