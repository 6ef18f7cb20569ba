-- expect: 1 "bad argument #3 to 'string.format' (no value)"
-- a labels format with a bad directive
local f = figure{ name = 'z' }
f:polygon({ {0, 0}, {1, 1} }, { labels = 'P_%q%q%q' })
