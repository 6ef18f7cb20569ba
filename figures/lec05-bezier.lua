-- lec05-bezier (seed 004, "Lec05 Bezier曲线 B样条曲线", §Bezier曲线,
-- image/3.png: "n次Bezier曲线：n+1 个控制顶点, x(t) = Σ B_i^n(t) b_i ...
-- 由控制顶点b_i来控制多边形").
-- A Bézier curve of degree n = 5 with its n + 1 = 6 control points
-- b_0 ... b_5 (the seed's notation) and its control polygon.
-- Data chosen (the seed's image is missing): b_0 ... b_5 = (0,0.4)
-- (0.8,3) (3,3.6) (3.8,0) (6,0.6) (6.6,3.2).

local c = bezier{ {0, 0.4}, {0.8, 3}, {3, 3.6}, {3.8, 0}, {6, 0.6}, {6.6, 3.2} }
local f = figure{
  name = "lec05-bezier",
  caption = "A Bézier curve x(t) = Σ B_i^5(t) b_i of degree 5 with its "
    .. "control polygon b_0 ... b_5 (Bezier曲线)",
  width = "9cm", height = "5cm",
}
f:polygon(c)
f:curve(c)
local places = { "w", "nw", "ne", "s", "se", "e" }
for i, p in ipairs(c:points()) do
  f:label(p, string.format("b_%d", i - 1), { place = places[i] })
end
f:label(c:eval(0.3), "x(t)", { place = "s", offset = 7 })
