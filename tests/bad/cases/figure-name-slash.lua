-- expect: 1 "figure: name "../escape" must be 1 to 100 characters and not start"
-- a figure name with a slash
local f = figure{ name = '../escape' }
