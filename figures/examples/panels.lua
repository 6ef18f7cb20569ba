-- Panels: f:panels{ rows, cols, share_x, share_y, gap, titles } splits the
-- page into a grid and returns one figure per cell, row by row; each takes
-- every drawing method and has its own window.  share_x: the panels of a
-- column map the same x to the same page x (here the parameter u, so the
-- knots line up); titles (a), (b), ... unless given or titles = false.
local U = { 0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1 }
local p, n = 3, 6
local c = { 0.2, 1.4, 0.3, 1.1, 0.6, 1.5, 0.4 }   -- control values c_i
local f = figure{ name = "example-panels", width = "10cm", height = "9cm",
                  caption = "A cubic spline function above its basis " ..
                            "functions, on one parameter axis" }
local top, bottom = f:panels{ rows = 2, cols = 1, share_x = true,
  titles = { "(a) $s(u) = \\sum c_i N_i^3(u)$", "(b) $N_i^3(u)$" } }
local function s(u)
  local v = 0
  for i = 0, n do v = v + c[i + 1] * basis(U, i, p, u) end
  return v
end
-- the control points of the spline function: (Greville abscissa, c_i)
local P = {}
for i = 0, n do
  P[#P + 1] = { (U[i + 2] + U[i + 3] + U[i + 4]) / 3, c[i + 1] }
end
top:plot{ x = { 0, 1 }, y = { 0, 1.6 }, yticks = { 0, 0.5, 1, 1.5 },
          xlabel = "u" }
top:polygon(P, { legend = "$(u_i^*, c_i)$" })
top:func(s, 0, 1, { legend = "$s(u)$" })
-- the knots by their indices in U: u_0 ... u_3 = 0, u_4 = 0.25, ...
bottom:plot{ x = { 0, 1 }, y = { 0, 1.1 }, knots = U,
             knot_labels = function(i, m)
               if i > 0 and U[i] == U[i + 1] then return false end
               return m > 1 and string.format("u_{%d..%d}", i, i + m - 1)
                            or string.format("u_{%d}", i)
             end, yticks = { 0, 1 }, xlabel = "u" }
for i = 0, n do
  bottom:basis({ table.unpack(U, i + 1, i + p + 2) }, 0, p,
               { color = i + 1 })
end
