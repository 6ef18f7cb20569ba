-- expect: 2 "bad format list 'svg,bmp' (use svg, pdf, png, ps, eps, pgf, html or all,"
-- an unknown format
-- args: -f svg,bmp
figure{ name = 'z' }
