-- Bernstein basis, convex hull, conics, offsets, interpolation and the
-- chapter-4 curves, checked against values worked out independently here.
local tol = 1e-12

local function close(a, b, what, t)
  t = t or tol
  if math.abs(a - b) > t * math.max(1, math.abs(a), math.abs(b)) then
    error(string.format("%s: %.17g ~= %.17g", what, a, b), 2)
  end
end

-- Bernstein: B_1^3(1/2) = 3/8; all of degree n sum to 1; derivatives
close(bernstein(3, 1, 0.5), 0.375, "B_1^3(1/2)")
local sum = 0
for _, b in ipairs(bernstein_all(7, 0.3)) do sum = sum + b end
close(sum, 1, "partition of unity")
-- d/dt B_0^2 = -2 (1 - t): at t = 0.25, -1.5
close(bernstein_all(2, 0.25, 1)[1], -1.5, "B_0^2'")
-- 1 + 2t + 3t^2 in Bernstein form of degree 2: 1, 2, 6
local b = bernstein_from_power{ 1, 2, 3 }
close(b[1], 1, "b0") close(b[2], 2, "b1") close(b[3], 6, "b2")
local a = bernstein_to_power(b)
close(a[3], 3, "round trip")
-- Bernstein approximation of f(t) = t^2 with n = 4: f_n(t) = t^2 + t(1-t)/n
local g = bernstein_approx(function(t) return t * t end, 4)
local p = g:eval(0.5)
close(p[1], 0.5, "f_n x")
close(p[2], 0.25 + 0.25 / 4, "f_n(1/2)")

-- convex hull: the square's corners, counter-clockwise from the lowest x
local h, idx = convex_hull{ {0, 0}, {1, 0.5}, {2, 0}, {2, 2}, {0, 2}, {1, 1} }
assert(#h == 4, "hull has " .. #h .. " vertices")
assert(idx[1] == 0 and idx[2] == 2 and idx[3] == 3 and idx[4] == 4,
       "hull order " .. table.concat(idx, ","))

-- conics: points on the circle, the ellipse, the parabola, the hyperbola
for _, piece in ipairs(conic.arc(1, 2, 3, 0.2, 4)) do
  for _, t in ipairs{ 0, 0.3, 0.7, 1 } do
    local q = piece:eval(t)
    close((q[1] - 1)^2 + (q[2] - 2)^2, 9, "circle")
  end
end
for _, piece in ipairs(conic.ellipse(0, 0, 3, 2, 0, 0, 2 * math.pi)) do
  local q = piece:eval(0.4)
  close(q[1]^2 / 9 + q[2]^2 / 4, 1, "ellipse")
end
for _, piece in ipairs(conic.parabola(0, 0, 0.5, math.pi / 2, -2, 2)) do
  local q = piece:eval(0.35)
  close(q[2], q[1]^2 / 2, "parabola y = x^2 / (4 f)")
end
for _, piece in ipairs(conic.hyperbola(0, 0, 2, 1, 0, -1.5, 1.5)) do
  local q = piece:eval(0.6)
  close(q[1]^2 / 4 - q[2]^2, 1, "hyperbola")
end

-- offsets: every piece's points lie at distance |d| from the curve
-- (within the requested tolerance 1e-4, checked with the curve's own
-- closest-point search)
local c = bezier{ {0, 5}, {1, -1}, {3, 0}, {4, 3}, {6, 10} }
local pieces = c:offset(0.5, { tolerance = 1e-4 })
local rep = pieces.report
assert(#pieces >= 1 and rep.max_error <= 1e-4 and rep.converged)
for _, piece in ipairs(pieces) do
  assert(piece:degree() == 3)
  for _, t in ipairs{ 0.25, 0.5, 0.75 } do
    local _, dist = c:closest(piece:eval(t))
    close(dist, 0.5, "offset distance", 2e-4)
  end
end
-- d > 0 lies left of travel: at t = 1/2 the offset point is c + d n
local q, n = c:eval(0.5), c:normal(0.5)
local o = c:offset_point(0.5, 0.5)
close(o[1], q[1] + 0.5 * n[1], "offset_point x")
close(o[2], q[2] + 0.5 * n[2], "offset_point y")

-- interpolation passes through its points; natural: C'' = 0 at the ends
local D = { {0, 0}, {1, 2}, {3, 1}, {4, 4}, {6, 3} }
for _, m in ipairs{ "natural", "not-a-knot", "catmull-rom" } do
  local s = interpolate{ points = D, method = m, param = "chord" }
  local u = parameters(D, "chord")
  for i, P in ipairs(D) do
    local x = s:eval(u[i])
    close(x[1], P[1], m .. " x", 1e-10)
    close(x[2], P[2], m .. " y", 1e-10)
  end
end
local nat = interpolate{ points = D, method = "natural" }
local d2 = nat:derivs(0, 2)[3]
assert(math.abs(d2[1]) < 1e-9 and math.abs(d2[2]) < 1e-9, "natural end")
-- Ferguson cubic: C(0) = P0, C'(0) = T0; its Bezier points P0 + T0/3
local f = ferguson({ 0, 0 }, { 3, 0 }, { 3, 3 }, { 3, -3 })
close(f:points()[2][1], 1, "ferguson B1 x")
close(f:points()[2][2], 1, "ferguson B1 y")
-- Coons cubic: B_0 = (P0 + 4 P1 + P2) / 6
local cc = coons_cubic{ {0, 0}, {6, 0}, {6, 6}, {0, 6} }
close(cc:points()[1][1], 5, "coons B0 x")
close(cc:points()[1][2], 1, "coons B0 y")

-- trimmed: the pieces, and the same pieces grouped in chains
local trimmed = c:offset(-3, { trim = true })
local n = 0
for _, chain in ipairs(trimmed.chains) do n = n + #chain end
assert(n == #trimmed and trimmed.report.trimmed_segments == n, "chains")
local t2, rep2, chains2 = c:offset(-3, { trim = true })
assert(#t2 == #trimmed and rep2.trimmed_chains == #chains2, "3 values")

print("core_more: ok")
