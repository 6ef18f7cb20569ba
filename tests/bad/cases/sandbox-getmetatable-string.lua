-- expect: 1 "'os' is not available to figure scripts"
-- changing the string metatable
local mt = getmetatable('')
mt.__index = function() return os end
local x = ('a').execute
x('touch /tmp/curvefig-escaped')
