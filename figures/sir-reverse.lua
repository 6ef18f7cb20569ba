-- sir-reverse, sir-affine (seed 000, Šír, "Bézierovy křivky", slide
-- "Bézierovy křivky", the two theorems after the convex hull:
-- "Jestliže c(t) je Bézierova křivka s řídícími body P_0, ..., P_n a
-- c̃(t) je Bézierova křivka s řídícími body P̃_0, ..., P̃_n, kde
-- P̃_i = P_{n−i}, pak c̃(t) = c(1 − t)" and "Mějme Eukleidovskou shodnost
-- ve tvaru Ax + a. ... kde P̃_i = AP_i + a, pak c̃(t) = Ac(t) + a").
--
-- sir-reverse: left, the cubic c(t) with P_0 ... P_3; right, the same
-- points numbered backwards, P̃_i = P_{3−i}, and their curve c̃(t): the
-- same point set run the other way.  The direction of the parameter is
-- shown by the marks t = 0 / t = 1 at the ends and arrows along the
-- curve; the point c(1/4) on the left and c̃(3/4) on the right are the
-- same point.  The right panel is the left one translated by (6, 0), so
-- the two can be compared side by side.
--
-- sir-affine: the cubic c(t) with P_0 ... P_3 and its image under the
-- Euclidean congruence x ↦ Ax + a the slide states: A the rotation by
-- −40°, a = (5.5, −1).  The image points P̃_i = AP_i + a with their curve
-- c̃(t) (drawn from the P̃_i, not by moving c) and the correspondence
-- P_i ↦ P̃_i and c(1/2) ↦ c̃(1/2) = Ac(1/2) + a by thin dotted lines.
--
-- Data chosen (the seed gives none): P_0 ... P_3 = (0,0) (0.8,2.4)
-- (3.4,2.6) (4.2,0.6).

local P = { {0, 0}, {0.8, 2.4}, {3.4, 2.6}, {4.2, 0.6} }
local c = bezier(P)

local function add(p, v) return { p[1] + v[1], p[2] + v[2] } end

-- direction arrows: short arrows tangent to the curve at parameters ts,
-- just outside the curve (on the side of its normal times side)
local function direction(f, curve, ts, side, colour)
  for _, t in ipairs(ts) do
    local p, d, nrm = curve:eval(t), curve:tangent(t), curve:normal(t)
    local base = { p[1] + side * 0.22 * nrm[1] - 0.25 * d[1],
                   p[2] + side * 0.22 * nrm[2] - 0.25 * d[2] }
    f:arrow(base, { 0.5 * d[1], 0.5 * d[2] }, { color = colour, width = 0.9 })
  end
end

-- sir-reverse ----------------------------------------------------------
local shift = { 6, 0 }
local Q = {}
for i = 1, #P do Q[i] = add(P[#P + 1 - i], shift) end  -- P̃_i = P_{n-i} (+ shift)
local r = bezier(Q)

local f = figure{
  name = "sir-reverse",
  caption = "Reversed control points P̃_i = P_{n−i} give the reversed "
    .. "parametrisation c̃(t) = c(1 − t): the same curve run the other "
    .. "way (left c(t), right c̃(t); c(1/4) = c̃(3/4))",
  width = "13cm", height = "4.8cm",
}
f:polygon(c)
f:curve(c, { legend = "c(t)" })
f:polygon(r)
f:curve(r, { color = "darkred", legend = "\\tilde{c}(t) = c(1 − t)" })
local lp = { "w", "nw", "ne", "ne" }
for i = 1, 4 do
  f:label(P[i], string.format("P_%d", i - 1), { place = lp[i] })
  f:label(Q[i], string.format("\\tilde{P}_%d", i - 1), { place = lp[5 - i] })
end
f:label(P[1], "t = 0", { place = "se" })
f:label(P[4], "t = 1", { place = "s", offset = 5 })
f:label(Q[1], "t = 0", { place = "s", offset = 5 })
f:label(Q[4], "t = 1", { place = "se" })
direction(f, c, { 0.12, 0.5, 0.88 }, -1, "darkblue")
direction(f, r, { 0.12, 0.5, 0.88 }, 1, "darkred")
local a, b = c:eval(0.25), r:eval(0.75)
f:points(a, { marker = "dot", color = "darkblue", marker_color = "darkblue" })
f:points(b, { marker = "dot", color = "darkred", marker_color = "darkred" })
f:label(a, "c(1/4)", { place = "e" })
f:label(b, "\\tilde{c}(3/4)")

-- sir-affine -----------------------------------------------------------
local th = math.rad(-40)
local A = { { math.cos(th), -math.sin(th) }, { math.sin(th), math.cos(th) } }
local av = { 5.5, -1 }
local function map(p)
  return { A[1][1] * p[1] + A[1][2] * p[2] + av[1],
           A[2][1] * p[1] + A[2][2] * p[2] + av[2] }
end
local R = {}
for i = 1, #P do R[i] = map(P[i]) end
local g_img = bezier(R)  -- drawn from the image points, not by mapping c

local g = figure{
  name = "sir-affine",
  caption = "Invariance under a Euclidean congruence x ↦ Ax + a "
    .. "(A the rotation by −40°, a = (5.5, −1)): the image points "
    .. "P̃_i = AP_i + a define the image curve c̃(t) = Ac(t) + a; "
    .. "dotted: P_i ↦ P̃_i and c(1/2) ↦ c̃(1/2)",
  width = "10cm", height = "7.5cm",
}
for i = 1, 4 do
  g:line(P[i], R[i], { color = "grey", dash = "dotted", width = 0.7 })
end
local m, mi = c:eval(0.5), g_img:eval(0.5)
g:line(m, mi, { color = "grey", dash = "dotted", width = 0.7 })
g:polygon(c)
g:curve(c)
g:polygon(g_img)
g:curve(g_img, { color = "darkred" })
local lq = { "sw", "nw", "n", "sw" }
local lr = { "auto", "auto", "ne", "auto" }   -- P̃_2: clear of the image curve
for i = 1, 4 do
  g:label(P[i], string.format("P_%d", i - 1), { place = lq[i] })
  g:label(R[i], string.format("\\tilde{P}_%d", i - 1),
          { place = lr[i] })
end
g:points(m, { marker = "dot", color = "darkblue", marker_color = "darkblue" })
g:points(mi, { marker = "dot", color = "darkred", marker_color = "darkred" })
g:label(m, "c(1/2)")
g:label(mi, "\\tilde{c}(1/2)")
