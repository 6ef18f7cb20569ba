-- lec05-convex-hull (seed 004, "Lec05 Bezier曲线 B样条曲线", 性质1. 正权性,
-- image/1.png: "给定二维平面上的点集，凸包就是将最外层的点连接起来构成的
-- 凸多边形，它能包含点集中所有的点" - given a planar point set, the convex
-- hull is the convex polygon joining the outermost points; it contains
-- every point of the set).
-- A planar set of 16 points and its convex hull: the hull shaded and
-- outlined, its vertices (the outermost points) drawn larger and darker
-- than the inner points.
-- Data chosen (the seed's image is missing): the 16 points below.

local pts = {
  {0.2, 1.1}, {1.0, 3.1}, {1.6, 0.3}, {2.3, 2.2}, {2.9, 4.0}, {3.1, 1.2},
  {3.8, 2.9}, {4.4, 0.1}, {4.7, 2.0}, {5.3, 3.6}, {5.9, 1.0}, {6.4, 2.6},
  {1.5, 1.6}, {3.6, 3.5}, {2.6, 0.8}, {5.2, 2.7},
}
local hull = convex_hull(pts)

local f = figure{
  name = "lec05-convex-hull",
  caption = "A planar point set and its convex hull: the convex polygon "
    .. "through the outermost points contains every point of the set (凸包)",
  width = "8cm", height = "5.5cm",
}
f:hull(pts)
f:polyline(hull, { closed = true, color = "#1f5fbf", width = 1.4 })
f:points(pts, { marker = "dot", marker_size = 4, color = "grey", marker_color = "grey" })
f:points(hull, { marker = "dot", marker_size = 5.5, color = "black", marker_color = "black" })
