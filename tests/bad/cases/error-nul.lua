-- expect: 1 "before\0after"
-- a NUL in an error message cut the message there
error("before\0after")
