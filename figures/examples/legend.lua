-- A legend: every drawing method takes legend = "..." and the figure
-- collects the entries, each with a sample of its line, fill or marker as
-- drawn, in a box placed where nothing is drawn (legend_place = "ne" etc.
-- names a corner instead; legend_frame = false leaves the frame out).
local f = figure{ name = "example-legend", width = "8cm", height = "5.5cm",
                  caption = "Two Bézier cubics with a common start and " ..
                            "their legend" }
local P = { {0, 0}, {1, 3}, {4, 3.5}, {6, 0.5} }
f:polygon(P, { legend = "control polygon $P_0 \\ldots P_3$" })
local c = bezier(P)
f:curve(c, { legend = "Bézier cubic $c(t)$" })
f:curve(bezier{ {0, 0}, {1, 3}, {5.5, 2}, {6, 0.5} },
        { dash = "dashed", color = "red",
          legend = "$P_2$ moved: $\\tilde{c}(t)$" })
f:points({ c:eval(0.5) }, { marker = "star", color = "darkgreen",
                            marker_size = 8, legend = "$c(1/2)$" })
