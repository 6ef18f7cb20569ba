-- expect: 1 "slider: label has the control character U+0001 at byte 1"
-- a control character in a slider's label reached the live page's JSON
slider{ name = "t", label = "a\1" }
