-- expect: 1 "bezier has no method 'degree_elevate' (did you mean 'elevate'?)"
-- a method named by what it does: the nearest method is a word of it
local c = bezier{ {0, 0}, {1, 1}, {2, 0} }
c:degree_elevate(1)
