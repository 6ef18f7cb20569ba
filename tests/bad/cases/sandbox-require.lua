-- expect: 1 "'require' is not available to figure scripts"
-- require of a module
local m = require('os')
