-- expect: 1 "figure: width "8furlong": give a number and a unit, e.g. "8cm" (cm, mm, in; bp or pt: the PostScript point, 1/72 in; texpt: TeX's point, 1/72.27 in)"
-- an unknown unit
local f = figure{ name = 'z', width = '8furlong' }
