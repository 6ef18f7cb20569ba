-- expect: 1 "conic.circle: radius is -1; it must be positive"
-- conic.circle with a negative radius
local l = conic.circle(0, 0, -1)
