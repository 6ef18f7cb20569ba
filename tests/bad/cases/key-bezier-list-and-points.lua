-- expect: 1 "bezier: give the points either as the list, bezier{ {x, y}, ... }, or as points = {...}, not both"
-- points given twice
local c = bezier{ {0, 0}, {1, 1}, points = { {0, 0}, {1, 2}, {2, 0}, {3, 1} } }
