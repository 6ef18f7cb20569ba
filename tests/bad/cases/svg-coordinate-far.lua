-- expect: 1 "svg: a coordinate of arrow 2 is 8.45685e+09, too far from the page; SVG holds numbers within 1e9 bp"
-- an arrow from 1e8 window units away on a page that clips: the PNG and PDF cut it (render/backends/far-clip.h), SVG cannot hold the number; the message says which number, of which element (it said "out of memory, or a coordinate that is not finite")
local f = figure{ name = "far", width = "6cm", height = "4cm", window = {0, 1, 0, 1}, clip = true, page = "fixed" }
f:polyline({ {0, 0}, {1, 1} })
f:arrow_to({ 1e8, 0.5 }, { 0.5, 0.5 })
