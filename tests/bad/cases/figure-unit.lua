-- expect: 1 "figure: width "8furlong": give a number and a unit (bp, pt, texpt,"
-- an unknown unit
local f = figure{ name = 'z', width = '8furlong' }
