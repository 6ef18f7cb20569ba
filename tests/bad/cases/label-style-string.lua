-- expect: 1 "points: label_style is a style table, e.g. { color = "red" }, got string"
-- a label style that is not a table is refused, not ignored
local f = figure{ name = 'z' }
f:points({ {0, 0}, {1, 1} }, { labels = 'P_%d', label_style = 'red' })
