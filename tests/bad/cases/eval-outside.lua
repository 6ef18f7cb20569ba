-- expect: 1 "eval: t = 2 is outside [0, 1]"
-- evaluation at t = 2
local c = bezier{{0,0},{1,2},{2,0},{3,2},{4,0}}
print(c:eval(2))
