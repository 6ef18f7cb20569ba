-- expect: 1 "script exceeded the memory limit of 32 MiB"
-- a figure with millions of points
-- args: --max-memory 32
local f = figure{ name = 'z' }
for i = 1, 1e7 do f:points({ {i, i} }) end
