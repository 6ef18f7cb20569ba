-- expect: 1 "attempt to call a nil value (global 'loadfile')"
-- loadfile
local f = loadfile('/etc/passwd')
