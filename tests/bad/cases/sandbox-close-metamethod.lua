-- expect: 1 "closing"
-- an error inside a __close metamethod
do local x <close> = setmetatable({}, { __close = function() error('closing') end }) end
