-- expect: 1 "points: visible = "2-x": unexpected "x""
-- a letter after an open range
local f = figure{ name = 'z' }
f:points({ { 0, 0 }, { 1, 1 } }, { visible = '2-x' })
