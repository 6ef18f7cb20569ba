-- expect: 1 "figure: legend_place "nee" is unknown (did you mean "ne"?)"
-- a legend place misspelt
local f = figure{ name = 'z', legend_place = 'nee' }
