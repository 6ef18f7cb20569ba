-- expect: 1 "coons: ends must be a string, got table"
-- an enumerated option of the wrong type names the option
local s = coons{ points = { {0, 0}, {1, 1}, {2, 0} }, ends = { 'plain' } }
