-- expect: 1 "reduce: continuity 1 cannot be kept at both ends of a curve of degree 2 (reducing 4 by 2): k must be -1 .. 0"
-- C^1 at both ends needs 4 points, degree 2 has 3
local c = bezier{{0,0},{1,2},{2,0},{3,2},{4,0}}
local r = c:reduce{ by = 2, continuity = 1 }
