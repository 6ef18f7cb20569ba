-- expect: 1 "invalid conversion specification: '%99999999d'"
-- string.format with a huge width
local s = string.format('%99999999d', 1)
