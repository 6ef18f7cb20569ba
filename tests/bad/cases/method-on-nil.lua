-- expect: 1 "eval: call a method with ':' (c:eval(...)), not '.'"
-- a method called on the wrong receiver
local c = bezier{{0,0},{1,2},{2,0},{3,2},{4,0}}
local p = c.eval(5, 0.5)
