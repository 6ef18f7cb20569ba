-- expect: 1 "nurbs_circle: radius 0 must be positive"
-- a circle of radius 0
local s = nurbs_circle({0, 0}, 0)
