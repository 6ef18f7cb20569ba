-- markova-2.9, markova-2.10 (seed 002, "B-spline křivky", §2.3, local
-- control, Obr. 2.9 "Původní křivka", Obr. 2.10 "Změna P_4").
-- "Změna pozice řídicího bodu P_i ovlivní křivku C(u) pouze na intervalu
-- [u_i, u_{i+p+1})": the sample curve (p = 2, P_0 ... P_7,
-- U = {0,0,0,0.17,0.33,0.5,0.67,0.83,1,1,1}), then the same curve with P_4
-- moved.  The seed does not say where P_4 goes: chosen v = (0, -1), i.e.
-- P_4 = (3, 3) -> (3, 2), which deepens the notch of the heart.  In both
-- figures the arc on [u_4, u_7) = [0.33, 0.83) -- the only part P_4 acts
-- on -- is drawn in orange and the knot points are marked; the rest of the
-- curve is the same in both (checked with `curvefig run`: over 10001
-- samples of [0, 1] the two curves differ by exactly 0 outside
-- [0.33, 0.83) and by at most 0.746 = max N_4^2 * |v| inside; the script
-- asserts < 1e-12 outside).  Same window and size as markova-2.1 ... 2.8
-- and markova-2.11.

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local place = { "s", "se", "e", "n", "s", "n", "w", "sw" }
local s = bspline{ degree = 2, knots = U, points = P }
local v = { 0, -1 }
local d = s:move_point(4, v)
local lo, hi = s:support(4)
assert(lo == U[5] and hi == U[8])
for j = 0, 1000 do
  local u = j / 1000
  if u < lo or u >= hi then
    local a, b = s:eval(u), d:eval(u)
    assert(math.abs(a[1] - b[1]) + math.abs(a[2] - b[2]) < 1e-12)
  end
end

local figs = {
  { "markova-2.9", s, "The sample curve (p = 2); the arc on [u_4, u_7) = "
    .. "[0.33, 0.83), where P_4 acts, in orange (Obr. 2.9: Původní křivka)" },
  { "markova-2.10", d, "The sample curve with P_4 moved by v = (0, -1): only "
    .. "the arc on [u_4, u_7) = [0.33, 0.83) changes (Obr. 2.10: Změna P_4)" },
}
for _, g in ipairs(figs) do
  local c = g[2]
  local f = figure{ name = g[1], caption = g[3], width = "6.5cm",
                    height = "5.4cm", window = { 0.45, 5.55, 0.55, 4.45 } }
  f:polygon(c)
  f:curve(c)
  f:curve(c, { range = { lo, hi }, color = "#e8821e", width = 3 })
  f:knots(c)
  f:points(c, { color = "#3c3c3c", marker_color = "#3c3c3c" })
  for i, q in ipairs(c:points()) do
    f:label(q, string.format("P_%d", i - 1), { place = place[i] })
  end
  -- the ends of the arc, named as in the text
  f:label(c:eval(lo), "C(u_4)", { color = "#b35f00", font_size = 8 })
  f:label(c:eval(hi), "C(u_7)", { color = "#b35f00", font_size = 8 })
end
