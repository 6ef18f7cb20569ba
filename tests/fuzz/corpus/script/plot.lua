local f = figure{ name = "seed-plot", aspect = false }
f:plot{ x = {0, 1}, y = {0, 1}, xticks = 0.25, xlabel = "$t$" }
for i = 0, 3 do f:bernstein(3, i) end
f:func(function(x) return x * x end, 0, 1)
local h = interpolate{ points = { {0,0}, {1,1}, {2,0}, {3,1} }, method = "not-a-knot", param = "chord" }
print(h:degree(), #h:knots())
