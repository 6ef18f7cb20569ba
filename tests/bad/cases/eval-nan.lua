-- expect: 1 "eval: t is "
-- evaluation at NaN
local c = bezier{{0,0},{1,2},{2,0},{3,2},{4,0}}
print(c:eval(0/0))
