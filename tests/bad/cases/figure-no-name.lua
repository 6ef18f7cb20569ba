-- expect: 1 "figure: name = "..." is required (it names the files)"
-- a figure without a name
local f = figure{ width = '8cm' }
