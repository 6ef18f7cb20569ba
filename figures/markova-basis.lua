-- markova-1.1 ... markova-1.6 (seed 002, chapter 1): the B-spline basis
-- functions N_0^1, N_1^1, N_2^1, N_0^2, N_1^2, N_0^3 over the thesis'
-- knot vector U = {0, 1, 3, 6, 10}, one plot each, knots marked on the
-- axis.

local U = { 0, 1, 3, 6, 10 }
local which = { {0, 1}, {1, 1}, {2, 1}, {0, 2}, {1, 2}, {0, 3} }

for k, ip in ipairs(which) do
  local i, p = ip[1], ip[2]
  local f = figure{
    name = "markova-1." .. k,
    caption = string.format("B-spline basis function N_%d^%d over U = {0, 1, 3, 6, 10}", i, p),
    width = "8cm", height = "4cm",
  }
  f:plot{ x = {0, 10}, y = {0, 1}, knots = U, knot_labels = "u_%d",
          xticks = false, yticks = { 0, 0.5, 1 }, xlabel = "u" }
  f:basis(U, i, p)
  -- the label near the maximum of the function
  local best, bu = -1, 0
  for j = 0, 200 do
    local u = U[i + 1] + (U[i + p + 2] - U[i + 1]) * j / 200
    local v = basis(U, i, p, u)
    if v > best then best, bu = v, u end
  end
  f:label({ bu, best }, string.format("N_%d^%d", i, p), { place = "n" })
end
