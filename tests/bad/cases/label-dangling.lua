-- expect: 1 "label: label "P_": '_' without a subscript at byte 1"
-- a label ending in _
local f = figure{ name = 'z' }
f:label({0, 0}, 'P_')
