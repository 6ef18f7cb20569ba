-- expect: 1 "'io' is not available to figure scripts"
-- io.open
local f = io.open('/etc/passwd')
