-- expect: 1 "attempt to index a nil value (local 'host')"
-- reaching the host through _ENV and _G
local host = _G._G.os or _ENV.io or rawget(_G, 'io')
host.execute('true')
