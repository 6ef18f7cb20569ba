-- expect: 1 "curve: option 1 has no name; options are named"
-- an options table with an unnamed entry
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} }, { 'red' })
