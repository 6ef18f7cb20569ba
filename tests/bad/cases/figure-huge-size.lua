-- expect: 1 "figure: figure size 2.83465e+10 x 170.079 bp exceeds 14400 bp (200 in)"
-- a figure 1e9 cm wide
local f = figure{ name = 'z', width = '1e9cm' }
f:curve(bezier{ {0, 0}, {1, 1} })
