-- expect: 1 "bspline_surface: knots U: 7 knots given, degree 2 with 5 points needs 8"
-- a knot vector that does not match the degree and the grid
local P = {}
for i = 1, 5 do
  P[i] = {}
  for j = 1, 3 do P[i][j] = { i, j, 0 } end
end
local s = bspline_surface{ degree = { 2, 2 }, points = P,
  knots = { { 0, 0, 0, 0.5, 1, 1, 1 }, { 0, 0, 0, 1, 1, 1 } } }
