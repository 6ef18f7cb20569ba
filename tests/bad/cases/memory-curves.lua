-- expect: 1 "script exceeded the memory limit of 32 MiB"
-- a million Bezier curves kept alive
-- args: --max-memory 32
local t = {}
for i = 1, 1e6 do t[i] = bezier{ {0, 0}, {i, 1}, {2, 0}, {3, i} } end
