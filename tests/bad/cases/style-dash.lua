-- expect: 1 "curve: dash "wiggly" is unknown; the names are "solid", "dashed", "dotted" or "dashdot", or {on, off, ...} in bp"
-- an unknown dash
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} }, { dash = 'wiggly' })
