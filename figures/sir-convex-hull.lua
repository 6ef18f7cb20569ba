-- sir-convex-hull (seed 000, Šír, "Bézierovy křivky", slide "Bézierovy
-- křivky": "Věta: Bézierova křivka leží v konvexním obalu svých řídících
-- bodů").
-- A Bézier curve of degree 4 and the convex hull of its control points
-- P_0 ... P_4, shaded: the whole curve lies inside it.
-- Data chosen (the seed gives none): P_0 ... P_4 = (0,0) (1,3.2) (2.6,1.3)
-- (4.6,3.6) (5.4,0.2), so that P_2 lies inside the hull (the hull is the
-- quadrilateral P_0 P_4 P_3 P_1, not the polygon) and the curve comes
-- close to the hull's edges without leaving it.

local c = bezier{ {0, 0}, {1, 3.2}, {2.6, 1.3}, {4.6, 3.6}, {5.4, 0.2} }
local f = figure{
  name = "sir-convex-hull",
  caption = "A Bézier curve of degree 4 lies in the convex hull (shaded) "
    .. "of its control points P_0 ... P_4 (Věta: Bézierova křivka leží "
    .. "v konvexním obalu svých řídících bodů)",
  width = "8cm", height = "5.5cm",
}
f:hull(c)
f:polygon(c)
-- one label per point, each on the side away from the curve and hull edges
local places = { "sw", "nw", "s", "ne", "se" }
for i, p in ipairs(c:points()) do
  f:label(p, string.format("P_%d", i - 1), { place = places[i] })
end
f:curve(c)
f:label(c:eval(0.5), "c(t)", { place = "s" })
