-- expect: 1 "points-figure-misspelt.lua:3: points 'P' (line 3): figure = 'markova' names no figure of the script (did you mean 'markov'?)"
-- points{} dragged in a figure the script does not define: render wrote the figure and said nothing (only live refused the script, without the nearest name), so the typo showed in the lecture hall, as points that cannot be dragged
local P = points{ name = "P", default = { {0, 0}, {1, 1} },
                  figure = "markova" }
local f = figure{ name = "markov", width = "4cm", height = "3cm", window = {-2, 2, -2, 2} }
f:polyline(P)
