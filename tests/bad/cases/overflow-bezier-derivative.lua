-- expect: 1 "overflow"
-- a Bezier derivative whose points overflow (1.7e308 apart)
local c = bezier{ {-1.7e308, 0}, {1.7e308, 0} }
local d = c:derivative()
