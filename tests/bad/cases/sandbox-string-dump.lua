-- expect: 1 "attempt to call a nil value (field 'dump')"
-- string.dump
local d = string.dump(function() end)
