-- expect: 1 "interpolate: degree is -1; it must be in [0, 32]"
-- interpolation of degree -1
local s = interpolate{ points = {{0,0},{1,2},{2,0},{3,2},{4,0}}, method = 'global', degree = -1 }
