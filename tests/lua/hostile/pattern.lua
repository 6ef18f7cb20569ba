-- must stop: a pattern search that backtracks for ages inside one C call
-- (its steps are counted before it runs, against the instruction limit)
local s = string.rep("a", 200000)
print(s:find(".-.-.-.-.-.-b"))
