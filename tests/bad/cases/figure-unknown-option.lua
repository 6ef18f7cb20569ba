-- expect: 1 "figure: unknown option 'colour'"
-- an unknown figure option
local f = figure{ name = 'z', colour = 'red' }
