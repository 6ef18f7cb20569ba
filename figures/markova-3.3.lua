-- markova-3.3, markova-3.4 (seed 002, "B-spline křivky", chapter 3,
-- section 3.1.2 "Vložení uzlu do existujícího jednoduchého uzlu",
-- Obr. 3.3 "Původní křivka" and Obr. 3.4 "Dvojnásobný uzel t = 0.5").
--
-- Inserting t = 0.5 into the sample curve (p = 2, P_0..P_7, U as given),
-- where 0.5 = u_5 is already a (simple) knot.  t lies in [u_5, u_6), so
-- k = 5 and the new points are Q_4 = (1 - a_4) P_3 + a_4 P_4 with
-- a_4 = (0.5 - 0.33) / (0.67 - 0.33) = 1/2, i.e. the midpoint of P_3 P_4,
-- and Q_5 with a_5 = (0.5 - u_5) / (u_7 - u_5) = 0: as the thesis says,
-- "Q_k, poslední nový řídicí bod, je roven P_{k-1}", so Q_5 = P_4 and no
-- corner is cut.  u_5 becomes a double knot, of multiplicity p = 2, so
-- the curve passes through the control point Q_4 = C(0.5).
--   markova-3.3: the original curve, its polygon and its knot points,
--                the knot point C(u_5) = C(0.5) pointed at.
--   markova-3.4: the same curve with the knot vector
--                {0,0,0,0.17,0.33,0.5,0.5,0.67,0.83,1,1,1}: the new
--                polygon P_0 P_1 P_2 P_3 Q_4 Q_5 P_5 P_6 P_7 with the new
--                point Q_4 in blue, Q_5 = P_4 labelled so, the double
--                knot u_5 = u_6 = 0.5 at C(0.5) = Q_4 pointed at.
-- Window and size as markova-3.1/3.2.  No further data needed.

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local s = bspline{ degree = 2, knots = U, points = P }
local t = 0.5

local window = { 0.6, 5.4, 0.7, 4.45 }
local W, H = "10cm", "7.8cm"
local place = { "s", "w", "e", "n", "s", "n", "w", "e" }

-- a pointer from above the dip of the curve to C(t)
local function mark_t(fig, c, text)
  local ct = c:eval(t)
  local from = { 3.0, 4.12 }
  local d = { ct[1] - from[1], ct[2] - from[2] }
  local len = math.sqrt(d[1] ^ 2 + d[2] ^ 2)
  fig:arrow_to(from, { ct[1] - 0.06 * d[1] / len, ct[2] - 0.06 * d[2] / len },
               { color = "darkgreen", width = 0.7 })
  fig:label(from, text, { place = "n", color = "darkgreen" })
end

-- markova-3.3 ----------------------------------------------------------------
local f = figure{
  name = "markova-3.3",
  caption = "Inserting into an existing knot, the original curve: the " ..
            "sample curve (p = 2) and its knot points; t = 0.5 is the " ..
            "simple knot u_5 (Obr. 3.3: Původní křivka)",
  width = W, height = H, window = window,
}
f:polygon(s, { })
for i = 0, 7 do
  f:label(P[i + 1], string.format("P_%d", i), { place = place[i + 1] })
end
f:curve(s)
f:knots(s)
f:points({ s:eval(t) }, { marker = "dot", color = "darkgreen",
                          marker_color = "darkgreen", marker_size = 4 })
mark_t(f, s, "t = u_5 = 0.5")

-- markova-3.4 ----------------------------------------------------------------
local n, info = s:insert_knot(t)
local Q = n:points()
-- the curve is unchanged (to 1e-12 of the unit size, 101 parameters)
for i = 0, 100 do
  local a, b = s:eval(i / 100), n:eval(i / 100)
  assert(math.abs(a[1] - b[1]) < 1e-12 and math.abs(a[2] - b[2]) < 1e-12)
end
assert(info.span == 5 and info.multiplicity == 1 and info.cut_count == 0
       and info.new_first == 4 and info.new_count == 1)

local g = figure{
  name = "markova-3.4",
  caption = "Inserting t = 0.5 into the existing knot u_5: the new point " ..
            "Q_4 on P_3 P_4, Q_5 = P_4; the double knot makes the curve " ..
            "pass through Q_4 = C(0.5) (Obr. 3.4: Dvojnásobný uzel t = 0.5)",
  width = W, height = H, window = window,
}
g:polygon(n, { })
for i = 0, 7 do
  if i ~= 4 then
    g:label(P[i + 1], string.format("P_%d", i), { place = place[i + 1] })
  end
end
g:label(P[5], "Q_5 = P_4", { place = "s" })
g:curve(n)
g:knots(n)
g:points({ Q[5] }, { marker = "dot", color = "blue", marker_color = "blue",
                     fill = "blue", marker_size = 5 })
g:label(Q[5], "Q_4", { place = "se", color = "blue" })
mark_t(g, n, "u_5 = u_6 = 0.5")
