-- expect: 1 "nurbs_circle: radius is "
-- a circle of radius NaN
local s = nurbs_circle({0, 0}, 0/0)
