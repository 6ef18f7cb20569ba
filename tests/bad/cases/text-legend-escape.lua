-- expect: 1 "curve: legend has the control character U+001B at byte 1"
-- a terminal escape in a legend entry
local f = figure{ name = "c" }
f:curve(bezier{ {0, 0}, {1, 1} }, { legend = "a\27[31m" })
