-- expect: 1 "bezier_surface: weight W[2][1] is -1; weights must be finite and positive"
-- a weight <= 0 is named by row and column
local s = bezier_surface{
  points = { { {0, 0, 0}, {1, 0, 0} }, { {0, 1, 0}, {1, 1, 1} } },
  weights = { { 1, 1 }, { -1, 1 } },
}
