-- expect: 1 "the figure has 260 labels, more than the 250 placed in one figure"
-- 260 labels in one figure (placing each among the others grows faster than their square)
local f = figure{ name = "l" }
for i = 1, 260 do f:label({i, 0}, "P_{" .. i .. "}") end
