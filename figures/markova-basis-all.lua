-- markova-basis-all (seed 002, "B-spline křivky", chapter 1, §1.2
-- "Vlastnosti bázových funkcí"; a figure added to the seed's, docs/figures.md
-- row markova-basis-all).
-- All eight quadratic basis functions N_0^2 ... N_7^2 over the knot vector
-- of the thesis' sample curve ("vzorová křivka", §2.10),
-- U = {0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1} (clamped, p = 2,
-- m = 10, n = m - p - 1 = 7), each in its own palette colour, and their
-- sum, dashed, which is 1 on the whole domain [u_2, u_8] = [0, 1] (§1.2:
-- "Součet všech nenulových bázových funkcí stupně p na úseku
-- [u_i, u_{i+1}) je roven 1").  The knots are marked on the u axis with
-- their values and names (u_0, u_1, u_2 stacked under 0, u_8 ... u_10
-- under 1).  The script checks the partition of unity numerically and
-- fails if the sum differs from 1 by more than 1e-12 anywhere on a fine
-- sample.
-- Not in the seed: the figure itself, its size and label places.

local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local p, n = 2, 7

local function sum(u)
  local s = 0
  for i = 0, n do s = s + basis(U, i, p, u) end
  return s
end
-- N_n^p(1) is 1 by the usual convention at the end of a clamped vector
for j = 0, 1000 do
  assert(math.abs(sum(j / 1000) - 1) < 1e-12, "partition of unity")
end

local f = figure{
  name = "markova-basis-all",
  caption = "All quadratic basis functions N_0^2 ... N_7^2 of the sample "
    .. "curve's knot vector U = {0,0,0,0.17,0.33,0.5,0.67,0.83,1,1,1}, "
    .. "each in its own colour, and their sum (dashed) = 1 on [0, 1]",
  width = "11cm", height = "6cm",
}
f:plot{ x = {0, 1}, y = {0, 1.2}, knots = U, knot_labels = "u_{%d}",
        yticks = { 0, 0.5, 1 }, xlabel = "u" }
f:func(sum, 0, 1, { dash = "dashed", color = "black", width = 0.8 })
f:label({ 0.5, 1 }, "$\\sum_{i=0}^{7} N_i^2(u) = 1$", { place = "n" })
-- each function only on its support (its local knots u_i .. u_{i+p+1}
-- give the same N_i^p), so the zero parts do not paint the axis over
for i = 0, n do
  f:basis({ table.unpack(U, i + 1, i + p + 2) }, 0, p, { color = i + 1 })
end
-- labels: at the maximum of each function (interior ones) or beside the
-- end functions, in the function's colour
for i = 0, n do
  local a, b = U[i + 1], U[i + p + 2]
  local best, bu = -1, a
  for j = 0, 200 do
    local u = a + (b - a) * j / 200
    local v = basis(U, i, p, u)
    if v > best then best, bu = v, u end
  end
  local at, place = { bu, best }, "n"
  if i == 0 then at, place = { 0.06, basis(U, 0, p, 0.06) }, "ne"
  elseif i == n then at, place = { 0.94, basis(U, n, p, 0.94) }, "auto" end
  f:label(at, string.format("N_%d^2", i), { place = place, color = i + 1 })
end
