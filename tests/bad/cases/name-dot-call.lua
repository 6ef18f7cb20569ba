-- expect: 1 "curve: call a method with ':' (f:curve(...)), not '.'"
-- a method called with '.'
local f = figure{ name = 'z' }
f.curve(bezier{ {0, 0}, {1, 2}, {2, 0} })
