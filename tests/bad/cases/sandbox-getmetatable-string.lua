-- expect: 1 "attempt to call a nil value (local 'x')"
-- changing the string metatable
local mt = getmetatable('')
mt.__index = function() return os end
local x = ('a').execute
x('touch /tmp/curvefig-escaped')
