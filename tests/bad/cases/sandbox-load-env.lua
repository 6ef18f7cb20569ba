-- expect: 1 "attempt to index a nil value (local 'io2')"
-- load with a custom environment reaching io
local f = load('return io', 'x', 't', {})
local io2 = f()
io2.open('/etc/passwd')
