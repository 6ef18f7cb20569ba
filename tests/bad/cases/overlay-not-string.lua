-- expect: 1 "plot: visible is an overlay specification, a string of steps such as "2-" or "1,3", not a table"
-- the steps as a table
local f = figure{ name = 'z' }
f:plot{ x = { 0, 1 }, y = { 0, 1 }, visible = { 2 } }
