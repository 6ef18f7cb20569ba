-- must stop: a pattern search that backtracks for ages inside one C call
-- (the instruction counter cannot see it; the --timeout watchdog does)
local s = string.rep("a", 200000)
print(s:find(".-.-.-.-.-.-b"))
