-- expect: 1 "label: label "P_{0": unbalanced '{' at byte 2"
-- a label with an unclosed brace
local f = figure{ name = 'z' }
f:label({0, 0}, 'P_{0')
