-- a bad argument in a nested call: the message names line 5, and the
-- frames that led there (lines 8 and 11)
local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local function make()
  return bspline{ degree = 2, knots = { 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1 }, points = P }
end
local function draw()
  local s = make()
  return s
end
draw()
