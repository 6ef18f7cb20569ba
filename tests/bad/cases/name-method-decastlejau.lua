-- expect: 1 "figure has no method 'decastlejau' (did you mean 'decasteljau'?)"
-- a misspelt method
local f = figure{ name = 'z' }
f:decastlejau(bezier{ {0, 0}, {1, 2}, {2, 0} }, 0.5)
