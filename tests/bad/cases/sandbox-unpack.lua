-- expect: 1 "too many results to unpack"
-- table.unpack of 1e8 values
local t = table.unpack({}, 1, 1e8)
