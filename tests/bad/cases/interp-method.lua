-- expect: 1 "interpolate: method: unknown interpolation method "cubic-ish";"
-- an unknown interpolation method
local s = interpolate{ points = {{0,0},{1,2},{2,0},{3,2},{4,0}}, method = 'cubic-ish' }
