-- expect: 1 "nested"
-- an error value that is a table with a failing __tostring
error(setmetatable({}, { __tostring = function() error('nested') end }))
