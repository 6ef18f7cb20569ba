-- expect: 1 "label: visible = "0-2": step 0: steps count from 1"
-- beamer's steps count from 1
local f = figure{ name = 'z' }
f:label({ 0, 0 }, 'A', { visible = '0-2' })
