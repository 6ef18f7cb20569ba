-- expect: 1 "offset: offset tolerance 0 must be finite and positive"
-- offset with tolerance 0
local c = bezier{{0,0},{1,2},{2,0},{3,2},{4,0}}
local l = c:offset(0.1, { tolerance = 0 })
