-- expect: 1 "script exceeded the memory limit of 32 MiB"
-- pcall catching the memory limit
-- args: --max-memory 32
local ok = pcall(function() local s = 'x'; while true do s = s .. s end end)
local t = {}
for i = 1, 1e9 do t[i] = i end
