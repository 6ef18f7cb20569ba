-- Points and lines in space among surfaces (tests/surfaces/
-- test_surface_figures.c checks every piece and point against the ray
-- caster): a polyline that pierces a bent patch and runs behind it, a
-- closed polygon about it, a segment through it (f:line), points and
-- labelled points in front of and behind it, two arrows (split as a
-- segment, the head following the tip), hidden pieces dashed,
-- removed and shown.

local P = {
  { {-1, -1, 0},   {-1, 0, 0.8}, {-1, 1, 0} },
  { {0, -1, 0.4},  {0, 0, 1.2},  {0, 1, 0.4} },
  { {1, -1, 0},    {1, 0, 0.8},  {1, 1, 0} },
}
local s = bezier_surface{ points = P }

local f = figure{
  name = "space-lines",
  width = "8cm", height = "6cm",
  view = { -60, 30 },
}
f:surface(s, { isolines = { 4, 4 }, hidden = "dashed" })
f:polyline({ {-1.4, -0.6, -0.4}, {0.2, 0.1, 1.4}, {1.3, 0.7, -0.5},
             {-0.2, 1.2, -0.3} }, { hidden = "dashed", color = "red" })
f:polyline({ {-1.2, -1.3, 0.2}, {1.2, -1.2, 0.9}, {1.1, 1.3, 0.1},
             {-1.3, 1.1, 0.7} }, { closed = true, hidden = "remove",
                                   color = "blue" })
f:line({ -0.3, -0.3, -0.6 }, { 0.4, 0.5, 1.6 }, { color = "green" })
f:polygon({ {-0.8, 0.9, -0.4}, {0.1, 0.3, 1.5}, {0.9, -0.9, -0.2} },
          { hidden = "show" })
f:points({ {0.2, 0.1, 1.4}, {0, 0, -0.5}, {0.5, -0.5, 1.2},
           {-0.5, 0.4, -0.2} }, { labels = "Q_%d" })
f:label({ 0.1, -0.1, -0.4 }, "behind", { hidden = "dashed" })
-- arrows: one whose shaft pierces the patch up to a tip in front of it,
-- one whose tip lies behind it (its head faded)
f:arrow_to({ 0.5, -0.6, -0.6 }, { -0.2, 0.3, 1.7 }, { color = "orange",
                                                      label = "a" })
f:arrow_to({ 0.7, -0.2, 1.6 }, { 0.2, 0.3, -0.3 }, { color = "purple" })
