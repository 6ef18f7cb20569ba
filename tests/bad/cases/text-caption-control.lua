-- expect: 1 "figure: caption has the control character U+0001 at byte 1"
-- a C0 control character in a caption made the SVG ill-formed XML
figure{ name = "c", caption = "x\1y" }
