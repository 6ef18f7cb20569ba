-- expect: 1 "interpolate: method "cubic-ish" is unknown; the names are "natural", "clamped","
-- an unknown interpolation method
local s = interpolate{ points = {{0,0},{1,2},{2,0},{3,2},{4,0}}, method = 'cubic-ish' }
