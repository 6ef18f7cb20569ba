-- expect: 1 "print: the script's output reached its limit of 16 MiB"
-- print of 100 MB
-- args: --max-instructions 100000000
local s = string.rep("x", 1000000)
for i = 1, 100 do print(s) end
