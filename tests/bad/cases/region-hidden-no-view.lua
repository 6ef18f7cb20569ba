-- expect: 1 "hull: hidden needs a region in R^3 in a figure with a view; give figure{view = {azimuth, elevation}, ...}"
-- hidden on a hull in a figure without a view
local f = figure{ name = 'z' }
f:hull({ {0, 0, 0}, {1, 0, 0}, {0, 1, 1} }, { hidden = 'remove' })
