-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- an endless loop in a gsub callback
-- args: --max-instructions 1000000
local s = ('x'):gsub('x', function() while true do end end)
