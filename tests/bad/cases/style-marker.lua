-- expect: 1 "points: marker "heart" is unknown; the names are "none", "dot""
-- an unknown marker
local f = figure{ name = 'z' }
f:points({ {0, 0} }, { marker = 'heart' })
