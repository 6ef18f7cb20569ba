-- expect: 1 "second thoughts"
-- an error after a valid figure: nothing may be written
local f = figure{ name = 'fine' }
f:curve(bezier{ {0, 0}, {1, 1} })
error('second thoughts')
