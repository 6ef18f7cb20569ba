-- sir-bernstein-1 ... sir-bernstein-5 (seed 000, "Bézierovy křivky"):
-- the Bernstein basis B_i^n on [0, 1] for n = 1 ... 5, one plot per n,
-- each B_i^n in its own palette colour, its maximum at t = i/n marked
-- (B_i^n(i/n) = C(n,i) (i/n)^i (1 - i/n)^(n-i)).
-- Data: none in the seed beyond n; the plots show all i = 0 ... n.

local function binomial(n, k)
  local r = 1
  for j = 1, k do r = r * (n - k + j) / j end
  return r
end

for n = 1, 5 do
  local f = figure{
    name = "sir-bernstein-" .. n,
    caption = "Bernstein polynomials B_i^" .. n .. " on [0, 1], maxima at i/" .. n,
    width = "8cm", height = "5cm",
  }
  f:plot{ x = {0, 1}, y = {0, 1}, xticks = 0.25, yticks = 0.5, xlabel = "t" }
  for i = 0, n do
    f:bernstein(n, i, { color = i + 1 })
    local t = i / n
    local b = binomial(n, i) * t^i * (1 - t)^(n - i)
    f:points({ t, b }, { color = i + 1, marker_color = i + 1, marker = "dot" })
    f:label({ t, b }, string.format("B_%d^%d", i, n),
            { place = "n", color = i + 1 })
  end
end
