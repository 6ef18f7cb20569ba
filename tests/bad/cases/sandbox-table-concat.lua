-- expect: 1 "script exceeded the memory limit of 32 MiB"
-- table.concat bomb
-- args: --max-memory 32
local t = {}
for i = 1, 64 do t[i] = string.rep('y', 1 << 20) end
local s = ''
for i = 1, 100 do s = s .. table.concat(t) end
