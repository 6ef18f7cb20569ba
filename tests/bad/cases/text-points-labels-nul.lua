-- expect: 1 "points: labels has a NUL byte at byte 1"
-- a NUL in a point's label silently cut it
local f = figure{ name = "c" }
f:points({ {0, 0}, {1, 1} }, { labels = { "P", "Q\0R" } })
