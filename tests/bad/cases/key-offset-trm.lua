-- expect: 1 "offset: unknown option 'trm' (did you mean 'trim'?)"
-- a misspelt offset option
local c = bezier{ {0, 0}, {1, 2}, {2, 0} }
local o = c:offset(0.1, { trm = true })
