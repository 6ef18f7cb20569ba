-- expect: 1 "reduce: unknown option 'contnuity' (did you mean 'continuity'?)"
-- a misspelt reduce option
local c = bezier{{0,0},{1,2},{2,0},{3,2}}
local r = c:reduce{ contnuity = 1 }
