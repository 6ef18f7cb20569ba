-- expect: 1 "coons: ends is a name, e.g. "plain", not a number"
-- an enumerated option given a number
local s = coons{ points = { {0, 0}, {1, 1}, {2, 0} }, ends = 3 }
