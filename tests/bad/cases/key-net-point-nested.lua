-- expect: 1 "decasteljau: point: unknown option 'markr' (did you mean 'marker'?)"
-- a misspelt key in the net's point style
local f = figure{ name = 'z' }
f:decasteljau(bezier{ {0, 0}, {1, 2}, {2, 0} }, 0.5, { point = { markr = 'star' } })
