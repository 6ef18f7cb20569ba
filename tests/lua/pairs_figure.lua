-- Points and their labels added in a pairs loop, close together so that
-- each label's place depends on those placed before it; the fill of A
-- under the others (tests/lua/test_tool.c: the same SVG at every run).
local f = figure{ name = "pairs-figure", width = "4cm", height = "3cm",
                  window = { -0.5, 1.5, -0.5, 1.5 } }
local pts = { A = { 0, 0 }, B = { 0.05, 0.05 }, C = { 0.1, 0 },
              D = { 0.05, -0.05 }, E = { 0.6, 0.6 }, F = { 0.65, 0.6 } }
for name, p in pairs(pts) do
  f:points({ p }, { labels = name, color = name == "A" and "red" or "blue",
                    marker_size = 6 })
end
