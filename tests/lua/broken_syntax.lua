-- a syntax error on line 4
local c = bezier{ {0, 0}, {1, 1} }

local x = = 3
