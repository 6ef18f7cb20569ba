-- expect: 1 "figure: the page of 5 x 170.079 bp leaves no room inside the margin of 14 bp"
-- a page too small for its margin names the page and the margin
local f = figure{ name = 'z', page = 'fixed', width = "5bp" }
