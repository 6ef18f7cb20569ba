-- expect: 1 "bezier_triangle: degree 2 needs 6 points ((n + 1)(n + 2) / 2), got 5"
-- a triangular patch with the wrong number of control points
local t = bezier_triangle{ degree = 2, points = { {0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1} } }
