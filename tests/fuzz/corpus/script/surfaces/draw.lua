-- f:surface's options on small patches, without silhouettes (a
-- silhouette takes half a second an execution in the fuzz build:
-- silhouette.lua has one); the figures of figures/surfaces/ take seconds
-- and seed only the replay (tests/fuzz/figure-seeds.py)
local P = { { {0, 0, 0}, {1, 0, 0.5}, {2, 0, 0} },
            { {0, 1, 0.5}, {1, 1, 1.5}, {2, 1, 0.5} },
            { {0, 2, 0}, {1, 2, 0.5}, {2, 2, 0} } }
local s = bezier_surface{ points = P }
local b = bspline_surface{ degree = {2, 1}, knots = { {0,0,0,1,1,1}, {0,0,0.5,1,1} }, points = P }
local f = figure{ name = "seed-surface-draw", width = "4cm", height = "4cm", view = { 30, 20 } }
f:surface(s, { isolines = { 1, 1 }, silhouette = false, hidden = "dashed", net = true })
f:surface(b, { isolines = { u = { 0.5 }, v = {} }, knot_lines = true, boundary = false, silhouette = false, hidden = "show", occludes = false })
