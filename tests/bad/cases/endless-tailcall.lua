-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- endless tail recursion
-- args: --max-instructions 1000000
local function f(n) return f(n + 1) end
f(0)
