-- expect: 1 "unknown name 'ctrl_pts' (did you mean 'ctrl_pt'?)"
-- a misspelt local is suggested from the locals in scope
local ctrl_pt = { {0, 0}, {1, 2}, {2, 0} }
local c = bezier(ctrl_pts)
