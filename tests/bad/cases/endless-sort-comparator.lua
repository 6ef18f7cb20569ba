-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- an endless loop inside a sort comparator
-- args: --max-instructions 1000000
local t = {3, 2, 1}
table.sort(t, function(a, b) while true do end end)
