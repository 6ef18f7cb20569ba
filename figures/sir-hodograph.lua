-- sir-hodograph (seed 000, Šír, "Bézierovy křivky", slide "Bézierovy
-- křivky": "Věta: Pro derivaci (hodograph) křivky c(t) s řídicími body
-- P_i ... platí c'(t) = Σ_{i=0}^{n−1} Q_i B_i^{n−1}(t), kde
-- Q_i = n(P_{i+1} − P_i)").
-- Left: a cubic c(t) with P_0 ... P_3 and its tangent vector c'(t) at
-- t = 0.8.  Right, side by side in its own frame with origin O: the
-- hodograph c'(t), the quadratic Bézier curve with control points
-- Q_0, Q_1, Q_2, Q_i = 3(P_{i+1} − P_i), drawn from O with the vectors
-- O→Q_i; the same vector c'(0.8) runs from O to the hodograph point.
-- The hodograph frame is drawn at scale 1 : 3 (so O→Q_i is parallel to
-- and as long as the leg P_iP_{i+1}); the tangent vector on the left is
-- drawn at the same scale, c'(t)/3.
-- Data chosen (the seed gives none): P_0 ... P_3 = (0,0) (1,2.5)
-- (3.5,2.8) (4.5,0.5).

local P = { {0, 0}, {1, 2.5}, {3.5, 2.8}, {4.5, 0.5} }
local c = bezier(P)
local n = c:degree()
local O = { 8.4, 1.2 }
local s = 1 / n           -- scale of the hodograph frame

local h = c:derivative()  -- control points Q_i = n (P_{i+1} - P_i)
local hq = {}
for i, q in ipairs(h:points()) do hq[i] = { O[1] + s * q[1], O[2] + s * q[2] } end
local hs = bezier(hq)     -- the hodograph as drawn (frame origin O, scale 1/3)

local f = figure{
  name = "sir-hodograph",
  caption = "A cubic c(t) (left) and its hodograph c'(t) (right, from the "
    .. "origin O, scale 1 : 3): the quadratic Bézier curve with control "
    .. "points Q_i = 3(P_{i+1} − P_i); the vector c'(0.8) is the same in both, "
    .. "drawn at a third of its length on the left too (měřítko = scale)",
  width = "15cm", height = "7cm",
}
-- the hodograph's frame: axes through O, and its scale
f:arrow({ O[1] - 0.5, O[2] }, { 3.4, 0 }, { color = "grey", width = 0.6 })
f:arrow({ O[1], O[2] - 2.7 }, { 0, 5.6 }, { color = "grey", width = 0.6 })
f:label({ O[1] + 3.4, O[2] - 2.1 }, "\\text{měřítko }1 : 3", { place = "w", color = "grey", font_size = 8 })
for i = 1, #hq do
  f:arrow_to(O, hq[i], { color = "grey", width = 0.6, dash = "dashed" })
end
f:polygon(hq)
f:curve(hs)
f:points(O, { marker = "dot" })
f:label(O, "O", { place = "sw" })
local qp = { "nw", "ne", "s" }
for i = 1, #hq do
  f:label(hq[i], string.format("Q_%d", i - 1), { place = qp[i] })
end
f:label(hs:eval(0.2), "c'(t)", { place = "w" })

-- the curve
f:polygon(c)
f:curve(c)
local pp = { "sw", "nw", "ne", "se" }
for i = 1, #P do
  f:label(P[i], string.format("P_%d", i - 1), { place = pp[i] })
end
f:label(c:eval(0.55), "c(t)", { place = "s" })

-- the same vector c'(0.8) (at scale 1/3) at c(0.8) and from O
local t0 = 0.8
local p0, d = c:eval(t0), c:derivs(t0, 1)[2]
f:arrow(p0, { s * d[1], s * d[2] }, { color = "darkred", width = 1.4 })
f:points(p0, { marker = "dot", color = "darkred", marker_color = "darkred" })
-- drawn at a third of its length, as in the hodograph's frame: said here
f:label({ p0[1] + s * d[1], p0[2] + s * d[2] }, "\\frac{1}{3}\\,c'(0.8)", { place = "e", color = "darkred" })
f:arrow(O, { s * d[1], s * d[2] }, { color = "darkred", width = 1.4 })
f:label({ O[1] + 0.45 * s * d[1], O[2] + 0.45 * s * d[2] }, "c'(0.8)", { place = "ne", color = "darkred", offset = 2 })
