-- expect: 1 "plot: xlabel is not valid UTF-8 at byte 1 (byte 0xC0)"
-- an overlong UTF-8 form in an axis label
local f = figure{ name = "c" }
f:plot{ x = { 0, 1 }, y = { 0, 1 }, xlabel = "\xC0\xAF" }
