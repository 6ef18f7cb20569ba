-- expect: 1 "figure: name "" must be 1 to 100 characters and not start with '.'"
-- an empty figure name
local f = figure{ name = '' }
