-- orazem-offset-1, orazem-offset-2, orazem-offset-3 (seed 003, Oražem,
-- "Bezierjeva krivulja in njen odmik", section 4 "Odmik krivulje",
-- Figure 1 "Normala obrnjena navznoter, d = 0.5", Figure 2 "... d = 1.5",
-- Figure 3 "... d = 3").
--
-- The offset of the report's Bézier curve P_0..P_4 = (0,5) (1,-1) (3,0)
-- (4,3) (6,10): every point moved by the constant distance d along the
-- normal, here the normal turned INWARD.  Which side is inward: the
-- signed curvature c:curvature(t) is positive on all of [0, 1] (checked
-- below at 101 parameters), so the curve turns left everywhere and its
-- centres of curvature lie on the left of the direction of travel, on
-- the side of c:normal(t); "inward" is therefore the left normal, d > 0
-- in c:offset(d).  The smallest radius of curvature is 0.687 (at
-- t = 0.357), so d = 0.5 gives a regular offset while d = 1.5 and d = 3
-- exceed it: two cusps each ("pridejo zelo čudne stvari"); at d = 1.5
-- the raw offset also crosses itself (a swallow-tail), at d = 3 it does
-- not (two cusps, no loop).
-- Drawn in each figure: the curve (thick, dark) with its control
-- polygon; a few inward normals of length d (thin grey arrows at
-- t = 0.1, 0.3, ..., 0.9); the raw offset c(t) + d n(t) (orange, thin,
-- dashed, drawn last so that it is seen everywhere) with its cusps marked
-- (red crosses); and beneath it in a second style the trimmed offset
-- (light green, wide): the raw offset with the pieces closer than d to
-- the curve (cusps, loop, swallow-tail) removed.  A legend (in Slovene,
-- as the report) names them; orazem-offset-2 magnifies its swallow-tail
-- (both cusps and the self-intersection) in a zoom inset.
-- All five orazem-offset figures share one window and size (the window
-- holds the widest of them, outward d = 3).

local P = { {0, 5}, {1, -1}, {3, 0}, {4, 3}, {6, 10} }
local c = bezier(P)

for i = 0, 100 do
  assert(c:curvature(i / 100) > 0, "the curve turns left everywhere")
end

local window = { -3.3, 9.2, -2.3, 11.1 }
local raw_colour, trimmed_colour = "#c8500a", "#92d192"
local W, H = "9cm", "9.65cm"
local place = { "w", "s", "se", "e", "e" }   -- P_4 right: the inward offset passes left of it

local function offset_figure(name, d, caption, places)
  places = places or place
  local f = figure{ name = name, caption = caption, width = W, height = H,
                    window = window }
  f:polygon(c, { })
  for i = 0, 4 do
    f:label(P[i + 1], string.format("P_%d", i), { place = places[i + 1] })
  end
  for t = 0.1, 0.95, 0.2 do
    f:arrow_to(c:eval(t), c:offset_point(t, d),
               { color = "grey", width = 0.5, arrow_size = 4 })
  end
  f:curve(c)
  -- the trimmed offset wide and light under the raw one, thin and dashed,
  -- so that both are seen where they coincide
  local trimmed = c:offset(d, { trim = true })
  f:curve(trimmed, { color = trimmed_colour, width = 2.6,
                     legend = "\\text{obrezan odmik}" })
  f:curve((c:offset(d)), { color = raw_colour, width = 0.9, dash = "dashed",
                           legend = "\\text{odmik} $c(t) + d\\, n(t)$" })
  local cusps = c:offset_cusps(d)
  for k, t in ipairs(cusps) do
    f:points({ c:offset_point(t, d) }, { marker = "cross", color = "red",
                                          marker_color = "red",
                                          marker_size = 6,
                                          legend = k == 1 and "\\text{osti}" or nil })
  end
  f:label({ window[1] + 0.2, window[4] - 0.2 },
          string.format("d = %g", math.abs(d)), { place = "se" })
  return f, cusps
end

local _, k1 = offset_figure("orazem-offset-1", 0.5,
  "Offset with the normal turned inward, d = 0.5: smaller than the " ..
  "smallest radius of curvature, the offset is regular (raw offset " ..
  "orange dashed over the trimmed offset, light green) (Figure 1: " ..
  "Normala obrnjena navznoter, d = 0.5)")
assert(#k1 == 0)
local f2, k2 = offset_figure("orazem-offset-2", 1.5,
  "Offset with the normal turned inward, d = 1.5: two cusps and a loop " ..
  "(a swallow-tail, magnified in the inset) in the raw offset (orange " ..
  "dashed, cusps red), the trimmed offset light green beneath it " ..
  "(Figure 2: Normala obrnjena navznoter, d = 1.5)",
  -- P_3 below right and P_4 above left, clear of the curve and the
  -- offsets; the inset (placed automatically) goes where its connectors
  -- cross the least: above left, clear of every point and label
  { "w", "s", "se", "se", "nw" })
assert(#k2 == 2)
-- the swallow-tail magnified: both cusps and the self-intersection
-- (about (2.03, 3.02)) inside the region
for _, t in ipairs(k2) do
  local q = c:offset_point(t, 1.5)
  assert(q[1] > 1.35 and q[1] < 2.65 and q[2] > 2.1 and q[2] < 3.25)
end
f2:inset{ region = { 1.35, 2.1, 2.65, 3.25 }, scale = 3 }
local _, k3 = offset_figure("orazem-offset-3", 3,
  "Offset with the normal turned inward, d = 3: two cusps and no loop " ..
  "in the raw offset (orange dashed, cusps red); only the " ..
  "green part is at distance 3 from the curve (Figure 3: Normala " ..
  "obrnjena navznoter, d = 3)")
assert(#k3 == 2)
