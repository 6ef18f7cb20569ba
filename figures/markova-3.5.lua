-- markova-3.5, markova-3.6, markova-3.7 (seed 002, "B-spline křivky",
-- chapter 3, section 3.2 "De Boorův algoritmus", Obr. 3.5 "u = 0.5",
-- Obr. 3.6 "Výpočet nových bodů", Obr. 3.7 "Nová křivka").
--
-- De Boor's algorithm: to find C(u), insert u until its multiplicity is
-- p; the last point of the triangular scheme is C(u) = P_{k-s,p-s}.
--
-- DATA NOT IN THE SEED (docs/figures.md allows it): the thesis' sample curve
-- has p = 2 and u = 0.5 is its simple knot u_5, so de Boor inserts 0.5
-- only p - s = 1 time and the "triangle" is one new point.  These
-- figures therefore use the sample's control points P_0..P_7 with
-- degree p = 3 and the clamped knot vector
--     U = {0, 0, 0, 0, 0.25, 0.4, 0.7, 0.85, 1, 1, 1, 1}.
-- u = 0.5 lies in [u_5, u_6) = [0.4, 0.7), k = 5, s = 0: three columns
-- (P_{3,1} P_{4,1} P_{5,1}; P_{4,2} P_{5,2}; P_{5,3} = C(u)) from
-- P_2..P_5.  The interior knots are not equally spaced on purpose: the
-- points P_2..P_5 are point-symmetric about (3.5, 3.5), and with knots
-- symmetric about 0.5 (e.g. 0.2, 0.4, 0.6, 0.8) C(0.5) falls exactly on
-- P_{4,1} and the triangle collapses onto one point.
--   markova-3.5: the curve, its polygon and knot points, the p + 1 = 4
--                points P_2..P_5 that act on the span of u (polygon
--                drawn dark there, that arc of the curve highlighted) and
--                the point C(0.5).
--   markova-3.6: the de Boor net, column by column: column 0 (P_2..P_5)
--                black, column 1 blue, column 2 orange, C(u) = P_{5,3}
--                a red star; the new points labelled P_{i,j} as in the
--                thesis' scheme, the last one P_{5,3} = C(u); the curve
--                light behind.  The net is small beside the whole curve,
--                so this figure is a close-up of the region of P_2..P_5
--                (16 cm wide), drawn with its own window.
--   markova-3.7: the new curve after inserting u = 0.5 three times: the
--                same curve with the polygon P_0 P_1 P_2 P_{3,1} P_{4,2}
--                P_{5,3} P_{5,2} P_{5,1} P_5 P_6 P_7, which passes
--                through C(u) = P_{5,3}: the new points blue, C(u) a
--                red star, the new legs blue over a thinner curve, and
--                P_{4,2} C(u) P_{5,2} (where the legs touch the curve)
--                magnified in a zoom inset.
-- markova-3.5 and 3.7 share one window and size; 3.6 is the close-up.

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
-- Not the thesis's sample curve (vzorová křivka, degree 2): every caption
-- says which curve is drawn, and so does the figure (a legend entry of the
-- curve: its degree and knots).
local SAMPLE = "; the curve here: p = 3, U = {0, 0, 0, 0, 0.25, 0.4, " ..
  "0.7, 0.85, 1, 1, 1, 1} on the sample points, not the thesis's sample " ..
  "curve of degree 2"
local U = { 0, 0, 0, 0, 0.25, 0.4, 0.7, 0.85, 1, 1, 1, 1 }
local CURVE = "p = 3,\\; U = \\{0, 0, 0, 0, 0.25, 0.4, 0.7, 0.85, 1, 1, 1, 1\\}"
local s = bspline{ degree = 3, knots = U, points = P }
local u = 0.5
local L, k, mult = s:deboor(u)
assert(k == 5 and mult == 0 and #L == 4)

local window = { 0.6, 5.4, 0.7, 4.45 }
local W, H = "12cm", "9.35cm"
-- the close-up of markova-3.6: the region of P_2..P_5
local zoom, ZW, ZH = { 1.85, 5.15, 2.85, 4.25 }, "16cm", "7.35cm"
local place = { "s", "w", "e", "n", "s", "n", "w", "e" }
local level_color = { "black", "blue", "orange", "red" }

local function label_P(fig, skip)
  for i = 0, 7 do
    if not (skip and skip[i]) then
      fig:label(P[i + 1], string.format("P_%d", i), { place = place[i + 1] })
    end
  end
end

-- markova-3.5 ----------------------------------------------------------------
local f = figure{
  name = "markova-3.5",
  caption = "De Boor's algorithm at u = 0.5 on the sample points with " ..
            "p = 3: the points P_2 ... P_5 acting on the span [u_5, u_6) " ..
            "and the point C(u) (Obr. 3.5: u = 0.5)" .. SAMPLE,
  width = W, height = H, window = window,
}
f:polygon(s, { })
f:polyline({ P[3], P[4], P[5], P[6] }, { color = "black", width = 0.9 })
label_P(f)
f:curve(s, { legend = CURVE })
f:curve(s, { range = { U[6], U[7] }, color = "darkgreen", width = 2.2 })
f:knots(s)
-- the ends of the span, named as in the text
f:label(s:eval(U[6]), "C(u_5)", { color = "darkgreen",
                                  font_size = 8.5 })
f:label(s:eval(U[7]), "C(u_6)", { color = "darkgreen", font_size = 8.5 })
f:points({ L[4][1] }, { marker = "star", color = "red", marker_color = "red",
                        marker_size = 9 })
f:label(L[4][1], "C(0.5)", { place = "s", color = "red", offset = 5.5 })

-- markova-3.6 ----------------------------------------------------------------
local g = figure{
  name = "markova-3.6",
  caption = "De Boor's algorithm at u = 0.5, the new points column by " ..
            "column: P_{i,1} (blue), P_{i,2} (orange), P_{5,3} = C(u) " ..
            "(red) (Obr. 3.6: Výpočet nových bodů)" .. SAMPLE,
  width = ZW, height = ZH, window = zoom,
}
-- Only what lies inside the close-up window is drawn (the renderer
-- reserves room for ink outside an explicit window): the legs clipped to
-- it, the curve on the parameter interval around u that stays inside.
local function clip(a, b, w)
  local t0, t1 = 0, 1
  local d = { b[1] - a[1], b[2] - a[2] }
  local tests = { { -d[1], a[1] - w[1] }, { d[1], w[2] - a[1] },
                  { -d[2], a[2] - w[3] }, { d[2], w[4] - a[2] } }
  for _, pq in ipairs(tests) do
    local pp, q = pq[1], pq[2]
    if pp == 0 then
      if q < 0 then return nil end
    else
      local r = q / pp
      if pp < 0 then t0 = math.max(t0, r) else t1 = math.min(t1, r) end
    end
  end
  if t0 > t1 then return nil end
  return { a[1] + t0 * d[1], a[2] + t0 * d[2] },
         { a[1] + t1 * d[1], a[2] + t1 * d[2] }
end
local function inside(p, w)
  return p[1] >= w[1] and p[1] <= w[2] and p[2] >= w[3] and p[2] <= w[4]
end
local function inner_range(c, w, eps)
  local a, b = u, u
  while a - eps > 0 and inside(c:eval(a - eps), w) do a = a - eps end
  while b + eps < 1 and inside(c:eval(b + eps), w) do b = b + eps end
  return a, b
end
for i = 1, 7 do
  local a, b = clip(P[i], P[i + 1], zoom)
  if a then g:line(a, b, { color = "grey", width = 0.6 }) end
end
for i = 3, 6 do
  g:label(P[i], string.format("P_%d", i - 1), { place = place[i] })
end
g:curve(s, { range = { inner_range(s, zoom, 0.001) }, color = "#9fb0d0",
             width = 1.2, legend = CURVE })
g:deboor(s, u, { colors = level_color, width = 0.9,
                 point = { marker = "star", color = "red",
                           marker_color = "red", marker_size = 9 } })
local lplace = {
  [1] = { "ne", "nw", "sw" },
  [2] = { "n", "nw" },
  [3] = { "se" },
}
for j = 1, 3 do
  for i, q in ipairs(L[j + 1]) do
    local text = string.format("P_{%d,%d}", k - 3 + j + i - 1, j)
    if j == 3 then text = text .. " = C(u)" end
    g:label(q, text,
            { place = lplace[j][i], color = level_color[j + 1] })
  end
end

-- markova-3.7 ----------------------------------------------------------------
local n = s:insert_knot(u, 3)
-- the curve is unchanged (to 1e-12 of the unit size, 101 parameters)
for i = 0, 100 do
  local a, b = s:eval(i / 100), n:eval(i / 100)
  assert(math.abs(a[1] - b[1]) < 1e-12 and math.abs(a[2] - b[2]) < 1e-12)
end
local h = figure{
  name = "markova-3.7",
  caption = "The new curve: u = 0.5 inserted three times; the same " ..
            "curve, its new polygon passes through C(u) = P_{5,3} " ..
            "; right, magnified, the new legs P_{4,2} C(u) P_{5,2} " ..
            "(Obr. 3.7: Nová křivka)" .. SAMPLE,
  width = W, height = H, window = window,
}
h:polygon(n, { })
label_P(h, { [3] = true, [4] = true })
-- the curve thinner than in 3.5 and the new legs P_{3,1} ... P_{5,1}
-- in blue over it: near C(u) they touch the curve
local Q = n:points()
h:curve(n, { width = 1.1, legend = CURVE })
h:polyline({ Q[4], Q[5], Q[6], Q[7], Q[8] }, { color = "blue", width = 1.1 })
h:knots(n)
-- P_{5,2} above left and P_{4,2} above their points, C(u) below: outside
-- the inset's region
-- (P_{5,2}'s label outside the region's frame, left of it)
local new = { { 3, "P_{3,1}", "ne" }, { 4, "P_{4,2}", "n" },
              { 6, "P_{5,2}", "w", { 3.13, Q[7][2] + 0.05 } },
              { 7, "P_{5,1}", "sw" } }
for _, e in ipairs(new) do
  h:points({ Q[e[1] + 1] }, { marker = "dot", color = "blue",
                              marker_color = "blue", marker_size = 4.5 })
  h:label(e[4] or Q[e[1] + 1], e[2], { place = e[3], color = "blue" })
end
h:points({ Q[6] }, { marker = "star", color = "red", marker_color = "red",
                     marker_size = 9 })
-- C(u) below its star, between the two connectors
h:label({ Q[6][1] - 0.29, Q[6][2] - 0.36 }, "P_{5,3} = C(u)",
        { place = "center", color = "red" })
-- P_{4,2}, C(u), P_{5,2} magnified
-- in the empty middle of the heart, just below the region: short
-- connectors, clear of the labels and of the curve
h:inset{ region = { 3.15, 3.455, 3.95, 3.69 },
         at = { "131bp", "100bp", "110bp", "33bp" } }
