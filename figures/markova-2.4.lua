-- markova-2.4 ... markova-2.6 (seed 002, "B-spline křivky", §2.3
-- "Vlastnosti plovoucích křivek", Obr. 2.4 "$p = 1$", Obr. 2.5
-- "$p = 2$", Obr. 2.6 "$p = 3$").
-- Clamped B-spline curves of degree p = 1, 2, 3 over one polygon, the
-- sample curve's P_0 ... P_7; "Čím nižší je stupeň, tím více se křivka
-- přibližuje ke svému řídicímu polygonu": p = 1 is the polygon itself,
-- p = 3 keeps farthest from it.  Knot points C(u_i) are marked: they cut
-- each curve into its pieces of degree p.  Knots:
--   p = 1: U = {0, 0, 1/7, 2/7, ..., 6/7, 1, 1} (clamped, equally spaced
--          interior knots, as docs/figures.md asks for p = 1 and 3);
--   p = 2: the sample curve's U = {0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83,
--          1, 1, 1} (seed data);
--   p = 3: U = {0, 0, 0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1, 1, 1}.
-- The three figures share window and size (and those of markova-2.1).

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local place = { "s", "se", "e", "n", "s", "n", "w", "sw" }
local U2 = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }

for p = 1, 3 do
  local s = p == 2 and bspline{ degree = 2, knots = U2, points = P }
                    or bspline{ degree = p, points = P, kind = "clamped" }
  local f = figure{
    name = "markova-2." .. (p + 3),
    caption = string.format("Clamped B-spline of degree p = %d on the sample "
      .. "polygon, knot points marked (Obr. 2.%d: p = %d)", p, p + 3, p),
    width = "6.5cm", height = "5.4cm", window = { 0.45, 5.55, 0.55, 4.45 },
  }
  f:polygon(P)
  f:curve(s)
  f:knots(s)
  f:points(P, { color = "#3c3c3c", marker_color = "#3c3c3c" })  -- on top
  for i, q in ipairs(P) do
    f:label(q, string.format("P_%d", i - 1), { place = place[i] })
  end
end
