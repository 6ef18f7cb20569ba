-- markova-2.7, markova-2.8 (seed 002, "B-spline křivky", §2.3, the strong
-- convex hull property, Obr. 2.7 "$p = 2, u = 0.6$", Obr. 2.8
-- "$p = 3, u = 0.3$").
-- "pokud u ∈ [u_i, u_{i+1}), potom C(u) leží v konvexním obalu řídicích
-- bodů P_{i-p}, P_{i-p+1}, ..., P_i": on the sample polygon P_0 ... P_7,
-- the hull of exactly the p + 1 control points acting on the knot span
-- [u_k, u_{k+1}) that contains u is shaded, the curve piece on that span
-- is highlighted (thick, orange) and the point C(u) marked; the knot
-- points C(u_i) are marked so the span's ends are visible.
--   2.7: p = 2, the sample curve's U = {0,0,0,0.17,0.33,0.5,0.67,0.83,1,1,1};
--        u = 0.6 lies in [u_5, u_6) = [0.5, 0.67): hull of P_3, P_4, P_5.
--   2.8: p = 3, clamped U = {0,0,0,0,0.2,0.4,0.6,0.8,1,1,1,1} (equally
--        spaced interior knots, docs/figures.md's choice for p = 3); u = 0.3
--        lies in [u_4, u_5) = [0.2, 0.4): hull of P_1, P_2, P_3, P_4.
-- The span and the points come from the library (s:active_points); the
-- script asserts that they are the ones named here.  Same window and size
-- as markova-2.1 ... 2.6.

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local place = { "s", "se", "e", "n", "s", "n", "w", "sw" }
local cases = {
  { name = "markova-2.7", p = 2, u = 0.6, first = 3, span = 5,
    s = bspline{ degree = 2, points = P,
                 knots = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 } },
    cplace = "n", coff = 7 },
  { name = "markova-2.8", p = 3, u = 0.3, first = 1, span = 4,
    s = bspline{ degree = 3, points = P, kind = "clamped" },
    cplace = "sw" },
}

for k, c in ipairs(cases) do
  local first, lo, hi = c.s:active_points(c.u)
  local U = c.s:knots()
  assert(first == c.first and lo == U[c.span + 1] and hi == U[c.span + 2])
  local act = {}
  for i = first, first + c.p do act[#act + 1] = P[i + 1] end
  local f = figure{
    name = c.name,
    caption = string.format("Strong convex hull property, p = %d, u = %g: "
      .. "C(u) and the curve piece on [u_%d, u_%d) = [%g, %g) lie in the "
      .. "shaded hull of P_%d ... P_%d (Obr. 2.%d)", c.p, c.u, c.span,
      c.span + 1, lo, hi, first, first + c.p, k + 6),
    width = "6.5cm", height = "5.4cm", window = { 0.45, 5.55, 0.55, 4.45 },
  }
  f:hull(act)
  f:polygon(P)
  f:curve(c.s)
  f:curve(c.s, { range = { lo, hi }, color = "#e8821e", width = 3 })
  f:knots(c.s)
  f:points(P, { color = "#3c3c3c", marker_color = "#3c3c3c" })
  for i, q in ipairs(P) do
    f:label(q, string.format("P_%d", i - 1), { place = place[i] })
  end
  local cu = c.s:eval(c.u)
  f:points(cu, { marker = "dot", marker_size = 5, marker_color = "black" })
  f:label(cu, string.format("C(%g)", c.u),
          { place = c.cplace, offset = c.coff })
end
