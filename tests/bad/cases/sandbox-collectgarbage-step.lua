-- expect: 1 "script exceeded the memory limit of 32 MiB"
-- collectgarbage tricks (generational, step) and a memory bomb
-- args: --max-memory 32
collectgarbage('generational')
collectgarbage('step', 1e9)
local s = 'x'
while true do s = s .. s end
