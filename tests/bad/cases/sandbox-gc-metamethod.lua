-- expect: 1 "instruction limit"
-- an endless loop inside a __gc metamethod
-- args: --max-instructions 1000000 --timeout 10
setmetatable({}, { __gc = function() while true do end end })
collectgarbage()
collectgarbage()
