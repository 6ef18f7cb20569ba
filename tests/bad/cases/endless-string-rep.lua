-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- string.rep of an empty string 10^13 times loops in C
-- args: --max-instructions 1000000
local s = string.rep("", 1e13)
