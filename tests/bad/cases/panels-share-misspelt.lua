-- expect: 1 "panels: unknown option 'share_z' (did you mean 'share_x'?)"
-- a sharing option misspelt
local f = figure{ name = 'z' }
f:panels{ rows = 2, share_z = true }
