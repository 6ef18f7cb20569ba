-- expect: 1 "figure: view angle 1 is string, not a number"
-- a view with a string
local f = figure{ name = 'z', view = {'up', 30} }
