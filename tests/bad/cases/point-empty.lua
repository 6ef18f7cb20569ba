-- expect: 1 "bezier: point 1 has no coordinates"
-- a point with no coordinates
local c = bezier{ {}, {} }
