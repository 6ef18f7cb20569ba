-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- an endless loop in a label callback
-- args: --max-instructions 1000000
local f = figure{ name = 'z' }
f:polygon({ {0, 0}, {1, 1} }, { labels = function(i) while true do end end })
