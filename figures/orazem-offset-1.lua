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
-- dashed) with its cusps marked (red crosses); and in a second style the
-- trimmed offset (green, thick): the raw offset with the pieces closer
-- than d to the curve (cusps, loop, swallow-tail) removed.
-- All five orazem-offset figures share one window and size (the window
-- holds the widest of them, outward d = 3).

local P = { {0, 5}, {1, -1}, {3, 0}, {4, 3}, {6, 10} }
local c = bezier(P)

for i = 0, 100 do
  assert(c:curvature(i / 100) > 0, "the curve turns left everywhere")
end

local window = { -3.3, 9.2, -2.3, 11.1 }
local W, H = "9cm", "9.65cm"
local place = { "w", "s", "se", "e", "e" }   -- P_4 right: the inward offset passes left of it

local function offset_figure(name, d, caption)
  local f = figure{ name = name, caption = caption, width = W, height = H,
                    window = window }
  f:polygon(c, { })
  for i = 0, 4 do
    f:label(P[i + 1], string.format("P_%d", i), { place = place[i + 1] })
  end
  for t = 0.1, 0.95, 0.2 do
    f:arrow_to(c:eval(t), c:offset_point(t, d),
               { color = "grey", width = 0.5, arrow_size = 4 })
  end
  f:curve(c)
  f:curve((c:offset(d)), { color = "orange", width = 0.9, dash = "dashed" })
  local cusps = c:offset_cusps(d)
  for _, t in ipairs(cusps) do
    f:points({ c:offset_point(t, d) }, { marker = "cross", color = "red",
                                          marker_color = "red",
                                          marker_size = 6 })
  end
  local trimmed = c:offset(d, { trim = true })
  f:curve(trimmed, { color = "darkgreen", width = 1.8 })
  f:label({ window[1] + 0.2, window[4] - 0.2 },
          string.format("d = %g", math.abs(d)), { place = "se" })
  return f, cusps
end

local _, k1 = offset_figure("orazem-offset-1", 0.5,
  "Offset with the normal turned inward, d = 0.5: smaller than the " ..
  "smallest radius of curvature, the offset is regular (raw offset " ..
  "orange dashed, trimmed offset green) (Figure 1: Normala obrnjena " ..
  "navznoter, d = 0.5)")
assert(#k1 == 0)
local _, k2 = offset_figure("orazem-offset-2", 1.5,
  "Offset with the normal turned inward, d = 1.5: two cusps and a loop " ..
  "in the raw offset (orange dashed, cusps red), the trimmed offset " ..
  "green (Figure 2: Normala obrnjena navznoter, d = 1.5)")
assert(#k2 == 2)
local _, k3 = offset_figure("orazem-offset-3", 3,
  "Offset with the normal turned inward, d = 3: two cusps and no loop " ..
  "in the raw offset (orange dashed, cusps red); only the " ..
  "green part is at distance 3 from the curve (Figure 3: Normala " ..
  "obrnjena navznoter, d = 3)")
assert(#k3 == 2)
