-- expect: 1 "reduce: method "minimax" is unknown; the names are "l2" or "uniform""
-- a reduction method that does not exist
local c = bezier{{0,0},{1,2},{2,0},{3,2}}
local r = c:reduce{ method = "minimax" }
