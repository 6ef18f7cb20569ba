-- expect: 1 "figure: width = 5: give a unit, e.g. "5cm" (cm, mm, in; bp or pt: the PostScript point, 1/72 in; texpt: TeX's point, 1/72.27 in)"
-- a page width without a unit: 5 meant as cm would be a 5 bp page
local f = figure{ name = 'z', page = 'fixed', width = 5 }
