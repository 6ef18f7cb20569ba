-- Prints "key v1 v2 ..." lines (%.17g, exact) that test_tool.c compares
-- with what the C API computes for the same input.
local function put(key, ...)
  local out = { key }
  local function add(v)
    if type(v) == "table" then for _, x in ipairs(v) do add(x) end
    else out[#out + 1] = string.format("%.17g", v) end
  end
  add({ ... })
  print(table.concat(out, " "))
end

local orazem = { {0, 5}, {1, -1}, {3, 0}, {4, 3}, {6, 10} }
local c = bezier(orazem)
local q = bezier{ points = { {0, 5}, {1, -1}, {3, 0} }, weights = { 1, 0.5, 2 } }
put("eval", c:eval(0.3))
put("reval", q:eval(0.3))
put("decasteljau", c:decasteljau(0.75))
local L, R = c:split(0.3)
put("split", L:points(), R:points())
put("elevate", c:elevate(2):points())
local dq = q:derivative(1)
put("derivative", c:derivative(1):eval(0.4), dq:eval(0.4), dq:degree())
put("rpoints", q:points(), q:weights(), q:degree())

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local s = bspline{ degree = 2, knots = U, points = P }
local nb = bspline{ degree = 2, knots = U, points = P, weights = { 1, 2, 1, 0.5, 1, 3, 1, 1 } }
put("beval", s:eval(0.6), nb:eval(0.6))
local t = s:insert_knot(0.6, 2)
put("insert", t:points(), t:knots())
local lv, span, mult = s:deboor(0.5)
put("deboor", lv, span, mult)
local pieces = nb:to_beziers()
local flat = {}
for _, b in ipairs(pieces) do
  flat[#flat + 1] = b:points()
  flat[#flat + 1] = b:weights()
end
put("to_beziers", flat)
local ds = s:derivative(1)
put("bderivative", ds:eval(0.45), ds:degree())
put("belevate", s:elevate(1):points())
put("bqueries", nb:weights(), nb:knots(), nb:degree())

-- offsets and interpolation (DESIGN.md core names)
local off = c:offset(1.5, { tolerance = 1e-3 })
local rep = off.report
local offp = {}
for _, b in ipairs(off) do offp[#offp + 1] = b:points() end
put("offset", offp, rep.max_error)
local D = { {0, 0}, {1, 2}, {3, 1}, {4, 4}, {6, 3} }
local methods = { "natural", "not-a-knot", "periodic", "catmull-rom" }
for _, m in ipairs(methods) do
  local it = interpolate{ points = D, method = m }
  put("interp-" .. m, it:points(), it:knots())
end
local ig = interpolate{ points = D, method = "global", degree = 2, param = "centripetal" }
put("interp-global", ig:points(), ig:knots())
