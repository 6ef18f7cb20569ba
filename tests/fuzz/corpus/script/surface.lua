local P = { { {0,0,0}, {1,0,1}, {2,0,0} }, { {0,1,1}, {1,1,2}, {2,1,1} }, { {0,2,0}, {1,2,1}, {2,2,0} } }
local s = bezier_surface{ points = P, weights = { {1,2,1}, {1,1,1}, {2,1,1} } }
local b = bspline_surface{ degree = {2, 1}, knots = { {0,0,0,1,1,1}, {0,0,0.5,1,1} }, points = P }
local lo, hi = s:split("u", 0.4)
local k = b:insert_knot("v", 0.25, 1):elevate(1, 1)
local sp = nurbs_sphere{ center = {0, 0, 0}, r = 1 }
local r = revolve(bezier{ {1,0,0}, {2,0,1}, {1,0,2} }, { axis = {0, 0, 1}, from = 0, to = 3 })
local I = interpolate_surface{ points = P, method = "natural" }
local D = s:derivs(0.3, 0.7, 2)
local K, H = sp:curvature(0.2, 0.6)
local net = b:deboor(0.5, 0.5)
local T = k:to_bezier()
local f = figure{ name = "seed-surface" }
f:curve(s:iso("u", 0.3)):curve(b:iso("v", 0.6)):curve(sp:iso("u", 0.1))
f:curve(r:iso("v", 0.5)):curve(I:iso("u", 0.5)):curve(hi:iso("v", 0.2))
f:points(s:eval{ {0.1, 0.2}, {0.5, 0.5} })
