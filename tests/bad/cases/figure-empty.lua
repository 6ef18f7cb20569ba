-- expect: 1 "the figure draws nothing"
-- a figure with nothing drawn is an error, not a blank page
local f = figure{ name = 'z' }
