-- the silhouette of a biquadratic patch, its hidden part dashed
local s = bezier_surface{ points = {
  { {0, 0, 0}, {1, 0, 0.5}, {2, 0, 0} },
  { {0, 1, 0.5}, {1, 1, 1.5}, {2, 1, 0.5} },
  { {0, 2, 0}, {1, 2, 0.5}, {2, 2, 0} } } }
local f = figure{ name = "seed-surface-silhouette", width = "4cm", height = "4cm", view = { 30, 20 } }
f:surface(s, { isolines = { 0, 0 }, hidden = "dashed" })
