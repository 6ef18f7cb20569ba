-- overlay-deboor (seed 002, "B-spline křivky", chapter 3, section 3.2
-- "De Boorův algoritmus", Obr. 3.6 "Výpočet nových bodů"; the net of
-- markova-3.6 shown column by column, as overlay steps for slides).
--
-- DATA NOT IN THE SEED, as markova-3.5.lua explains: the thesis' sample
-- points P_0..P_7 with degree p = 3 and the clamped knot vector
--     U = {0, 0, 0, 0, 0.25, 0.4, 0.7, 0.85, 1, 1, 1, 1},
-- u = 0.5 in the span [u_5, u_6), k = 5, s = 0.  One column per step:
--   step 1  the curve, its polygon and the p + 1 = 4 points P_2..P_5
--           that act on the span (dark);
--   step 2  column 1: P_{3,1} P_{4,1} P_{5,1} (blue);
--   step 3  column 2: P_{4,2} P_{5,2} (orange);
--   step 4  column 3: P_{5,3} = C(u) (red star).
-- Colours, window and size those of markova-3.6 (the close-up of the
-- region of P_2..P_5; the polygon and the curve are clipped to it).

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local U = { 0, 0, 0, 0, 0.25, 0.4, 0.7, 0.85, 1, 1, 1, 1 }
local s = bspline{ degree = 3, knots = U, points = P }
local u = 0.5
local L, k, mult = s:deboor(u)
assert(k == 5 and mult == 0 and #L == 4)
local level_color = { "black", "blue", "orange", "red" }
local place = { "s", "w", "e", "n", "s", "n", "w", "e" }

local f = figure{
  name = "overlay-deboor",
  caption = "De Boor's algorithm at u = 0.5 (p = 3), column by column in " ..
            "four overlay steps: P_2 ... P_5, then P_{i,1} (blue), " ..
            "P_{i,2} (orange) and P_{5,3} = C(u) (red)",
  width = "16cm", height = "7.35cm", window = { 1.85, 5.15, 2.85, 4.25 },
}
f:polygon(s, { color = "grey", marker_color = "grey" })
f:curve(s, { color = "#9fb0d0", width = 1.2 })
f:polyline(L[1], { color = "black", width = 1.0 })
for i = 2, 5 do
  f:label(P[i + 1], string.format("P_%d", i), { place = place[i + 1] })
end
local lplace = {
  [1] = { "ne", "nw", "sw" },
  [2] = { "n", "nw" },
  [3] = { "se" },
}
for j = 1, 3 do
  local step = (j + 1) .. "-"
  if j < 3 then
    f:polygon(L[j + 1], { color = level_color[j + 1], width = 0.9,
                          marker_color = level_color[j + 1],
                          visible = step })
  else
    f:points(L[4], { marker = "star", color = "red", marker_color = "red",
                     marker_size = 9, visible = step })
  end
  for i, q in ipairs(L[j + 1]) do
    local text = string.format("P_{%d,%d}", k - 3 + j + i - 1, j)
    if j == 3 then text = text .. " = C(u)" end
    f:label(q, text, { place = lplace[j][i], color = level_color[j + 1],
                       visible = step })
  end
end
