-- expect: 1 "curve: dash "wiggly": use "solid", "dashed", "dotted", "dashdot" or"
-- an unknown dash
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} }, { dash = 'wiggly' })
