-- expect: 1 "'end' expected (to close 'function' at line 3) near <eof>"
-- an unclosed function
local function f()
  return 1

