-- expect: 1 "unexpected symbol near '='"
-- a syntax error
local x = = 1
