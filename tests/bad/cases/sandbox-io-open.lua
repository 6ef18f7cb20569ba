-- expect: 1 "attempt to index a nil value (global 'io')"
-- io.open
local f = io.open('/etc/passwd')
