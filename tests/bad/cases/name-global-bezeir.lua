-- expect: 1 "unknown name 'bezeir' (did you mean 'bezier'?)"
-- a misspelt global
local c = bezeir{ {0, 0}, {1, 2}, {2, 0} }
