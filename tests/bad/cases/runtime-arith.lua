-- expect: 1 "attempt to perform arithmetic on a table value"
-- arithmetic on a table
local x = {} + 1
