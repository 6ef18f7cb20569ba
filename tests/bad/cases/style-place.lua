-- expect: 1 "label: place "up" is unknown; the names are "center""
-- an unknown label place
local f = figure{ name = 'z' }
f:label({0, 0}, 'P', { place = 'up' })
