-- expect: 1 "needs distance (the eye's distance from the target)"
-- a perspective view without its distance
local f = figure{ name = 'z', view = { 30, 20 }, projection = "perspective" }
