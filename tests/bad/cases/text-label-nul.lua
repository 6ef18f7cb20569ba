-- expect: 1 "label: the text has a NUL byte at byte 2"
-- a NUL in a label silently cut it
local f = figure{ name = "c" }
f:label({0, 0}, "ab\0cd")
