-- expect: 1 "script exceeded the instruction limit of 10000000 instructions"
-- errors caught 150,000 calls deep: each costs a walk over the whole stack
-- args: --max-instructions 10000000
local function deep(n)
  if n == 0 then
    for i = 1, 300 do pcall(error, "x") end
    return 0
  end
  return 1 + deep(n - 1)
end
deep(150000)
