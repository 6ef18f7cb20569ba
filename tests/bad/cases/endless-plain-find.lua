-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- a plain find of "aaa...ab" in "aaa...a" compares the whole pattern at every byte (quadratic in C)
-- args: --max-instructions 1000000
local s = string.rep("a", 200000)
local p = string.rep("a", 100000) .. "b"
local n = 0
while true do
  assert(s:find(p, 1, true) == nil and s:find(p) == nil)
  n = n + 1
end
