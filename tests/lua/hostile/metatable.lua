-- must stop: the curve metatables are locked (no way to call __gc twice)
local c = bezier{ {0, 0}, {1, 1} }
local mt = getmetatable(c)
assert(type(mt) == "table", "metatable is " .. tostring(mt))
mt.__gc(c)
