-- expect: 1 "bezier: point 0 has no coordinates"
-- a point with no coordinates
local c = bezier{ {}, {} }
