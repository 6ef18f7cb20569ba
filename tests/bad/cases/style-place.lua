-- expect: 1 "label: place: unknown label place "up" (use center, n, ne, e, se, s,"
-- an unknown label place
local f = figure{ name = 'z' }
f:label({0, 0}, 'P', { place = 'up' })
