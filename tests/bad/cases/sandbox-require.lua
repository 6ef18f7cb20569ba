-- expect: 1 "attempt to call a nil value (global 'require')"
-- require of a module
local m = require('os')
