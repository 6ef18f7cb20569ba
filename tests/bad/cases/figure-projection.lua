-- expect: 1 "figure: 1 projection row given, at least 2 needed"
-- a projection matrix of the wrong shape
local f = figure{ name = 'z', projection = {{1, 0, 0}} }
