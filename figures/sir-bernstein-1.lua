-- sir-bernstein-1 ... sir-bernstein-5 (seed 000, Šír, "Bézierovy křivky",
-- slides "Bernsteinovy polynomy" and "Vlastnosti Bernsteinovy
-- polynomy": "B_i^n(t) je nezáporný na [0, 1] a pro n > 0 má na tomto
-- intervalu jediné maximum v bodě t = i/n").
-- The Bernstein basis B_0^n ... B_n^n on [0, 1] for n = 1 ... 5, one
-- function plot per n (the id ends in n), each B_i^n in its own palette
-- colour, its maximum (i/n, B_i^n(i/n)) marked with a dot and a dotted
-- drop line to the t axis, whose ticks are exactly the points i/n.
-- The label B_i^n sits above its maximum (B_0^n right of the y axis and
-- B_n^n left of the line t = 1, so no label touches an axis).
-- Not in the seed: sizes, colours, label places; all five plots share
-- the window [0, 1] x [0, 1.12] so they compare side by side.

local function binomial(n, k)
  local r = 1
  for j = 1, k do r = r * (n - k + j) / j end
  return r
end

-- palette colours 1-6 (apart for colour-blind readers too:
-- docs/accessibility.md)
local colour = { 1, 2, 3, 4, 5, 6 }

for n = 1, 5 do
  local f = figure{
    name = "sir-bernstein-" .. n,
    caption = string.format("Bernstein polynomials B_i^%d, i = 0 ... %d, "
      .. "on [0, 1]; each has its single maximum at t = i/%d (marked)",
      n, n, n),
    width = "8cm", height = "5.2cm",
  }
  local ticks, names = {}, {}
  for i = 0, n do
    ticks[#ticks + 1] = i / n
    if i == 0 then names[#names + 1] = "0"
    elseif i == n then names[#names + 1] = "1"
    else names[#names + 1] = string.format("%d/%d", i, n) end
  end
  f:plot{ x = {0, 1}, y = {0, 1.12}, xticks = ticks, xtick_labels = names,
          yticks = { 0, 0.5, 1 }, xlabel = "t" }
  for i = 0, n do
    local t = i / n
    local b = binomial(n, i) * t^i * (1 - t)^(n - i)
    if i > 0 and i < n then
      f:line({ t, 0 }, { t, b }, { color = colour[i + 1], dash = "dotted", width = 0.7 })
    end
    f:bernstein(n, i, { color = colour[i + 1] })
    f:points({ t, b }, { color = colour[i + 1], marker_color = colour[i + 1], marker = "dot" })
    local place = "n"
    if i == 0 then place = "ne" elseif i == n then place = "nw" end
    f:label({ t, b }, string.format("B_%d^%d", i, n),
            { place = place, color = colour[i + 1] })
  end
end
