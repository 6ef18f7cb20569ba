-- A zoom inset: a region of the data window drawn again, magnified, in a
-- framed box where nothing is drawn (at = "ne" or {x, y, w, h} in page
-- units places it), joined to the region's frame by two lines.
local f = figure{ name = "example-inset", width = "13cm", height = "6cm",
                  caption = "A cubic with a cusp: the neighbourhood of " ..
                            "the cusp magnified three times" }
local c = bezier{ {0, 0}, {4, 3}, {0, 3}, {4, 0} }
f:polygon(c)
f:curve(c, { legend = "$c(t)$, a cusp at $t = 1/2$" })
f:points({ c:eval(0.5) }, { marker = "dot" })
f:inset{ region = { 1.7, 2.0, 2.3, 2.5 }, scale = 3 }
