-- expect: 1 "'debug' is not available to figure scripts"
-- the debug library
debug.sethook()
