-- every curve method and library function once, one call a line, small
-- and fast: the seeds of degenerate values (gen-degenerate.py) set each
-- line's numbers to an edge value in turn
local c = bezier{ {0, 0}, {1, 2}, {3, 2}, {4, 0} }
local r = bezier{ {0, 0}, {1, 1}, {2, 0}, weights = {1, 3, 1} }
local p = c:eval(0.3)
local q = c:eval{0, 0.5, 1}
local d = c:derivs(0.2, 2)
local tg, nm, k = c:tangent(0.4), c:normal(0.4), c:curvature(0.4)
local h = c:derivative(1)
local a, b = c:split(0.6)
local g = c:segment(0.2, 0.7):reverse():transform({{1, 0}, {0, 1}}, {1, 1})
local e, m = c:elevate(2), c:reduce()
local L = c:decasteljau(0.25)
local lo, hi = c:bbox()
local len = c:length(1e-6)
local tc, dc = c:closest({2, 3})
local fl = c:flatten(0.01)
local cu = c:to_cubics(0.01)
local o = c:offset(0.5, { tolerance = 1e-3, trim = true })
local op = c:offset_point(0.5, 0.25)
local oc = r:offset_cusps(0.8)
local s = bspline{ degree = 3, points = { {0, 0}, {1, 2}, {2, 0}, {3, 2}, {4, 0} } }
local s1 = s:insert_knot(0.5, 2)
local s2 = s:refine{0.25, 0.75}
local s3, times = s1:remove_knot(0.5, 1, 1e-9)
local D = s:deboor(0.4)
local bz = s:to_beziers()
local sa, sb = s:split(0.3)
local sg = s:segment(0.1, 0.9):elevate(1):reverse():transform({{2, 0}, {0, 1}}, {0, 0})
local sm = s:move_point(2, {0.5, 0.5})
local su0, su1 = s:support(1)
local af, alo, ahi = s:active_points(0.6)
local bf, bv = s:basis(0.6)
local so = s:offset(-0.2)
local N = basis({0, 0, 0, 0.5, 1, 1, 1}, 1, 2, 0.3)
local Nk = basis({0, 0, 0, 0.5, 1, 1, 1}, 1, 2, 0.3, 2)
local bk, bfs = basis_funs({0, 0, 0, 0.5, 1, 1, 1}, 2, 0.7)
local U1, U2 = knots.uniform(2, 5, 0, 1), knots.clamped(3, 6, 0, 2)
local U3, kc = knots.averaged(2, {0, 0.3, 0.6, 1}), knots.count(2, 4)
local ok = knots.validate(2, 4, {0, 0, 0, 0.5, 1, 1, 1})
local ka, kb = knots.domain(2, {0, 0, 0, 0.5, 1, 1, 1})
local B1, B2 = bernstein(3, 1, 0.4), bernstein_all(3, 0.4, 1)
local ba = bernstein_approx(function(t) return t * t end, 4)
local bp, pb = bernstein_from_power({1, 2, 3}), bernstein_to_power({1, 0, 1})
local bm, pm = bernstein_matrix(3), power_matrix(3)
local hull, idx = convex_hull({ {0, 0}, {2, 0}, {1, 1}, {1, 3} })
local ca, cc = conic.arc(0, 0, 1, 0, math.pi / 2), conic.circle(0, 0, 2)
local ce = conic.ellipse(0, 0, 3, 1, 0.2, 0, math.pi)
local cp = conic.parabola(0, 0, 0.5, math.pi / 2, -1, 1)
local ch = conic.hyperbola(0, 0, 1, 1, 0, -1, 1)
local ni = interpolate{ points = { {0, 0}, {1, 2}, {2, 1}, {3, 3} }, method = "natural" }
local ap = approximate{ points = { {0, 0}, {1, 2}, {2, 1}, {3, 3}, {4, 0} }, count = 4, degree = 2 }
local par = parameters({ {0, 0}, {1, 2}, {2, 1} }, "chord", false)
local fe = ferguson({0, 0}, {2, 0}, {1, 2}, {1, -2})
local fc = ferguson_chain({ {0, 0}, {1, 1}, {2, 0} }, { {1, 1}, {1, 0}, {1, -1} })
local cq = coons_cubic{ {0, 0}, {1, 2}, {2, 2}, {3, 0} }
local cn = coons_chain{ points = { {0, 0}, {1, 2}, {2, 2}, {3, 0}, {4, 1} }, ends = "tripled" }
local co = coons{ points = { {0, 0}, {1, 2}, {2, 2}, {3, 0} }, ends = "plain" }
local nc, na = nurbs_circle({0, 0}, 2), nurbs_arc{ center = {0, 0}, x = {1, 0}, y = {0, 1}, r = 1, from = 0, to = 2 }
local f = figure{ name = "lib", width = "4cm", height = "3cm" }
f:curve(c):curve(o):curve(so):curve(nc):curve(ca)
