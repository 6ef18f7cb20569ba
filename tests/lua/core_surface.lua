-- Surfaces in the figure language, checked against sums written here
-- (Bernstein and Cox-de Boor in Lua) and against their curves.  Tolerance
-- 1e-12 relative: the library and these sums differ by rounding only.
local tol = 1e-12

local function close(a, b, what)
  if math.abs(a - b) > tol * math.max(1, math.abs(a), math.abs(b)) then
    error(string.format("%s: %.17g ~= %.17g", what, a, b), 2)
  end
end

local function close_pt(p, q, what)
  assert(#p == #q, what .. ": dimensions differ")
  for k = 1, #q do close(p[k], q[k], what .. "[" .. k .. "]") end
end

local function binom(n, k)
  local r = 1
  for i = 1, k do r = r * (n - k + i) / i end
  return r
end

local function B(n, i, t) return binom(n, i) * t ^ i * (1 - t) ^ (n - i) end

-- S(u, v) = sum B_i^m(u) B_j^n(v) w_ij P_ij / sum B B w
local function ref_bezier(P, W, u, v)
  local m, n, num, den = #P - 1, #P[1] - 1, { 0, 0, 0 }, 0
  for i = 0, m do
    for j = 0, n do
      local b = B(m, i, u) * B(n, j, v) * (W and W[i + 1][j + 1] or 1)
      den = den + b
      for k = 1, 3 do num[k] = num[k] + b * P[i + 1][j + 1][k] end
    end
  end
  return { num[1] / den, num[2] / den, num[3] / den }
end

local P = {
  { { 0, 0, 0 }, { 1, 0, 1 }, { 2, 0, 0 }, { 3, 0, 0.5 } },
  { { 0, 1, 1 }, { 1, 1, 2 }, { 2, 1, 1 }, { 3, 1, 0 } },
  { { 0, 2, 0 }, { 1, 2, 1 }, { 2, 2, 2 }, { 3, 2, 1 } },
}
local W = { { 1, 2, 1, 1 }, { 0.5, 1, 3, 1 }, { 1, 1, 1, 2 } }

local s = bezier_surface{ points = P }
local r = bezier_surface{ points = P, weights = W }
assert(tostring(s) == "bezier surface of degrees (2, 3) in R^3", tostring(s))
assert(tostring(r):find("^rational bezier surface"))
local p, q = s:degree()
assert(p == 2 and q == 3)
for _, uv in ipairs{ { 0, 0 }, { 0.3, 0.7 }, { 1, 0.25 }, { 0.5, 1 } } do
  local u, v = uv[1], uv[2]
  close_pt(s:eval(u, v), ref_bezier(P, nil, u, v), "bezier eval")
  close_pt(r:eval(u, v), ref_bezier(P, W, u, v), "rational eval")
  -- eval = eval of the iso-curves (exact curve objects)
  close_pt(r:iso("u", u):eval(v), r:eval(u, v), "iso u")
  close_pt(r:iso("v", v):eval(u), r:eval(u, v), "iso v")
  -- the de Casteljau scheme ends at the point
  local sch = r:decasteljau(u, v)
  close_pt(sch.v[#sch.v][1], r:eval(u, v), "decasteljau")
  assert(#sch.columns == 4 and #sch.columns[1] == 3)
end
-- a list of pairs
local many = r:eval{ { 0.1, 0.2 }, { 0.9, 0.4 } }
close_pt(many[2], r:eval(0.9, 0.4), "eval list")
-- derivatives: D[1][2] = S_v against a difference quotient of order h^2
local D = s:derivs(0.4, 0.6, 2)
local h = 1e-5
local a, b = s:eval(0.4, 0.6 + h), s:eval(0.4, 0.6 - h)
for k = 1, 3 do
  assert(math.abs(D[1][2][k] - (a[k] - b[k]) / (2 * h)) < 1e-8, "S_v")
end
assert(#D == 3 and #D[1] == 3 and #D[3] == 1)
-- split and elevation leave the surface where it was
local lo, hi = r:split("u", 0.3)
close_pt(lo:eval(0.5, 0.4), r:eval(0.15, 0.4), "split lo")
close_pt(hi:eval(0.5, 0.4), r:eval(0.65, 0.4), "split hi")
local e = r:elevate(1, 2)
local ep, eq = e:degree()
assert(ep == 3 and eq == 5)
close_pt(e:eval(0.2, 0.9), r:eval(0.2, 0.9), "elevate")
assert(#r:weights() == 3 and r:weights()[2][3] == 3)
assert(s:points()[3][4][3] == 1)

-- B-splines: a bicubic surface with clamped uniform knots by default
local G = {}
for i = 1, 6 do
  G[i] = {}
  for j = 1, 5 do G[i][j] = { i, j, math.sin(i) * math.cos(j) } end
end
local bs = bspline_surface{ degree = { 3, 2 }, points = G }
local U, V = bs:knots()
assert(#U == 10 and #V == 8 and U[4] == 0 and U[5] == 1 / 3)
local k = bs:insert_knot("v", 0.3, 2)
close_pt(k:eval(0.45, 0.7), bs:eval(0.45, 0.7), "insert_knot")
close_pt(bs:iso("u", 0.45):eval(0.7), bs:eval(0.45, 0.7), "bspline iso")
local net, su, sv = bs:deboor(0.45, 0.7)
close_pt(net.v[#net.v][1], bs:eval(0.45, 0.7), "deboor")
-- spans as 0-based knot indices: u_4 = 1/3 <= 0.45, v_4 = 2/3 <= 0.7
assert(su == 4 and sv == 4)
local T = bs:to_bezier()
assert(#T == 3 and #T[1] == 3)
-- patch (2, 1) covers [1/3, 2/3] x [0, 1/3]
close_pt(T[2][1]:eval(0.5, 0.5), bs:eval(0.5, 1 / 6), "to_bezier")
close_pt(bs:elevate(1, 1):eval(0.8, 0.1), bs:eval(0.8, 0.1), "elevate")
assert(tostring(bs):find("^bspline surface of degrees %(3, 2%), 6 x 5"))

-- the exact sphere: on the sphere, K = 1 / r^2, |H| = 1 / r
local sp = nurbs_sphere{ center = { 1, 2, 3 }, r = 2 }
for i = 0, 8 do
  for j = 1, 7 do
    local x = sp:eval(i / 8, j / 8)
    local d = math.sqrt((x[1] - 1) ^ 2 + (x[2] - 2) ^ 2 + (x[3] - 3) ^ 2)
    close(d, 2, "sphere radius")
    local K, H = sp:curvature(i / 8, j / 8)
    close(K, 0.25, "sphere K")
    close(math.abs(H), 0.5, "sphere H")
  end
end
local to = nurbs_torus{ R = 3, r = 1 }
local x = to:eval(0.3, 0.6)
close((math.sqrt(x[1] ^ 2 + x[2] ^ 2) - 3) ^ 2 + x[3] ^ 2, 1, "torus")
-- a surface of revolution of a bezier curve about z
local prof = bezier{ { 1, 0, 0 }, { 2, 0, 1 }, { 1, 0, 2 } }
local rev = revolve(prof, { axis = { 0, 0, 1 } })
local y = rev:eval(0.37, 0.5)
close(math.sqrt(y[1] ^ 2 + y[2] ^ 2), prof:eval(0.5)[1], "revolve radius")
close(y[3], prof:eval(0.5)[3], "revolve height")
-- ruled, extrude, interpolation
local c1 = bezier{ { 0, 0, 0 }, { 1, 1, 0 }, { 2, 0, 0 } }
local c2 = bezier{ { 0, 0, 1 }, { 2, 0, 1 } }
local ru = ruled{ c1, c2 }
close_pt(ru:eval(0.3, 0), c1:eval(0.3), "ruled v = 0")
close_pt(ru:eval(0.3, 1), c2:eval(0.3), "ruled v = 1")
close_pt(extrude(c1, { 0, 0, 2 }):eval(0.3, 0.5),
         { c1:eval(0.3)[1], c1:eval(0.3)[2], 1 }, "extrude")
-- the Coons patch of the four boundaries of the bicubic bs: the boundaries
local cp = coons_patch{ bs:iso("v", 0), bs:iso("v", 1), bs:iso("u", 0),
                        bs:iso("u", 1) }
close_pt(cp:eval(0.3, 0), bs:eval(0.3, 0), "coons c0")
close_pt(cp:eval(1, 0.6), bs:eval(1, 0.6), "coons d1")
local I = interpolate_surface{ points = G, method = "global", degree = 3 }
assert(tostring(I):find("^bspline surface of degrees %(3, 3%)"))

-- a triangular patch of degree 2: T = sum 2 / (i! j! k!) u^i v^j w^k b_ijk
local tb = { { 0, 0, 0 }, { 1, 0, 1 }, { 1, 1, 0 }, { 2, 0, 0 }, { 1, 2, 1 },
             { 0, 2, 0 } }   -- b200, b110, b101, b020, b011, b002
local tri = bezier_triangle{ degree = 2, points = tb }
local u, v = 0.2, 0.5
local w = 1 - u - v
local coef = { u * u, 2 * u * v, 2 * u * w, v * v, 2 * v * w, w * w }
local want = { 0, 0, 0 }
for i = 1, 6 do
  for k = 1, 3 do want[k] = want[k] + coef[i] * tb[i][k] end
end
close_pt(tri:eval(u, v), want, "triangle eval")
local lv = tri:decasteljau(u, v)
assert(#lv == 3 and #lv[1] == 6 and #lv[3] == 1)
close_pt(lv[3][1], want, "triangle decasteljau")
close_pt(tri:elevate():eval(u, v), want, "triangle elevate")
close_pt(tri:boundary(1):eval(0.25), tri:eval(0.75, 0.25), "triangle edge")
local t1, t2, t3 = tri:subdivide(0.3, 0.3)
close_pt(t1:eval(1, 0), tri:eval(0.3, 0.3), "triangle subdivide")
assert(tostring(tri) == "bezier triangle of degree 2 in R^3")

-- errors in the user's terms
local function fails(f, fragment)
  local ok, msg = pcall(f)
  assert(not ok, "expected an error: " .. fragment)
  assert(tostring(msg):find(fragment, 1, true), tostring(msg))
end
fails(function() return bezier_surface{ points = { { { 0, 0, 0 }, { 1, 0, 0 } },
  { { 0, 1, 0 } } } } end, "row 2 has 1 point, row 1 has 2")
fails(function() return bezier_surface{ points = P, weights = { { 1, 1, 1, 1 },
  { 1, 1, -1, 1 }, { 1, 1, 1, 1 } } } end, "weight W[2][3] is -1")
fails(function() return bezier_surface{ points = { { { 0, 0 }, { 1, 0 } },
  { { 0, 0/0 }, { 1, 1 } } } } end, "point P[2][1] has coordinate 2 = ")
fails(function() return bezier_surface{ point = P } end,
  "did you mean 'points'")
fails(function() return s:eval(1.5, 0.5) end, "outside the domain")
fails(function() return s:iso("w", 0.5) end, "did you mean")
fails(function() return bspline_surface{ degree = { 3, 2 }, points = G,
  knots = { U, { 0, 0, 0, 1, 1, 1 } } } end, "knots V:")
fails(function() return s:knots() end, "a bezier surface has no knots")
print("core_surface: ok")
