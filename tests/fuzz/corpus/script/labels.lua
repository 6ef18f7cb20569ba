-- labels and what places them, one number a line: the seeds of degenerate
-- values (gen-degenerate.py) put 0, 1, -1, 1e300 and NaN into each alone
-- (an offset of 1e300 crashed the label placement: docs/robustness.md)
local f = figure{ name = "l", width = "4cm", height = "3cm",
                  window = { 0, 1, 0, 1 } }
f:polyline({ {0, 0}, {1, 1} }, { width = 2 })
local o = {
  offset = 4,
  halo = 1,
  font_size = 9,
  opacity = 0.5,
}
local x =
  0.5
local y =
  0.25
f:label({ x, y }, "P_1", o)
f:label({ 0.2, 0.8 }, "Q", { place = "ne", offset = o.offset })
f:label({ 1.2, 0.5 }, "R", { place = "e" })
f:points({ {0.3, 0.3}, {0.7, 0.2} }, { labels = "A_%d", label_place = "s" })
f:arrow({ 0.1, 0.1 }, { 0.2, 0 }, { label = "v" })
f:polyline({ {0, 1}, {1, 0} }, { legend = "a line" })
