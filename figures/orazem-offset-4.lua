-- orazem-offset-4, orazem-offset-5 (seed 003, Oražem, "Bezierjeva
-- krivulja in njen odmik", section 4 "Odmik krivulje", Figure 4 "Normala
-- obrnjena navzven, d = 1" and Figure 5 "Normala obrnjena navzven,
-- d = 3").
--
-- The offset of the report's Bézier curve P_0..P_4 = (0,5) (1,-1) (3,0)
-- (4,3) (6,10) with the normal turned OUTWARD.  The curve turns left
-- everywhere (signed curvature > 0 on [0, 1], checked below), so its
-- centres of curvature are on the left (inward, see orazem-offset-1.lua)
-- and outward is the right normal: d < 0 in c:offset(d), the offset
-- c(t) - |d| n(t).  On this side the offset of a convex arc never
-- degenerates ("slika je veliko lepša, če normalo obrnemo navzven"): no
-- cusps, no loops, the trimmed offset equals the raw one.
-- Drawn as in orazem-offset-1 ... 3 (same window and size, same styles):
-- the curve and its polygon, outward normals of length |d| at t = 0.1,
-- 0.3, ..., 0.9 (grey arrows), the raw offset (orange, dashed, drawn
-- last) over the trimmed offset (light green, wide), which equals it
-- here; a legend (in Slovene) names them.

local P = { {0, 5}, {1, -1}, {3, 0}, {4, 3}, {6, 10} }
local c = bezier(P)

for i = 0, 100 do
  assert(c:curvature(i / 100) > 0, "the curve turns left everywhere")
end

local window = { -3.3, 9.2, -2.3, 11.1 }
local raw_colour, trimmed_colour = "#c8500a", "#92d192"
local W, H = "9cm", "9.65cm"
-- P_0 above (the outward offset starts left of it), P_4 left; P_3's
-- label goes below it, in the narrow gap between the leg P_2 P_3 and the
-- offset for d = 1
local place = { "n", "se", "s", false, "w" }

local function offset_figure(name, d, caption)
  local f = figure{ name = name, caption = caption, width = W, height = H,
                    window = window }
  f:polygon(c, { })
  for i = 0, 4 do
    if place[i + 1] then
      f:label(P[i + 1], string.format("P_%d", i), { place = place[i + 1] })
    end
  end
  f:label({ P[4][1] + 0.14, P[4][2] - 0.5 }, "P_3", { place = "center" })
  for t = 0.1, 0.95, 0.2 do
    f:arrow_to(c:eval(t), c:offset_point(t, d),
               { color = "grey", width = 0.5, arrow_size = 4 })
  end
  f:curve(c)
  -- the trimmed offset wide and light under the raw one, thin and dashed,
  -- so that both are seen where they coincide (here everywhere)
  local trimmed, report = c:offset(d, { trim = true })
  f:curve(trimmed, { color = trimmed_colour, width = 2.6,
                     legend = "\\text{obrezan odmik}" })
  f:curve((c:offset(d)), { color = raw_colour, width = 0.9, dash = "dashed",
                           legend = "\\text{odmik} $c(t) - |d|\\, n(t)$" })
  f:label({ window[1] + 0.2, window[4] - 0.2 },
          string.format("d = %g", math.abs(d)), { place = "se" })
  assert(#c:offset_cusps(d) == 0 and report.trimmed_chains == 1)
  return f
end

offset_figure("orazem-offset-4", -1,
  "Offset with the normal turned outward, d = 1: a regular curve, the " ..
  "trimmed offset (light green, beneath the raw one, orange dashed) is " ..
  "the whole raw offset (Figure 4: Normala obrnjena navzven, d = 1)")
offset_figure("orazem-offset-5", -3,
  "Offset with the normal turned outward, d = 3: still regular, no " ..
  "cusps or loops (Figure 5: Normala obrnjena navzven, d = 3)")
