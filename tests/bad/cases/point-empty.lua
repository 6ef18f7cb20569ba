-- expect: 1 "bezier: point P_0 has no coordinates"
-- a point with no coordinates
local c = bezier{ {}, {} }
