-- expect: 1 "deboor: u = -0.5 is outside the domain"
-- de Boor outside the domain
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
local l = s:deboor(-0.5)
