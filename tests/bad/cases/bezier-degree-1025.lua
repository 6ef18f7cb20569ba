-- expect: 1 "1025"
-- Bezier curve with 1026 points (degree above 1024)
local p = {}
for i = 1, 1026 do p[i] = {i, (i % 7)} end
local c = bezier(p)
