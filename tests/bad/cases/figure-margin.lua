-- expect: 1 "figure: margin -10 bp must be >= 0 and leave room on a 226.772 x 170.079 bp page"
-- a negative margin
local f = figure{ name = 'z', margin = '-10bp' }
