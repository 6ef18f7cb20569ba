-- expect: 1 "attempt to perform arithmetic on a nil value"
-- the run command on a failing script
-- command: run
print('computing')
local x = nil + 1
