-- expect: 1 "out of memory for the PNG's 5556 x 5556 pixels (118 MiB)"
-- a PNG whose pixels alone need more than the memory limit: they are taken from the script's budget
-- args: --max-memory 64 -f png --dpi 200
-- max-rss: 80
local f = figure{ name = "wide", width = "2000bp", height = "2000bp" }
f:curve(bezier{ {0, 0}, {1, 1} })
