-- Three misspelt options: the message names the first in byte order,
-- 'colr', at every run (tests/lua/test_tool.c; before, the binding named
-- whichever Lua's seeded hash order gave first).
local c = bezier{ { 0, 0 }, { 1, 1 }, { 2, 0 } }
local f = figure{ name = "two-bad" }
f:curve(c, { widht = 2, dahs = "dashed", colr = "red" })
