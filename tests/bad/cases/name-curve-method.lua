-- expect: 1 "bezier has no method 'elevat' (did you mean 'elevate'?)"
-- a misspelt curve method
local c = bezier{ {0, 0}, {1, 2}, {2, 0} }
local d = c:elevat(1)
