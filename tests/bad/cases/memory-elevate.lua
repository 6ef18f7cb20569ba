-- expect: 1 "script exceeded the memory limit of 32 MiB"
-- elevated Bezier curves (degree 21) kept alive in a loop
-- args: --max-memory 32
local t = {}
for i = 1, 1e6 do t[i] = bezier{ {0, 0}, {1, 1} }:elevate(20) end
