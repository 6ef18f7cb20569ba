-- Regions in space for the memory-budget sweep (test_budget_sweep.c):
-- a shaded bent patch, a quad through it, a self-crossing fill (the
-- nonzero rule's signed fan) and a hull partly behind it, each split by
-- the hidden-line core, with labels placed round them.

local s = bezier_surface{ points = {
  { {-1, -1, 0},  {-1, 0, 0.8}, {-1, 1, 0} },
  { {0, -1, 0.4}, {0, 0, 1.2},  {0, 1, 0.4} },
  { {1, -1, 0},   {1, 0, 0.8},  {1, 1, 0} },
} }

local f = figure{
  name = "budget-regions",
  width = "6cm", height = "4.5cm",
  view = { -60, 30 },
}
f:surface(s, { isolines = { 2, 2 }, hidden = "dashed", fill = "#dde6f2" })
f:fill({ {-1.3, -0.3, 0.3}, {1.3, -0.3, 0.3}, {1.3, 0.4, 0.9},
         {-1.3, 0.4, 0.9} }, { fill = "red", opacity = 0.6 })
f:fill({ {-0.9, -0.9, 1.3}, {0.9, 0.9, 1.5}, {0.9, -0.9, 1.3},
         {-0.9, 0.9, 1.5} }, { fill = "orange", opacity = 0.7 })
f:hull({ {0.3, 0.3, -0.6}, {1.2, 0.4, -0.5}, {0.4, 1.3, -0.4},
         {0.8, 0.8, 0.5}, {0.9, 0.2, 0.1} },
       { fill = "blue", opacity = 0.5, hidden = "dashed" })
f:points({ {0.8, 0.8, 0.5}, {-0.9, 0.9, 1.5} }, { labels = "A_%d" })
