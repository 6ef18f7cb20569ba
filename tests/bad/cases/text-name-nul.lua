-- expect: 1 "figure: name has a NUL byte at byte 1"
-- a NUL in a figure's name cut it (the files were named "a")
figure{ name = "a\0b" }
