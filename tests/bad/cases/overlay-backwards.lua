-- expect: 1 "curve: visible = "3-1": the range 3-1 runs backwards"
-- an overlay range that runs backwards
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} }, { visible = '3-1' })
