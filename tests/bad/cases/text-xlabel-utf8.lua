-- expect: 1 "plot: xlabel has invalid UTF-8 at byte 0 (0xC0)"
-- an overlong UTF-8 form in an axis label
local f = figure{ name = "c" }
f:plot{ x = { 0, 1 }, y = { 0, 1 }, xlabel = "\xC0\xAF" }
