-- expect: 1 "figure: title has invalid UTF-8 at byte 1 (0xFF)"
-- invalid UTF-8 in a title made the SVG ill-formed XML
figure{ name = "c", title = "x\255y" }
