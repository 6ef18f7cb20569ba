-- expect: 1 "5000 bytes, more than the 1000 a label may have"
-- a 5,000-character label (each character laid out again with its run: quadratic)
local f = figure{ name = "l" }
f:label({0, 0}, string.rep("a", 5000))
