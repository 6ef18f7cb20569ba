-- expect: 1 "invalid UTF-8 at byte 1"
-- a label with invalid UTF-8
local f = figure{ name = 'z' }
f:label({0, 0}, 'P\255\254')
