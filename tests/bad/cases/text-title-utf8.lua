-- expect: 1 "figure: title is not valid UTF-8 at byte 2 (byte 0xFF)"
-- invalid UTF-8 in a title made the SVG ill-formed XML
figure{ name = "c", title = "x\255y" }
