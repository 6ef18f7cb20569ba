-- markova-4.1 ... markova-4.7 (seed 002, "B-spline křivky", chapter 4
-- "Křivky v počítačové grafice"): one figure per kind of curve surveyed
-- there.  The chapter has no figures and gives no data; all data below
-- are this project's choice, made to show what the text says of each
-- kind.
--   markova-4.1  4.2.1 "Fergusonovy kubiky": a Ferguson (Hermite) cubic
--                from P_0, P_1 and the tangent vectors T_0, T_1 drawn as
--                arrows at full length (c'(0) = T_0, c'(1) = T_1);
--                "směr a velikost tečných vektorů [určují] míru jejího
--                vyklenutí": the cubics with the same points and
--                tangent directions but T_0, T_1 halved (dashed) and
--                doubled (dotted) are drawn thin and named in a legend.
--                P_0 = (0,0), P_1 = (6,0), T_0 = (2,6), T_1 = (4,-5).
--   markova-4.2  4.3.1 "Bézierovy kubiky": a Bézier cubic with its
--                polygon P_0..P_3 = (0,0) (1.5,3) (4.5,3.5) (6,0.5); it
--                passes through P_0 and P_3, tangent to the end legs.
--                "při změně polohy řídicího bodu dojde ke změně tvaru
--                celé křivky": P_2 moved to P_2' = (5.5,2) gives the
--                dashed curve, different along its whole length.
--   markova-4.3  4.3.2 "Coonsovy kubiky": the Coons cubic of the same
--                four points (one segment of a uniform cubic B-spline,
--                starting at (P_0 + 4 P_1 + P_2)/6 and ending at
--                (P_1 + 4 P_2 + P_3)/6): it does not pass through the end
--                points of its polygon ("obecně neprochází krajními body
--                svého řídicího polygonu"); the Bézier cubic of the same
--                points light and dashed for comparison, both named in a
--                legend (in Czech, as the thesis).
--   markova-4.4  4.3.3 "Spline křivky": the natural cubic spline (C^2,
--                zero second derivative at both ends) through the seven
--                points (0,0) (1,2) (3,2.5) (4,0.5) (6,0) (7,2) (8.5,1.5),
--                chord-length parameters; the data points are on the
--                curve, there is no control polygon.
--   markova-4.5  4.3.4 "Uniformní neracionální kubické B-spline křivky":
--                the uniform cubic (Coons) B-spline of the same seven
--                points with the end points tripled (P_0, P_0, P_0, P_1,
--                ..., P_6, P_6, P_6): it passes through P_0 and P_6; the
--                joints of its segments (knots) marked.  The B-spline of
--                the plain sequence P_0..P_6 is the middle part of this
--                curve (u in [2, 6]; it does not reach the end points);
--                the two segments at each end that the tripling adds are
--                drawn in orange.
--   markova-4.6  the closed uniform cubic B-spline of P_0..P_5 =
--                (0,0) (3,-1) (5.5,0.5) (5,3) (2.5,3.5) (0.5,2.5) from
--                the sequence P_0, ..., P_5, P_0, P_1, P_2 (closed C^2
--                curve), knots marked.
--   markova-4.7  4.3.5 "NURBS": "umožňují přesné vyjádření kuželoseček":
--                the NURBS circle of radius 2 (p = 2, nine control points
--                on a square, weights 1 and sqrt(2)/2 written at the
--                points, knots {0,0,0,1/4,1/4,1/2,1/2,3/4,3/4,1,1,1}),
--                with the exact circle's points checked below; the
--                non-rational B-spline of the same points and knots
--                (all weights 1), which is not a circle, dashed; a legend
--                (in Czech) names both.

local figs = {}
local function fig(id, caption, w, h)
  local f = figure{ name = id, caption = caption, width = w or "8cm",
                    height = h or "5.5cm" }
  figs[#figs + 1] = f
  return f
end
local function labels(f, pts, places, fmt, opts)
  for i, p in ipairs(pts) do
    if places[i] then
      local o = { place = places[i] }
      for k, v in pairs(opts or {}) do o[k] = v end
      f:label(p, string.format(fmt or "P_%d", i - 1), o)
    end
  end
end
local light = "#8c9bbd"

-- markova-4.1: Ferguson cubic ---------------------------------------------------
do
  local P0, P1, T0, T1 = { 0, 0 }, { 6, 0 }, { 2, 6 }, { 4, -5 }
  local f = fig("markova-4.1",
    "A Ferguson cubic: the end points P_0, P_1 and the tangent vectors " ..
    "T_0, T_1; dashed and dotted, named in the legend: the same with the " ..
    "tangent vectors halved and doubled (4.2.1 Fergusonovy kubiky)",
    "8cm", "6cm")
  local variants = {
    { 0.5, { color = "#4a7fc1", width = 0.9, dash = "dashed",
             legend = "½T_0, ½T_1" } },
    { 2, { color = "#e08214", width = 0.9, dash = "dotted",
           legend = "2T_0, 2T_1" } } }
  local c = ferguson(P0, P1, T0, T1)
  -- the Hermite conditions, checked
  local d0, d1 = c:derivs(0, 1), c:derivs(1, 1)
  assert(math.abs(d0[2][1] - T0[1]) < 1e-12 and math.abs(d1[2][2] - T1[2]) < 1e-12)
  f:curve(c, { legend = "T_0, T_1" })
  for _, v in ipairs(variants) do
    local k = v[1]
    f:curve(ferguson(P0, P1, { k * T0[1], k * T0[2] },
                     { k * T1[1], k * T1[2] }), v[2])
  end
  f:arrow(P0, T0, { color = "darkred", width = 1.0 })
  f:arrow(P1, T1, { color = "darkred", width = 1.0 })
  f:points({ P0, P1 }, { marker = "dot" })
  f:label(P0, "P_0", { place = "sw" })
  f:label(P1, "P_1", { place = "ne" })
  f:label({ P0[1] + T0[1], P0[2] + T0[2] }, "T_0", { place = "e", color = "darkred" })
  f:label({ P1[1] + T1[1], P1[2] + T1[2] }, "T_1", { place = "e", color = "darkred" })
end

-- markova-4.2: Bezier cubic ----------------------------------------------------
local B = { {0,0}, {1.5,3}, {4.5,3.5}, {6,0.5} }
do
  local f = fig("markova-4.2",
    "A Bézier cubic with its control polygon P_0 ... P_3; moving P_2 to " ..
    "P_2' changes the whole curve (dashed) (4.3.1 Bézierovy kubiky)")
  local B2 = { B[1], B[2], { 5.5, 2 }, B[4] }
  f:polygon(B2, { color = "#b0b0b0", dash = "dashed", marker = "none" })
  f:curve(bezier(B2), { color = light, width = 1.0, dash = "dashed" })
  f:points({ B2[3] }, { marker = "circle", color = "grey", marker_color = "grey" })
  f:label(B2[3], "P_2'", { place = "e", color = "grey" })
  f:polygon(B, { })
  labels(f, B, { "sw", "nw", "ne", "se" })
  f:curve(bezier(B))
end

-- markova-4.3: Coons cubic -----------------------------------------------------
do
  local f = fig("markova-4.3",
    "A Coons cubic on the polygon P_0 ... P_3: it starts at " ..
    "(P_0 + 4P_1 + P_2)/6 and ends at (P_1 + 4P_2 + P_3)/6, not at the " ..
    "end points; dashed: the Bézier cubic of the same points, both named " ..
    "in the legend (4.3.2 Coonsovy kubiky)")
  local c = coons_cubic(B)
  local s0 = { (B[1][1] + 4 * B[2][1] + B[3][1]) / 6,
               (B[1][2] + 4 * B[2][2] + B[3][2]) / 6 }
  local e0 = c:eval(0)
  assert(math.abs(e0[1] - s0[1]) < 1e-12 and math.abs(e0[2] - s0[2]) < 1e-12)
  f:curve(bezier(B), { color = light, width = 0.9, dash = "dashed",
                       legend = "Bézierova kubika $B(t)$" })
  f:polygon(B, { })
  labels(f, B, { "sw", "nw", "ne", "se" })
  f:curve(c, { legend = "Coonsova kubika $Q(t)$" })
  f:points({ c:eval(0), c:eval(1) }, { marker = "dot", color = "darkred",
                                        marker_color = "darkred" })
  -- Q(0) lies between the leg P_0 P_1, the dashed curve and the Coons
  -- cubic: its label in the narrow gap below the point
  f:label(c:eval(0), "Q(0)", { place = "s", offset = 2, color = "darkred" })
  f:label(c:eval(1), "Q(1)", { place = "s", color = "darkred" })
end

-- markova-4.4: natural cubic spline --------------------------------------------
local S = { {0,0}, {1,2}, {3,2.5}, {4,0.5}, {6,0}, {7,2}, {8.5,1.5} }
local Splaces = { "s", "nw", "n", "sw", "s", "n", "e" }
do
  local f = fig("markova-4.4",
    "The natural cubic spline through P_0 ... P_6 (C^2, zero second " ..
    "derivative at the ends, chord-length parameters) (4.3.3 Spline " ..
    "křivky)", "9cm", "4.2cm")
  local s = interpolate{ points = S, method = "natural", param = "chord" }
  f:curve(s)
  f:points(S, { marker = "dot", color = "darkred", marker_color = "darkred" })
  labels(f, S, Splaces)
end

-- markova-4.5: uniform cubic B-spline with tripled end points -------------------
do
  local f = fig("markova-4.5",
    "The uniform cubic (Coons) B-spline of P_0, P_0, P_0, P_1, ..., " ..
    "P_6, P_6, P_6: it passes through the end points; segment joints " ..
    "marked; the segments that the tripled end points add to the " ..
    "B-spline of P_0 ... P_6 in orange (4.3.4)", "9cm", "4.2cm")
  local s = coons{ points = S, ends = "tripled" }
  local plain = coons{ points = S, ends = "plain" }
  -- the plain curve is the part [2, 6] of the tripled one (checked)
  local a, b = s:domain()
  assert(a == 0 and b == 8)
  for i = 0, 12 do
    local p, q = plain:eval(4 * i / 12), s:eval(2 + 4 * i / 12)
    assert(math.abs(p[1] - q[1]) < 1e-12 and math.abs(p[2] - q[2]) < 1e-12)
  end
  f:polygon(S, { })
  labels(f, S, Splaces)
  f:curve(s, { range = { 2, 6 } })
  f:curve(s, { range = { 0, 2 }, color = "#e08214" })
  f:curve(s, { range = { 6, 8 }, color = "#e08214" })
  f:knots(s)
end

-- markova-4.6: closed uniform cubic B-spline ------------------------------------
do
  local C = { {0,0}, {3,-1}, {5.5,0.5}, {5,3}, {2.5,3.5}, {0.5,2.5} }
  local f = fig("markova-4.6",
    "A closed uniform cubic B-spline from the sequence P_0, ..., P_5, " ..
    "P_0, P_1, P_2; segment joints marked (4.3.4)", "7cm", "5cm")
  local s = coons{ points = C, ends = "closed" }
  f:polyline(C, { closed = true, color = "#8c8c8c", width = 0.6 })
  f:points(C, { marker = "dot", color = "#3a3a3a", marker_color = "#3a3a3a",
                marker_size = 3.6 })
  labels(f, C, { "sw", "se", "e", "ne", "n", "w" })
  f:curve(s)
  f:knots(s)
end

-- markova-4.7: NURBS circle -----------------------------------------------------
do
  local f = fig("markova-4.7",
    "A NURBS: the exact circle of radius 2 with p = 2, nine control " ..
    "points P_0 = P_8, ..., P_7 and weights w_i = 1 and \u{221A}2/2 " ..
    "(written at the points); " ..
    "dashed: the same points and knots with all weights 1, not a circle; " ..
    "both named in the legend (4.3.5 NURBS)", "7cm", "7cm")
  local c = nurbs_circle({ 0, 0 }, 2)
  for i = 0, 40 do
    local p = c:eval(i / 40)
    assert(math.abs(math.sqrt(p[1] ^ 2 + p[2] ^ 2) - 2) < 1e-12)
  end
  local pts, w = c:points(), c:weights()
  local flat = bspline{ degree = 2, knots = c:knots(), points = pts }
  f:curve(flat, { color = light, width = 0.9, dash = "dashed",
                  legend = "všechny váhy $w_i = 1$" })
  f:polygon(pts, { })
  f:curve(c, { legend = "NURBS, kružnice $C(u)$" })
  for i, p in ipairs(pts) do
    if i < #pts then
      local text = string.format("w_%d = %s", i - 1,
                                 w[i] == 1 and "1" or "\\sqrt{2}/2")
      if i == 1 then text = "w_0 = w_8 = 1" end
      local place = ({ "e", "ne", "n", "nw", "w", "sw", "s", "se" })[i]
      -- the corners' labels nearer along the diagonal (their boxes'
      -- corners, not their glyphs, would be at the offset)
      f:label(p, text, { place = place, font_size = 8,
                         offset = #place == 2 and 1 or nil })
    end
  end
end
