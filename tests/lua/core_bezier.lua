-- The Bézier core names of DESIGN.md checked against values computed
-- independently in this script (Bernstein sums, the power form) or by hand.
-- Tolerances: the algorithms (de Casteljau) and the reference (Bernstein
-- sums) differ only by rounding, ~1e-15 of coordinates of size 10; 1e-12
-- leaves room for a few dozen operations.
local tol = 1e-12

local function close(a, b, what)
  if math.abs(a - b) > tol * math.max(1, math.abs(a), math.abs(b)) then
    error(string.format("%s: %.17g ~= %.17g", what, a, b), 2)
  end
end

local function close_pt(p, q, what)
  assert(#p == #q, what .. ": dimensions differ")
  for k = 1, #p do close(p[k], q[k], what .. "[" .. k .. "]") end
end

local function binom(n, k)
  local r = 1
  for j = 1, k do r = r * (n - k + j) / j end
  return r
end

-- reference evaluation: sum of B_i^n(t) w_i P_i / sum of B_i^n(t) w_i
local function ref_eval(P, W, t)
  local n, d = #P - 1, #P[1]
  local num, den = {}, 0
  for k = 1, d do num[k] = 0 end
  for i = 0, n do
    local b = binom(n, i) * t^i * (1 - t)^(n - i) * (W and W[i + 1] or 1)
    den = den + b
    for k = 1, d do num[k] = num[k] + b * P[i + 1][k] end
  end
  for k = 1, d do num[k] = num[k] / den end
  return num
end

local P = { {0, 5}, {1, -1}, {3, 0}, {4, 3}, {6, 10} }
local c = bezier(P)

-- degree, points, weights
assert(c:degree() == 4 and c:dim() == 2 and not c:is_rational())
for i, p in ipairs(c:points()) do close_pt(p, P[i], "points") end
for _, w in ipairs(c:weights()) do close(w, 1, "weights") end

-- eval: by hand, c(3/4) = (4.265625, 4.40234375) (worked out from the
-- Bernstein weights 1/256, 12/256, 54/256, 108/256, 81/256)
close_pt(c:eval(0.75), { 1092 / 256, 1127 / 256 }, "eval(3/4)")
for _, t in ipairs{ 0, 0.1, 0.25, 0.5, 0.9, 1 } do
  close_pt(c:eval(t), ref_eval(P, nil, t), "eval(" .. t .. ")")
end
local many = c:eval{ 0.2, 0.7 }
close_pt(many[2], ref_eval(P, nil, 0.7), "eval{...}")

-- decasteljau: levels n+1, n, ..., 1; level j point i is the Bézier of
-- P_i..P_{i+j} at t (a property independent of the algorithm)
local lv = c:decasteljau(0.75)
assert(#lv == 5)
for j = 0, 4 do
  assert(#lv[j + 1] == 5 - j)
  for i = 0, 4 - j do
    local sub = {}
    for k = i, i + j do sub[#sub + 1] = P[k + 1] end
    close_pt(lv[j + 1][i + 1], ref_eval(sub, nil, 0.75), "decasteljau")
  end
end

-- split: left(s) = c(t s), right(s) = c(t + (1 - t) s); the receiver is
-- unchanged
local L, R = c:split(0.3)
for _, s in ipairs{ 0, 0.2, 0.5, 1 } do
  close_pt(L:eval(s), ref_eval(P, nil, 0.3 * s), "split left")
  close_pt(R:eval(s), ref_eval(P, nil, 0.3 + 0.7 * s), "split right")
end
for i, p in ipairs(c:points()) do close_pt(p, P[i], "receiver after split") end
close_pt(L:points()[1], P[1], "left starts at P_0")
close_pt(R:points()[5], P[5], "right ends at P_4")

-- elevate: degree + r, the same curve
local E = c:elevate(2)
assert(E:degree() == 6 and c:degree() == 4)
for _, t in ipairs{ 0.1, 0.4, 0.8 } do
  close_pt(E:eval(t), ref_eval(P, nil, t), "elevate")
end
-- first elevated point by hand: P_0, then (1/5) P_0 + (4/5) P_1 for r = 1
close_pt(c:elevate(1):points()[2], { 0.8, 0.2 }, "elevate by hand")

-- derivative: Q_i = n (P_{i+1} - P_i); c'(0) = 4 (P_1 - P_0) = (4, -24)
local D = c:derivative()
assert(D:degree() == 3)
close_pt(D:eval(0), { 4, -24 }, "derivative(0)")
close_pt(D:points()[4], { 8, 28 }, "hodograph Q_3")
close_pt(c:derivative(2):eval(0), { 12 * (3 - 2 + 0), 12 * (0 + 2 + 5) },
         "second derivative") -- 12 (P_2 - 2 P_1 + P_0)
-- compare with a central difference at t = 0.4 (h = 1e-5: error ~1e-9)
local h = 1e-5
local a, b = ref_eval(P, nil, 0.4 - h), ref_eval(P, nil, 0.4 + h)
local d = D:eval(0.4)
for k = 1, 2 do
  assert(math.abs(d[k] - (b[k] - a[k]) / (2 * h)) < 1e-6, "derivative fd")
end

-- rational: quarter circle, weights 1, sqrt(2)/2, 1: |r(t)| = 1
local W = { 1, math.sqrt(2) / 2, 1 }
local r = bezier{ points = { {1, 0}, {1, 1}, {0, 1} }, weights = W }
assert(r:is_rational())
for _, t in ipairs{ 0, 0.3, 0.5, 0.77, 1 } do
  local q = r:eval(t)
  close(q[1]^2 + q[2]^2, 1, "circle radius")
  close_pt(q, ref_eval(r:points(), W, t), "rational eval")
end
close_pt(r:points()[2], { 1, 1 }, "rational points are Cartesian")
close(r:weights()[2], W[2], "rational weights")
-- rational derivative: a rational curve of higher degree, tangent to the
-- circle (q . q' = 0) and equal to a central difference
local rd = r:derivative()
assert(rd:is_rational() and rd:degree() > r:degree())
for _, t in ipairs{ 0.2, 0.5, 0.9 } do
  local q, dq = r:eval(t), rd:eval(t)
  assert(math.abs(q[1] * dq[1] + q[2] * dq[2]) < 1e-12, "tangent to circle")
  local qa, qb = ref_eval(r:points(), W, t - h), ref_eval(r:points(), W, t + h)
  assert(math.abs(dq[1] - (qb[1] - qa[1]) / (2 * h)) < 1e-6, "rational fd")
end
-- split and elevate of a rational curve keep it on the circle
local rl = r:split(0.5)
local q = rl:eval(0.5)
close(q[1]^2 + q[2]^2, 1, "rational split")
q = r:elevate(3):eval(0.6)
close(q[1]^2 + q[2]^2, 1, "rational elevate")

-- R^3 and R^1
local c3 = bezier{ {0, 0, 0}, {1, 2, 3}, {2, 0, 1} }
close_pt(c3:eval(0.5), { 1, 1, 1.75 }, "eval in R^3")
local c1 = bezier{ {0}, {1}, {0} }
close_pt(c1:eval(0.5), { 0.5 }, "eval in R^1")

print("core_bezier: ok")
