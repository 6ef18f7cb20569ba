-- sir-reduction (seed 000, Šír, "Bézierovy křivky": the slide pair of
-- degree elevation, P_n ⊂ P_{n+1}; its converse, degree reduction).
-- Reduction is not exact: a quintic has no cubic form, and the best cubic
-- depends on how the error is measured.
-- (a) the quintic c(t) with its polygon P_0 ... P_5 (grey) and the cubic r(t)
-- nearest to it in L2 keeping the end points (C^0 ends; blue, polygon
-- Q_0 ... Q_3).
-- (b) the error |c(t) − r(t)| over t for the L2 cubic and for the
-- near-best uniform (L∞) cubic with the same ends (orange): the uniform
-- one has the smaller maximum, spread evenly over the curve; the dashed
-- lines, in the same colours, are the certified bounds of the two (each
-- cubic elevated back to degree 5 and the difference of the polygons
-- bounded on 32 de Casteljau pieces).  Labels on the curves, not legends:
-- a legend beside the panels would widen the page.
-- The reports: L2 max 0.3300, bound 0.3312, polygon bound (the two
-- polygons compared without the pieces) 2.1165, L2 error 0.1719; uniform
-- max 0.2574, bound 0.2577, polygon bound 2.2316, L2 error 0.1838.
-- Data chosen (the seed gives none): P_0 ... P_5 = (0,0) (0.4,2.8)
-- (2,3.6) (3,0.4) (4.6,3) (5.6,0.8), reduction by 2 degrees.

local P = { {0, 0}, {0.4, 2.8}, {2, 3.6}, {3, 0.4}, {4.6, 3}, {5.6, 0.8} }
local c = bezier(P)
local r, rep = c:reduce{ by = 2, continuity = 0 }
local u, urep = c:reduce{ by = 2, continuity = 0, method = "uniform" }

local f = figure{
  name = "sir-reduction",
  caption = "Degree reduction 5 → 3 keeping the end points: (a) the "
    .. "quintic and its polygon P_0 … P_5, the L2-nearest cubic and its "
    .. "polygon Q_0 … Q_3; (b) the error |c(t) − r(t)| of the L2 and the "
    .. "uniform (L∞) reductions, with the certified bound of each (dashed)",
  width = "12cm", height = "11cm",
}
local top, bottom = f:panels{ rows = 2, cols = 1,
  titles = { "(a) $c$ of degree 5, $r$ of degree 3",
             "(b) $|c(t) - r(t)|$" } }

-- Q_0 = P_0 and Q_3 = P_5 (the ends are kept): one label each
top:polygon(c, { labels = { "P_0 = Q_0", "P_1", "P_2", "P_3", "P_4",
                            "P_5 = Q_3" } })
top:polygon(r, { color = "blue", marker_color = "blue", width = 0.8,
                 labels = { false, "Q_1", "Q_2", false },
                 label_place = { "w", "nw", "n", "e" },
                 label_style = { color = "blue" } })
top:curve(c)
top:curve(r, { color = "blue" })
top:label(c:eval(0.6), "c(t)", { place = "s" })
top:label(r:eval(0.35), "r(t)", { place = "n", color = "blue" })

local function dist(a, t)
  local p, q = c:eval(t), a:eval(t)
  return math.sqrt((p[1] - q[1])^2 + (p[2] - q[2])^2)
end
local ymax = 1.15 * math.max(rep.bound, urep.bound)
bottom:plot{ x = {0, 1}, y = {0, ymax}, xticks = 0.25, xlabel = "t" }
bottom:func(function (t) return dist(r, t) end, 0, 1,
            { color = "blue", width = 1.5 })
bottom:func(function (t) return dist(u, t) end, 0, 1,
            { color = "orange", width = 1.5 })
bottom:line({0, rep.bound}, {1, rep.bound}, { color = "blue", dash = "dashed",
                                              width = 0.8 })
bottom:line({0, urep.bound}, {1, urep.bound},
            { color = "orange", dash = "dashed", width = 0.8 })
bottom:label({0.55, dist(r, 0.55)}, "L^2", { place = "s", color = "blue" })
bottom:label({0.575, dist(u, 0.575)}, "L^\\infty", { place = "n",
                                                 color = "orange" })

