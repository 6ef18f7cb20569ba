-- expect: 1 "no label for 0"
-- a label function that fails
local f = figure{ name = 'z' }
f:polygon({ {0, 0}, {1, 1} }, { labels = function(i) error('no label for ' .. i) end })
