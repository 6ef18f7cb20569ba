-- The B-spline core names of DESIGN.md checked against an independent
-- Cox-de Boor recursion written here, and against values worked out by
-- hand.  Tolerance 1e-12: the library (de Boor, triangular basis) and the
-- recursion differ by rounding only.
local tol = 1e-12

local function close(a, b, what)
  if math.abs(a - b) > tol * math.max(1, math.abs(a), math.abs(b)) then
    error(string.format("%s: %.17g ~= %.17g", what, a, b), 2)
  end
end

local function close_pt(p, q, what)
  for k = 1, #q do close(p[k], q[k], what .. "[" .. k .. "]") end
end

-- N_i^p(u) by the Cox-de Boor recursion (U 1-based: U[i + 1] = u_i);
-- right-continuous, left limit at the last knot
local function N(U, i, p, u)
  if p == 0 then
    local a, b = U[i + 1], U[i + 2]
    if u >= a and u < b then return 1 end
    if u == U[#U] and b == U[#U] and a < b then return 1 end
    return 0
  end
  local r = 0
  local d1 = U[i + p + 1] - U[i + 1]
  if d1 > 0 then r = r + (u - U[i + 1]) / d1 * N(U, i, p - 1, u) end
  local d2 = U[i + p + 2] - U[i + 2]
  if d2 > 0 then r = r + (U[i + p + 2] - u) / d2 * N(U, i + 1, p - 1, u) end
  return r
end

local function ref_eval(P, U, p, u, W)
  local num, den = {}, 0
  for k = 1, #P[1] do num[k] = 0 end
  for i = 0, #P - 1 do
    local b = N(U, i, p, u) * (W and W[i + 1] or 1)
    den = den + b
    for k = 1, #P[1] do num[k] = num[k] + b * P[i + 1][k] end
  end
  for k = 1, #num do num[k] = num[k] / den end
  return num
end

-- the thesis' sample curve
local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local s = bspline{ degree = 2, knots = U, points = P }

assert(s:degree() == 2 and s:count() == 8 and s:dim() == 2)
for i, k in ipairs(s:knots()) do close(k, U[i], "knots") end
for i, p in ipairs(s:points()) do close_pt(p, P[i], "points") end
for _, w in ipairs(s:weights()) do close(w, 1, "weights") end

-- eval against Cox-de Boor; clamped ends at P_0, P_7
for _, u in ipairs{ 0, 0.1, 0.17, 0.3, 0.5, 0.6, 0.9, 1 } do
  close_pt(s:eval(u), ref_eval(P, U, 2, u), "eval(" .. u .. ")")
end
close_pt(s:eval(0), P[1], "starts at P_0")
close_pt(s:eval(1), P[8], "ends at P_7")
-- by hand at u = 0.5 (a knot, span [0.5, 0.67)): N_3 = (0.67-0.5)/(0.67-0.33)
-- = 0.5, N_4 = 0.5, so C = (P_3 + P_4)/2 = (3.5, 3.5)
close_pt(s:eval(0.5), { 3.5, 3.5 }, "eval by hand")

-- basis functions
close(basis(U, 3, 2, 0.5), 0.5, "basis N_3^2(0.5)")
close(basis({ 0, 1, 3, 6, 10 }, 0, 3, 2), N({ 0, 1, 3, 6, 10 }, 0, 3, 2),
      "basis on a short vector")
local first, Ns = s:basis(0.6)
local sum = 0
for j, v in ipairs(Ns) do
  close(v, N(U, first + j - 1, 2, 0.6), "s:basis")
  sum = sum + v
end
close(sum, 1, "partition of unity")

-- insert_knot: same curve, one more point and knot; Boehm by hand for
-- u = 0.6 in span k = 5 ([0.5, 0.67)): Q_i = (1 - a_i) P_{i-1} + a_i P_i,
-- a_i = (u - u_i) / (u_{i+p} - u_i), i = 4, 5
local t, info = s:insert_knot(0.6, 1)
assert(t:count() == 9 and #t:knots() == 12 and s:count() == 8)
assert(info.span == 5 and info.multiplicity == 0 and info.times == 1)
for _, u in ipairs{ 0.05, 0.4, 0.6, 0.61, 0.95 } do
  close_pt(t:eval(u), s:eval(u), "insert_knot keeps the curve")
end
local function lerp(A, B, a) return { (1 - a) * A[1] + a * B[1], (1 - a) * A[2] + a * B[2] } end
local a4 = (0.6 - U[5]) / (U[7] - U[5])
local a5 = (0.6 - U[6]) / (U[8] - U[6])
close_pt(t:points()[5], lerp(P[4], P[5], a4), "Q_4 by hand")
close_pt(t:points()[6], lerp(P[5], P[6], a5), "Q_5 by hand")
local t2 = s:insert_knot(0.5, 1) -- into an existing knot: double knot
local count = 0
for _, k in ipairs(t2:knots()) do if k == 0.5 then count = count + 1 end end
assert(count == 2, "double knot")

-- deboor: level 0 = P_{k-p}..P_k, last level = C(u)
local lv, span, mult = s:deboor(0.6)
assert(#lv == 3 and span == 5 and mult == 0)
close_pt(lv[1][1], P[4], "de Boor level 0")
close_pt(lv[3][1], s:eval(0.6), "de Boor point")
close_pt(lv[2][1], t:points()[5], "de Boor level 1 = inserted points")

-- to_beziers: one piece per span, each reproducing its part of the curve
-- the spans of the domain: [0, 0.17], [0.17, 0.33], ..., [0.83, 1]
local breaks = { 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1 }
local pieces = s:to_beziers()
assert(#pieces == 6)
for i, b in ipairs(pieces) do
  assert(b:degree() == 2)
  local a0, a1 = breaks[i], breaks[i + 1]
  for _, x in ipairs{ 0, 0.3, 1 } do
    close_pt(b:eval(x), s:eval(a0 + x * (a1 - a0)), "to_beziers piece")
  end
end

-- derivative: degree p - 1; against a central difference
local D = s:derivative()
assert(D:degree() == 1)
local h = 1e-6
local pa, pb = s:eval(0.4 - h), s:eval(0.4 + h)
local d = D:eval(0.4)
for k = 1, 2 do assert(math.abs(d[k] - (pb[k] - pa[k]) / (2 * h)) < 1e-6) end

-- elevate: same curve, degree 3
local E = s:elevate(1)
assert(E:degree() == 3)
for _, u in ipairs{ 0.1, 0.55, 0.9 } do close_pt(E:eval(u), s:eval(u), "elevate") end

-- NURBS: the full circle of radius 2 around (1, 1)
local circ = nurbs_circle({ 1, 1 }, 2)
assert(circ:is_rational())
for _, u in ipairs{ 0, 0.1, 0.33, 0.5, 0.8 } do
  local q = circ:eval(u)
  close((q[1] - 1)^2 + (q[2] - 1)^2, 4, "circle")
end
-- NURBS with weights against the reference
local W = { 1, 2, 1, 0.5, 1, 3, 1, 1 }
local nb = bspline{ degree = 2, knots = U, points = P, weights = W }
for _, u in ipairs{ 0.2, 0.5, 0.7 } do
  close_pt(nb:eval(u), ref_eval(P, U, 2, u, W), "nurbs eval")
end
-- all weights 1: the NURBS equals the B-spline
local n1 = bspline{ degree = 2, knots = U, points = P, weights = { 1, 1, 1, 1, 1, 1, 1, 1 } }
close_pt(n1:eval(0.37), s:eval(0.37), "unit weights")

-- generated knots
local kc = knots.clamped(2, 8)
assert(#kc == 11 and kc[1] == 0 and kc[3] == 0 and kc[11] == 1)
local cl = bspline{ degree = 3, points = P, kind = "closed" }
close_pt(cl:eval(0), cl:eval(1), "closed curve")

print("core_bspline: ok")
