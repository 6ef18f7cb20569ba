-- expect: 1 "curve: color: unknown colour "#12345" (use #rrggbb, #rrggbbaa, none"
-- a malformed hex colour
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} }, { color = '#12345' })
