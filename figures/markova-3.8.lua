-- markova-3.8, markova-3.9, markova-3.10, markova-3.11 (seed 002,
-- "B-spline křivky", chapter 3, section 3.3 "Rozdělení B-spline křivky",
-- 3.3.1 "Výběr řídicích bodů": Obr. 3.8 "u = 0.5", Obr. 3.9 "Výpočet
-- nových bodů", Obrázek 3.10 "První část [0, u]", Obrázek 3.11 "Druhá
-- část [u, 1]").
--
-- Subdividing a B-spline at u with de Boor's algorithm: the control
-- points of the part on [0, u] are the untouched P_0..P_{k-p} followed
-- by the first point of every column of the de Boor net, ending at
-- C(u) = P_{k-s,p-s}; those of the part on [u, 1] start at C(u), take the
-- last point of every column back to P_{k-s} and go on to P_n.
--
-- DATA: the same curve as markova-3.5 ... 3.7 (the sample points P_0..P_7,
-- p = 3, U = {0, 0, 0, 0, 0.25, 0.4, 0.7, 0.85, 1, 1, 1, 1}; see that
-- script for why p = 3 and these knots), u = 0.5, k = 5, s = 0.  So the
-- first part has the polygon P_0 P_1 P_2 P_{3,1} P_{4,2} P_{5,3}, the
-- second P_{5,3} P_{5,2} P_{5,1} P_5 P_6 P_7.
--   markova-3.8:  the curve, C(u) and its two arcs [0, u] (green) and
--                 [u, 1] (purple), the polygon.
--   markova-3.9:  the de Boor net at u (close-up as markova-3.6), with
--                 the two new polygons traced over it in the parts'
--                 colours: P_2 P_{3,1} P_{4,2} P_{5,3} and P_{5,3} P_{5,2}
--                 P_{5,1} P_5.
--   markova-3.10: the first part [0, u] with its own polygon (green);
--                 the rest of the curve light for orientation.
--   markova-3.11: the second part [u, 1] with its own polygon (purple).
-- 3.8, 3.10 and 3.11 share one window and size (that of markova-3.5).

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
local A, B = s:split(u)
local C = L[4][1]

local window = { 0.6, 5.4, 0.7, 4.45 }
local W, H = "12cm", "9.35cm"
local zoom, ZW, ZH = { 1.85, 5.15, 2.85, 4.25 }, "16cm", "7.35cm"
local place = { "s", "w", "e", "n", "s", "n", "w", "e" }
local col1, col2 = "#1b7837", "#762a83"
local light = "#b4c0da"
local star = { marker = "star", color = "red", marker_color = "red",
               marker_size = 9 }

local function label_P(fig, which, color)
  for _, i in ipairs(which) do
    fig:label(P[i + 1], string.format("P_%d", i),
              { place = place[i + 1], color = color })
  end
end

-- the net's points by name: net[j][i] = P_{i,j}
local net = {}
for j = 0, 3 do
  net[j] = {}
  for q = 1, #L[j + 1] do net[j][k - 3 + j + q - 1] = L[j + 1][q] end
end
-- the chains of de Boor points that the two parts take (thesis 3.3.1)
local chain1 = { net[0][2], net[1][3], net[2][4], net[3][5] }
local chain2 = { net[3][5], net[2][5], net[1][5], net[0][5] }
-- check them against the library's split (to 1e-12 of the unit size)
do
  local pa, pb = A:points(), B:points()
  for q = 1, 4 do
    for d = 1, 2 do
      assert(math.abs(pa[2 + q][d] - chain1[q][d]) < 1e-12)
      assert(math.abs(pb[q][d] - chain2[q][d]) < 1e-12)
    end
  end
end

-- markova-3.8 ----------------------------------------------------------------
local f = figure{
  name = "markova-3.8",
  caption = "Subdivision at u = 0.5: the point C(u) divides the curve " ..
            "(p = 3 on the sample points) into the arcs [0, u] and " ..
            "[u, 1] (Obr. 3.8: u = 0.5)" .. SAMPLE,
  width = W, height = H, window = window,
}
f:polygon(s, { legend = CURVE })
label_P(f, { 0, 1, 2, 3, 4, 5, 6, 7 })
f:curve(s, { range = { 0, u }, color = col1 })
f:curve(s, { range = { u, 1 }, color = col2 })
f:points({ C }, star)
f:label(C, "C(0.5)", { place = "se", color = "red", offset = 6 })
f:label(s:eval(0.2), "[0, u]", { place = "w", color = col1, offset = 8 })
f:label(s:eval(0.9), "[u, 1]", { place = "e", color = col2, offset = 8 })

-- markova-3.9 ----------------------------------------------------------------
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

-- the de Boor net's columns told apart by dash and marker as well as by
-- colour (its red point beside the green chain, docs/accessibility.md)
theme{ redundant = true }
local g = figure{
  name = "markova-3.9",
  caption = "Subdivision at u = 0.5, the de Boor net: the first points " ..
            "of its columns P_2, P_{3,1}, P_{4,2}, P_{5,3} (green) and " ..
            "the last ones P_{5,3}, P_{5,2}, P_{5,1}, P_5 (purple) go to " ..
            "the two parts (Obr. 3.9: Výpočet nových bodů)" .. SAMPLE,
  width = ZW, height = ZH, window = zoom,
}
-- the legs of the polygon inside the close-up (the renderer reserves
-- room for ink outside an explicit window, so only that is drawn)
for i = 1, 7 do
  local a, b = clip(P[i], P[i + 1], zoom)
  if a then g:line(a, b, { color = "grey", width = 0.6 }) end
end
do
  local a, b = u, u
  while inside(s:eval(a - 0.001), zoom) do a = a - 0.001 end
  while inside(s:eval(b + 0.001), zoom) do b = b + 0.001 end
  g:curve(s, { range = { a, b }, color = light, width = 1.2, legend = CURVE })
end
g:deboor(s, u, { colors = { "black", "grey", "grey", "red" }, width = 0.7 })
g:polyline(chain1, { color = col1, width = 2.0 })
g:polyline(chain2, { color = col2, width = 2.0 })
g:points(chain1, { marker = "dot", color = col1, marker_color = col1,
                   marker_size = 5 })
g:points(chain2, { marker = "dot", color = col2, marker_color = col2,
                   marker_size = 5 })
g:points({ C }, star)
for i = 2, 5 do
  g:label(P[i + 1], string.format("P_%d", i), { place = place[i + 1] })
end
g:label(net[1][3], "P_{3,1}", { place = "ne", color = col1 })
g:label(net[1][4], "P_{4,1}", { place = "nw", color = "grey" })
g:label(net[1][5], "P_{5,1}", { place = "sw", color = col2 })
g:label(net[2][4], "P_{4,2}", { place = "n", color = col1 })
g:label(net[2][5], "P_{5,2}", { place = "nw", color = col2 })
g:label(C, "P_{5,3} = C(u)", { place = "se", color = "red", offset = 5 })

-- markova-3.10, markova-3.11 ---------------------------------------------------
local function part(name, caption, c, range_other, color, plabels, newlabels)
  local h = figure{ name = name, caption = caption .. SAMPLE,
                    width = W, height = H, window = window }
  h:curve(s, { range = range_other, color = light, width = 1.0,
               dash = "dashed", legend = CURVE })
  h:polygon(c, { color = color, marker_color = color, width = 0.8 })
  label_P(h, plabels)
  h:curve(c, { color = color })
  h:knots(c, { color = color })
  for _, e in ipairs(newlabels) do
    h:label(e[1], e[2], { place = e[3], color = color,
                          offset = e[1] == C and 7 or nil })
  end
  h:points({ C }, star)
  return h
end

part("markova-3.10",
     "Subdivision at u = 0.5, the first part on [0, u] with its own " ..
     "polygon P_0 P_1 P_2 P_{3,1} P_{4,2} P_{5,3} (Obrázek 3.10: První " ..
     "část [0, u])",
     A, { u, 1 }, col1, { 0, 1, 2 },
     { { net[1][3], "P_{3,1}", "ne" }, { net[2][4], "P_{4,2}", "n" },
       { C, "P_{5,3} = C(u)", "nw" } })

part("markova-3.11",
     "Subdivision at u = 0.5, the second part on [u, 1] with its own " ..
     "polygon P_{5,3} P_{5,2} P_{5,1} P_5 P_6 P_7 (Obrázek 3.11: Druhá " ..
     "část [u, 1])",
     B, { 0, u }, col2, { 5, 6, 7 },
     { { C, "P_{5,3} = C(u)", "ne" }, { net[2][5], "P_{5,2}", "nw" },
       { net[1][5], "P_{5,1}", "sw" } })
