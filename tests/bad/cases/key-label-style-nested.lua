-- expect: 1 "points: label_style: unknown option 'colr' (did you mean 'color'?)"
-- a misspelt key in a nested table
local f = figure{ name = 'z' }
f:points({ {0, 0}, {1, 2}, {2, 0}, {3, 1} }, { labels = 'P_%d', label_style = { colr = 'red' } })
