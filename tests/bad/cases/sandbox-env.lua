-- expect: 1 "'os' is not available to figure scripts (the sandbox has no io, os,"
-- reaching the host through _ENV and _G
local host = _G._G.os or _ENV.io or rawget(_G, 'io')
host.execute('true')
