local c = bezier{ {0,5}, {1,-1}, {3,0}, {4,3}, {6,10} }
local l, r = c:split(0.4)
local f = figure{ name = "seed-bezier", width = "8cm", height = "6cm" }
f:curve(c):polygon(c, { labels = "P_%d" }):decasteljau(c, 0.4)
f:curve(c:elevate(2), { color = "red", dash = "dashed" })
f:label(c:eval(0.5), "C(t)", { place = "ne" })
