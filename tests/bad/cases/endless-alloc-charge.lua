-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- table.concat of 1 MB 1,500 times: the bytes' charge must stop it at once, not at the next hook
-- args: --max-instructions 1000000
local t = {}
for i = 1, 8 do t[i] = string.rep("x", 131072) end
for i = 1, 1500 do local s = table.concat(t) end
