-- expect: 1 "label 1 "P_0 = start" (line 4) sticks out of the 10.0 x 10.0 mm page by"
-- ink outside a fixed page is an error naming the element and how far it sticks out
local f = figure{ name = 'z', page = 'fixed', width = '1cm', height = '1cm', margin = '1mm', window = {0, 1, 0, 1} }
f:label({0.9, 0.5}, 'P_0 = start')
