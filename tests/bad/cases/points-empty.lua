-- expect: 1 "bezier: 0 points given, at least 1 needed"
-- a Bezier curve without points
local c = bezier{}
