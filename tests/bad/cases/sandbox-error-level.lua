-- expect: 1 "deep"
-- error with level 2 from the main chunk
local function f() error('deep', 2) end
f()
