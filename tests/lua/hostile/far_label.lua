-- A label's offset of 1e300 bp.  The label placement turned its box into
-- pixel indices no int holds and read far outside its raster (SIGSEGV);
-- at 1e17 bp the label's box lost its width to rounding and the PDF and
-- PNG were written without the label, silently.
local f = figure{ name = "far", width = "6cm", height = "4cm", window = { 0, 1, 0, 1 } }
f:polyline({ { 0, 0 }, { 1, 1 } })
f:label({ 0.5, 0.5 }, "P", { offset = 1e300 })
