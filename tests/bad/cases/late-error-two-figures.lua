-- expect: 1 "bspline: degree 9 needs at least 10 points, 2 given"
-- an error after two valid figures
figure{ name = 'one' }:curve(bezier{ {0, 0}, {1, 1} })
figure{ name = 'two' }:curve(bezier{ {0, 0}, {1, 2} })
local s = bspline{ degree = 9, points = {{0,0},{1,1}} }
