-- the de Casteljau schemes of a patch and of a triangle, and a shaded
-- triangle
local s = bezier_surface{ points = { { {0, 0, 0}, {1, 0, 0.5} }, { {0, 1, 0.5}, {1, 1, 0} } } }
local t = bezier_triangle{ degree = 2, points = { {0,0,0}, {1,0.5,1}, {1,-0.5,0.5}, {2,1,0}, {2,0,1}, {2,-1,0} } }
local f = figure{ name = "seed-surface-scheme", width = "4cm", height = "4cm", view = { -100, 35 } }
f:decasteljau_surface(s, 0.5, 0.5, { colors = { "red", "blue" } })
f:surface(t, { isolines = { 0, 0 }, silhouette = false, hidden = "remove", fill = "#88aacc", shade = "flat" })
f:triangle_scheme(t, 1/3, 1/3, { width = 0.6 })
