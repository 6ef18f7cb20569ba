-- expect: 1 "bezier_surface: row 3 has 2 points, row 1 has 3"
-- a ragged grid of control points is named by its row
local s = bezier_surface{ points = {
  { {0, 0, 0}, {1, 0, 0}, {2, 0, 0} },
  { {0, 1, 0}, {1, 1, 1}, {2, 1, 0} },
  { {0, 2, 0}, {1, 2, 0} },
} }
