-- expect: 1 "label_style: unknown option 'visible'"
-- steps belong to the drawing method, not to a nested style
local f = figure{ name = 'z' }
f:points({ { 0, 0 } }, { labels = { 'A' }, label_style = { visible = '2' } })
