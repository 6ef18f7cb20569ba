-- expect: 1 "offset: offset tolerance 0.001 is below what doubles resolve"
-- an offset at a distance so large that the default tolerance is finer
-- than doubles resolve there (it used to run forever)
local c = bezier{{0,0},{1,2},{2,0},{3,2},{4,0}}
local l = c:offset(1e14)
