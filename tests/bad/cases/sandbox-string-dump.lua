-- expect: 1 "string has no field 'dump'"
-- string.dump
local d = string.dump(function() end)
