-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- an endless loop in a plotted function
-- args: --max-instructions 1000000
local f = figure{ name = 'z' }
f:func(function(x) while true do end end, 0, 1)
