-- expect: 1 "label: point is nil; Lua lists start at 1: P[1] is P_0, P[0] is nil"
-- P[0] as the point of a label
local P = { {0, 0}, {1, 1} }
local f = figure{ name = 'z' }
f:label(P[0], "P_0")
