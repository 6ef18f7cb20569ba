-- expect: 1 "script exceeded the memory limit of 32 MiB"
-- utf8.char of a huge list
-- args: --max-memory 32
local t = {}
for i = 1, 1e8 do t[i] = 0x10FFFF end
local s = utf8.char(table.unpack(t))
