-- expect: 1 "arrow: point coordinate 1 is "
-- an arrow with a NaN vector
local f = figure{ name = 'z' }
f:arrow({0, 0}, {0/0, 1})
