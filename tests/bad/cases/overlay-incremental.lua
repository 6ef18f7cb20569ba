-- expect: 1 "polygon: visible = "+-": "+-": incremental specifications ("+-", ".-") are not supported"
-- beamer's incremental specifications need a frame's counter
local f = figure{ name = 'z' }
f:polygon({ { 0, 0 }, { 1, 1 }, { 2, 0 } }, { visible = '+-' })
