-- regions in space, one number a line: the seeds of degenerate values
-- (gen-degenerate.py) put 0, 1, -1, 1e300 and NaN into each alone.  A
-- fill that crosses itself (a bow tie), points in one plane, repeated
-- points, a hull of points on a grid (faces in one plane), a star.
local f = figure{ name = "r", width = "5cm", height = "4cm",
                  view = { 30, 20 } }
local a =
  2
local z =
  0.3
local n =
  40
f:fill({ {0, 0, 0}, {a, a, z}, {a, 0, z}, {0, a, 0} },
       { fill = "#d04040", opacity = 0.6 })
local g = {}
for i = 0, 2 do for j = 0, 2 do for k = 0, 2 do
  g[#g + 1] = { i * a / 2, j * a / 2, k * z }
end end end
g[#g + 1] = g[1]
f:hull(g, { hidden = "remove" })
local s = {}
for i = 1, n do
  local t = 2 * math.pi * i / n
  local r = 1 + 0.3 * math.sin(5 * t)
  s[i] = { r * math.cos(t), r * math.sin(t), z * math.sin(3 * t) }
end
f:fill(s, { fill = "#4060d0" })
f:hull({ {0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, z} })
