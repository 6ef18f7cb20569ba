-- expect: 1 "bezier: point P_0 (entry 1) is nil; Lua lists start at 1: P[1] is P_0, P[0] is nil"
-- P[0] is nil in Lua: the list's first entry is missing
local P = { {0, 0}, {1, 1}, {2, 0} }
local c = bezier{ P[0], P[1], P[2] }
