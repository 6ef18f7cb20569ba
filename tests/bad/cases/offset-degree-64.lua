-- expect: 1 "offset: the curve has degree 64; offsets are made of curves of degree at most 24"
-- the offset of a degree-64 curve (minutes for degree 1024)
local pts = {}
for i = 0, 64 do pts[#pts + 1] = { i, math.sin(i) } end
figure{ name = "o" }:curve(bezier(pts):offset(0.1))
