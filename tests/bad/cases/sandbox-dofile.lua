-- expect: 1 "'dofile' is not available to figure scripts"
-- dofile
dofile('/etc/passwd')
