-- what the layout places around the drawing, one number a line: insets,
-- legends, panels, plot axes and ticks, margins and page sizes (the seeds
-- of degenerate values put 0, 1, -1, 1e300 and NaN into each alone)
local c = bezier{ {0, 0}, {1, 2}, {2, 0} }
local f = figure{ name = "lay", width = "5cm", height = "4cm",
                  margin = "3bp",
                  window = { -0.5, 2.5, -0.5, 2.5 } }
f:curve(c, { legend = "$c(t)$" })
f:polygon(c, { legend = "polygon" })
f:legend{ place = "se", frame = false }
local r = {
  0.8,
  0.8,
  1.2,
  1.2,
}
f:inset{ region = r, at = "ne",
         scale =
           3 }
f:inset{ region = { 0, 0, 0.3, 0.3 }, at = "sw", size = "1cm" }
local g = figure{ name = "plt", width = "6cm", height = "4cm" }
local a, b = g:panels{ rows = 2, cols = 1, share_x = true }
a:plot{ x = { 0,
              10 }, y = { 0,
                          1 },
        xticks =
          2.5,
        knots = { 0, 0.5,
                  1 }, knot_labels = "u_%d" }
a:func(math.sin,
       0,
       10)
b:bernstein(3,
            1)
