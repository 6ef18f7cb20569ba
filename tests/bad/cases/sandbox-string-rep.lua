-- expect: 1 "resulting string too large"
-- string.rep of 2^40 bytes
-- args: --max-memory 32
local s = string.rep('x', 1 << 40)
