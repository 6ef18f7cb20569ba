-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- table.remove at the front of a table whose __len says 10^15 shifts 10^15 entries in C
-- args: --max-instructions 1000000
local t = setmetatable({}, { __len = function() return 1e15 end })
table.remove(t, 1)
