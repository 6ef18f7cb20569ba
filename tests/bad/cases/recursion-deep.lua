-- expect: 1 "stack overflow"
-- deep non-tail recursion
-- args: --timeout 10
local function f(n) return 1 + f(n + 1) end
f(0)
