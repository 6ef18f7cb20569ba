-- expect: 1 "attempt to index a nil value (local 'host')"
-- reaching the host around the missing-name handler, with rawget
local host = rawget(_G, 'os') or rawget(_ENV, 'io')
host.execute('true')
