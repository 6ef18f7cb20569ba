-- expect: 2 "--dpi '0': give a number from 1 to 2400"
-- --dpi 0
-- args: --dpi 0
figure{ name = 'z' }
