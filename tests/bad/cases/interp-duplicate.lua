-- expect: 1 "interpolate: points 0 and 1 coincide (0, 0); chord-length parameters"
-- chord-length interpolation through coincident points
local s = interpolate{ points = {{0, 0}, {0, 0}, {1, 1}}, param = 'chord' }
