-- expect: 1 "is unknown; give"
-- a projection that is neither
local f = figure{ name = 'z', view = { 30, 20 }, projection = "isometric" }
