-- expect: 1 "bspline_surface: point P[2][2] has coordinate 3 = NaN; coordinates must be finite"
-- a NaN coordinate is named by row and column
local P = {}
for i = 1, 4 do
  P[i] = {}
  for j = 1, 4 do P[i][j] = { i, j, 0 } end
end
P[2][2][3] = 0 / 0
local s = bspline_surface{ degree = 2, points = P }
