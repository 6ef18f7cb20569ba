-- Rational triangular patches (tests/surfaces/test_surface_figures.c):
-- every boundary and iso-line must lie on its patch and be hidden where
-- the ray caster finds it hidden.  A cubic patch with unequal weights
-- (0.25 to 8) in front of a rational bicubic patch, and a quadratic one
-- through it; weights on the corners, the edges and inside.

local t3 = bezier_triangle{ degree = 3, points = {
  {-0.8, -0.8, 1.6}, {-0.2, -0.8, 1.8}, {0.4, -0.8, 1.7}, {1.0, -0.8, 1.6},
  {-0.8, -0.2, 1.8}, {-0.2, -0.2, 2.2}, {0.4, -0.2, 1.9},
  {-0.8, 0.4, 1.7}, {-0.2, 0.4, 1.9},
  {-0.8, 1.0, 1.6} },
  weights = { 1, 0.5, 2, 1, 3, 8, 0.7, 1.5, 0.25, 2 } }

local t2 = bezier_triangle{ degree = 2, points = {
  {1.2, -1.2, -0.5}, {0.3, -0.4, 1.6}, {1.3, 0.8, 0.2},
  {-0.8, 0.2, 2.0}, {0.2, 1.0, 1.4}, {-1.0, 1.3, -0.3} },
  weights = { 2, 1, 0.5, 4, 1, 1 } }

local P, W = {}, {}
for i = 0, 3 do
  P[i + 1], W[i + 1] = {}, {}
  for j = 0, 3 do
    P[i + 1][j + 1] = { -1.2 + 0.8 * i, -1.2 + 0.8 * j,
                        0.5 * math.sin(1.3 * i) * math.cos(0.9 * j) }
    W[i + 1][j + 1] = 1 + 0.6 * ((i + 2 * j) % 3)
  end
end
local s = bezier_surface{ points = P, weights = W }

local f = figure{
  name = "rational-triangles",
  width = "8cm", height = "6cm",
  view = { -60, 30 },
}
f:surface(s, { isolines = { 3, 3 }, hidden = "dashed" })
f:surface(t3, { isolines = { 3, 3 }, hidden = "dashed", color = "red" })
f:surface(t2, { isolines = { 2, 2 }, hidden = "dashed", color = "blue" })
