-- expect: 1 "figure: the page of 5 x 170.079 bp leaves no room inside the margin of 14 bp (a bare number is in bp; give a unit"
-- a page width without unit blames the page, not the margin
local f = figure{ name = 'z', page = 'fixed', width = 5 }
