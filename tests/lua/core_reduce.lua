-- Degree reduction in the figure language (c:reduce, s:reduce), checked
-- against values known in closed form and against identities: an elevated
-- curve comes back, the bounds are above the measured maximum, the uniform
-- method's maximum is at most the least-squares one's.  Tolerances: the
-- reductions are exact up to rounding of coordinates of size <= 4 (1e-13);
-- the uniform method stops within 1e-4 of the grid's minimax and its grid
-- leaves 0.5 % between nodes (2e-3).
local function close(a, b, tol, what)
  if math.abs(a - b) > tol * math.max(1, math.abs(a), math.abs(b)) then
    error(string.format("%s: %.17g ~= %.17g", what, a, b), 2)
  end
end

local function close_pts(P, Q, tol, what)
  assert(#P == #Q, what .. ": counts differ")
  for i = 1, #P do
    for k = 1, #P[i] do close(P[i][k], Q[i][k], tol, what) end
  end
end

-- an elevated curve comes back, for every continuity the degree allows
local c = bezier{ {0, 0}, {1, 2}, {3, 3}, {4, 0}, {2, -1} }
local e = c:elevate(3)
for k = -1, 1 do
  for _, m in ipairs{ "l2", "uniform" } do
    local r, rep = e:reduce{ by = 3, continuity = k, method = m }
    assert(r:degree() == 4)
    close_pts(r:points(), c:points(), 1e-13, "elevated back " .. m)
    assert(rep.bound < 1e-12 and rep.max_error < 1e-13)
  end
end
-- c:reduce(2) is c:reduce{ by = 2 }
close_pts(c:reduce(2):points(), c:reduce{ by = 2 }:points(), 0, "by")

-- the graph of t^2 by a line: least squares t - 1/6, minimax t - 1/8
local g = bezier{ {0, 0}, {0.5, 0}, {1, 1} }
local l, rl = g:reduce{ continuity = -1 }
close_pts(l:points(), { {0, -1 / 6}, {1, 5 / 6} }, 1e-14, "L2 line")
close(rl.l2_error, math.sqrt(1 / 180), 1e-14, "L2 error")
local u, ru = g:reduce{ continuity = -1, method = "uniform" }
close_pts(u:points(), { {0, -1 / 8}, {1, 7 / 8} }, 2e-3, "minimax line")
close(ru.max_error, 1 / 8, 2e-3, "minimax error")
-- keeping the ends: the chord, error 1/4, polygon bound 1/2
local k0, rk = g:reduce()
close_pts(k0:points(), { {0, 0}, {1, 1} }, 0, "chord")
close(rk.max_error, 0.25, 1e-12, "chord error")
close(rk.polygon_bound, 0.5, 1e-12, "chord polygon bound")

-- bounds and methods on a curve of degree 7 reduced by 3 with C^1 ends
local w = bezier{ {0, 0}, {1, 3}, {2, -1}, {3, 4}, {4, 0}, {5, 2}, {6, -2},
                  {7, 1} }
local a, ra = w:reduce{ by = 3, continuity = 1 }
local b, rb = w:reduce{ by = 3, continuity = 1, method = "uniform" }
for _, r in ipairs{ ra, rb } do
  assert(r.polygon_bound >= r.bound and r.bound >= r.max_error,
         "bounds in order")
end
assert(rb.max_error < ra.max_error, "uniform below L2")
assert(ra.l2_error <= rb.l2_error, "L2 below uniform in L2")
-- the measured maximum is the densest sample's
local dense = 0
for j = 0, 4000 do
  local p, q = w:eval(j / 4000), a:eval(j / 4000)
  dense = math.max(dense, math.sqrt((p[1] - q[1])^2 + (p[2] - q[2])^2))
end
assert(ra.max_error >= dense * (1 - 1e-12) and ra.bound >= dense)

-- B-splines: an elevated curve comes back with its knots
local s = bspline{ degree = 2, points = { {0, 0}, {1, 2}, {2, 0}, {3, 2},
                                           {4, 0} } }
local se, rs = s:elevate(1):reduce{ tolerance = 1e-9 }
assert(se:degree() == 2 and rs.continuity == 1)
close_pts(se:points(), s:points(), 1e-12, "spline back")
local K1, K2 = se:knots(), s:knots()
assert(#K1 == #K2)
for i = 1, #K1 do close(K1[i], K2[i], 1e-15, "knots") end
-- a tolerance that cannot be met names the smallest error
local ok, err = pcall(function () return s:reduce{ tolerance = 1e-6 } end)
assert(not ok and err:find("needs an error of at least", 1, true), err)
-- options go through the schema
ok, err = pcall(function () return c:reduce{ contiuity = 1 } end)
assert(not ok and err:find("did you mean 'continuity'", 1, true), err)

print("core_reduce: ok")
