-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- repeat ... until false
-- args: --max-instructions 1000000
local i = 0
repeat i = i + 1 until false
