-- markova-1.1 ... markova-1.6 (seed 002, "B-spline křivky", chapter 1,
-- §1.1 "Základní pojmy a značení", Příklad 1, Obr. 1.1 - 1.6:
-- "$N_0^1(u)$", "$N_1^1(u)$", "$N_2^1(u)$", "$N_0^2(u)$", "$N_1^2(u)$",
-- "$N_0^3(u)$").
-- The B-spline basis functions of Example 1, U = {0, 1, 3, 6, 10} (the
-- seed's data), one function plot per figure: N_0^1, N_1^1, N_2^1 (hats),
-- N_0^2, N_1^2 (quadratic, C^1 at the simple knots) and N_0^3 (cubic, the
-- only cubic the five knots allow).  Every plot marks the knots on the
-- u axis with their values and their names u_0 ... u_4, and shades the
-- support [u_i, u_{i+p+1}) on which N_i^p is non-zero (§1.2: "N_i^p(u) je
-- nenulová na [u_i, u_{i+p+1})"), labelled with the interval.
-- Not in the seed (the thesis' images are missing): the plot size, the
-- common y range [0, 1] of all six plots (so they compare), the shading
-- and the places of the labels.

local U = { 0, 1, 3, 6, 10 }
local which = { {0, 1}, {1, 1}, {2, 1}, {0, 2}, {1, 2}, {0, 3} }

-- N_i^p sampled on its support: the maximum and, right of it, the point
-- where the function has fallen to 60 % of it (the function's label sits
-- there, outside the graph).
local function landmarks(i, p)
  local a, b = U[i + 1], U[i + p + 2]
  local best, bu = -1, a
  for j = 0, 400 do
    local u = a + (b - a) * j / 400
    local v = basis(U, i, p, u)
    if v > best then best, bu = v, u end
  end
  local lu = bu
  while lu < b and basis(U, i, p, lu) > 0.6 * best do
    lu = lu + (b - a) / 400
  end
  return bu, best, lu, basis(U, i, p, lu)
end

for k, ip in ipairs(which) do
  local i, p = ip[1], ip[2]
  local a, b = U[i + 1], U[i + p + 2]
  local f = figure{
    name = "markova-1." .. k,
    caption = string.format("B-spline basis function N_%d^%d over U = "
      .. "{0, 1, 3, 6, 10}, its support [u_%d, u_%d) = [%g, %g) shaded "
      .. "(Obr. 1.%d: N_%d^%d(u))", i, p, i, i + p + 1, a, b, k, i, p),
    width = "8cm", height = "4.6cm",
  }
  f:plot{ x = {0, 10}, y = {0, 1.22}, knots = U, knot_labels = "u_%d",
          yticks = { 0, 0.5, 1 }, xlabel = "u" }
  -- the support, shaded up to just above the largest value 1
  f:fill({ {a, 0}, {b, 0}, {b, 1.06}, {a, 1.06} })
  f:label({ a + 0.2, 1.06 },
          string.format("[u_%d, u_{%d}) = [%g, %g)", i, i + p + 1, a, b),
          { place = "ne", offset = 2 })
  f:basis(U, i, p)
  local _, _, lu, lv = landmarks(i, p)
  f:label({ lu, lv }, string.format("N_%d^%d(u)", i, p), { place = "ne" })
end
