-- expect: 1 "bad argument #1 to 'figure' (table expected, got string)"
-- figure called with a string
local f = figure('z')
