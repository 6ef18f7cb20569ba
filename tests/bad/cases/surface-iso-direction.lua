-- expect: 1 "iso: direction "U" is neither "u" nor "v" (did you mean "u"?)"
-- an iso-curve direction other than "u" or "v"
local s = nurbs_sphere{ r = 1 }
local c = s:iso("U", 0.5)
