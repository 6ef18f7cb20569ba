-- expect: 1 "script exceeded the memory limit of 32 MiB"
-- a growing table
-- args: --max-memory 32
local t = {}
for i = 1, 1e9 do t[i] = { i, i } end
