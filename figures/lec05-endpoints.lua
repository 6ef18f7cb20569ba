-- lec05-endpoints (seed 004, "Lec05 Bezier曲线 B样条曲线", 性质4. 端点插值性,
-- image/2.png: "可由该性质得出Bezier曲线经过首末两个控制顶点" - the Bézier
-- curve passes through its first and last control points; and in §Bezier
-- 曲线: "Bezier曲线端点的切线方向与边相同" - at the end points the
-- curve's tangent has the direction of the end legs).
-- A cubic x(t) = Σ B_i^3(t) b_i (the seed's notation b_i for control
-- points): it starts at x(0) = b_0 and ends at x(1) = b_3, and there it is
-- tangent to the legs b_0b_1 and b_2b_3 (highlighted, continued as
-- dashed lines); the end tangent vectors x'(0) = 3(b_1 − b_0) and
-- x'(1) = 3(b_3 − b_2) are drawn at 1/3 scale, i.e. exactly along the legs.
-- Data chosen (the seed's image is missing): b_0 ... b_3 = (0,0) (1.2,2.6)
-- (4.6,3.2) (5.6,0.6).

local c = bezier{ {0, 0}, {1.2, 2.6}, {4.6, 3.2}, {5.6, 0.6} }
local b = c:points()
local red = "#c0392b"

local f = figure{
  name = "lec05-endpoints",
  caption = "End-point interpolation: the curve passes through b_0 and b_3 "
    .. "and is tangent there to the end legs b_0b_1 and b_2b_3 (端点插值性)",
  width = "9cm", height = "5.5cm",
}
-- the end legs continued as dashed lines
local function extended(p, q, a, z)
  local d = { q[1] - p[1], q[2] - p[2] }
  f:line({ p[1] - a * d[1], p[2] - a * d[2] }, { q[1] + z * d[1], q[2] + z * d[2] },
         { color = red, dash = "dashed", width = 0.7 })
end
extended(b[1], b[2], 0.3, 0.25)
extended(b[3], b[4], 0.25, 0.3)
f:polygon(c)
f:line(b[1], b[2], { color = red, width = 1.4 })
f:line(b[3], b[4], { color = red, width = 1.4 })
f:curve(c)
f:tangent(c, 0, { scale = 1 / 3, color = red, width = 1.6 })
f:tangent(c, 1, { scale = 1 / 3, color = red, width = 1.6 })
f:points({ b[1], b[4] }, { marker = "dot", marker_size = 6, color = "black",
                         marker_color = "black" })
f:label(b[1], "x(0) = b_0", { place = "e" })
f:label(b[2], "b_1", { place = "nw" })
f:label(b[3], "b_2", { place = "ne" })
f:label(b[4], "x(1) = b_3", { place = "sw" })
f:label(c:eval(0.5), "x(t)", { place = "s" })
