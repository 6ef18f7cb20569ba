-- expect: 1 "'loadfile' is not available to figure scripts"
-- loadfile
local f = loadfile('/etc/passwd')
