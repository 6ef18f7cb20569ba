-- expect: 1 "figure: caption must be a string, got table"
-- a caption that is not text names the option
local f = figure{ name = 'z', caption = { 'a' } }
