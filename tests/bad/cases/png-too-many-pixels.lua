-- expect: 1 "PNG of 11812 x 11812 pixels is too large (at most 67 million pixels, 256 MiB)"
-- a 1 m square page at 300 dpi: 558 MB of pixels
-- args: --dpi 300 -f png
figure{ name = "p", width = "100cm", height = "100cm" }:points{ {0, 0}, {1, 1} }
