-- surfaces/triangle: a cubic triangular Bézier patch with its net P_ijk
-- (i + j + k = 3, each point labelled) and the de Casteljau scheme at
-- (u, v, w) = (1/3, 1/3, 1/3): the points of levels 1 and 2 in colours,
-- T(u, v, w) marked.

local b = {
  {0, 0, 0},                                        -- b300
  {1, 0.5, 1.2}, {1, -0.5, 0.8},                    -- b210 b201
  {2, 1, 1.0}, {2, 0, 1.6}, {2, -1, 0.6},           -- b120 b111 b102
  {3, 1.5, 0}, {3, 0.5, 0.9}, {3, -0.5, 0.7}, {3, -1.5, 0},  -- b030 .. b003
}
local t = bezier_triangle{ degree = 3, points = b }

local f = figure{
  name = "surfaces-triangle",
  caption = "A cubic triangular Bézier patch with its net and the de "
    .. "Casteljau scheme at u = v = w = 1/3",
  width = "9cm", height = "7cm",
  view = { -100, 35 },
}
-- P_030 and P_102 are labelled apart.  Around P_030's corner the boundary,
-- the net and the scheme's level-1 point leave no room at the labels'
-- offset; 10 bp above it, between the boundary and the net's edges to
-- P_021, there is (the point lies behind the patch: its label shown all
-- the same, as the net's).  P_102 lies on the patch's iso-lines above and
-- below it; to its west there is room.
f:surface(t, { isolines = { 3, 3 }, hidden = "dashed",
               net = { color = "grey" },
               labels = function(i, j, k)
                 if not (i == 0 and j == 3) and not (i == 1 and j == 0) then
                   return string.format("P_{%d%d%d}", i, j, k)
                 end
               end,
               label_style = { font_size = 7 } })
f:triangle_scheme(t, 1/3, 1/3, { width = 0.6 })
f:label(b[7], "P_{030}", { font_size = 7, place = "n", offset = 10,
                           hidden = "show" })
f:label(b[6], "P_{102}", { font_size = 7, place = "w" })
