-- expect: 1 "decasteljau: visible = "": the specification is empty"
-- an empty overlay specification
local f = figure{ name = 'z' }
f:decasteljau(bezier{ {0, 0}, {1, 1}, {2, 0} }, 0.5, { visible = '' })
