-- expect: 1 "script exceeded the memory limit of 32 MiB"
-- a doubling string
-- args: --max-memory 32
local s = 'x'
while true do s = s .. s end
