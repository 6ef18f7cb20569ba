-- expect: 1 "points: marker: unknown marker "heart" (use none, dot, circle,"
-- an unknown marker
local f = figure{ name = 'z' }
f:points({ {0, 0} }, { marker = 'heart' })
