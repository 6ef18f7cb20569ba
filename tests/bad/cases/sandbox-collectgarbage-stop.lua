-- expect: 1 "script exceeded the memory limit of 32 MiB"
-- collectgarbage('stop') then allocating
-- args: --max-memory 32
collectgarbage('stop')
local t = {}
for i = 1, 1e9 do t[i] = {i} end
