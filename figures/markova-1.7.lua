-- markova-1.7 ... markova-1.15 (seed 002, "B-spline křivky", chapter 1,
-- §1.1, Příklad 2, Obr. 1.7 - 1.15: "$N_1^1(u)$", "$N_2^1(u)$",
-- "$N_3^1(u)$", "$N_0^2(u)$", "$N_1^2(u)$", "$N_2^2(u)$", "$N_0^3(u)$",
-- "$N_1^3(u)$", "$N_0^4(u)$").
-- The basis functions of Example 2, U = {0, 1, 1, 3, 6, 10} (the seed's
-- data: Example 1 with u = 1 doubled), one function plot per figure.
-- As in markova-1.1: knots marked on the u axis with values and names
-- (u_1 and u_2 stacked under the double knot 1), the support
-- [u_i, u_{i+p+1}) shaded and labelled.  The double knot: a function
-- whose knots u_i ... u_{i+p+1} contain u_1 = u_2 is only C^{p-2} at
-- u = 1 (§1.2: "N_i^p(u) má v k-násobném uzlu spojitost třídy C^{p-k}"):
-- N_1^1 jumps (C^{-1}; right-continuous, so the filled dot is the value
-- and the open circle the limit from the left), N_0^2 has a corner (C^0),
-- N_1^2 starts with a non-zero slope (C^0), N_0^3 and N_1^3 are C^1,
-- N_0^4 is C^2.  For these a dotted line marks u = 1, a filled dot the
-- value N_i^p(1) (taken: N_i^p is continuous from the right, §1.2
-- "zprava spojitá"), and a note gives the continuity; the hollow circle
-- appears only in 1.7, for the value not taken.  N_2^1, N_3^1, N_2^2 do not
-- reach the double knot with both copies and have no note.
-- Not in the seed: the plot size, the common y range, the shading, the
-- notes and the places of the labels (chosen so that nothing collides).

local U = { 0, 1, 1, 3, 6, 10 }
local which = { {1, 1}, {2, 1}, {3, 1}, {0, 2}, {1, 2}, {2, 2},
                {0, 3}, {1, 3}, {0, 4} }

-- Right of the maximum of N_i^p: the first u where the function has fallen
-- to 60 % of its maximum (the function's label sits there, outside the
-- graph).
local function label_point(i, p)
  local a, b = U[i + 1], U[i + p + 2]
  local h = (b - a) / 400
  local best, bu = -1, a
  for u = a, b, h do
    local v = basis(U, i, p, u)
    if v > best then best, bu = v, u end
  end
  local lu = bu
  while lu < b and basis(U, i, p, lu) > 0.6 * best do lu = lu + h end
  return { lu, basis(U, i, p, lu) }
end

for k, ip in ipairs(which) do
  local i, p = ip[1], ip[2]
  local a, b = U[i + 1], U[i + p + 2]
  local double = i <= 1              -- u_1 and u_2 both among u_i..u_{i+p+1}
  local f = figure{
    name = "markova-1." .. (k + 6),
    caption = string.format("B-spline basis function N_%d^%d over U = "
      .. "{0, 1, 1, 3, 6, 10} (double knot u_1 = u_2 = 1), support "
      .. "[u_%d, u_%d) = [%g, %g) shaded%s (Obr. 1.%d: N_%d^%d(u))",
      i, p, i, i + p + 1, a, b,
      double and (p == 1
        and "; C^{-1} at the double knot: the filled dot is the value "
            .. "N_1^1(1) = 1 taken, the hollow circle the limit 0 from "
            .. "the left, not taken"
        or string.format("; C^%d at the double knot, the dot the value "
                         .. "N_%d^%d(1) taken", p - 2, i, p)) or "",
      k + 6, i, p),
    width = "8cm", height = "4.6cm",
  }
  f:plot{ x = {0, 10}, y = {0, 1.22}, knots = U, knot_labels = "u_%d",
          yticks = { 0, 0.5, 1 }, xlabel = "u" }
  f:fill({ {a, 0}, {b, 0}, {b, 1.06}, {a, 1.06} })
  f:label({ a + 0.2, 1.06 },
          string.format("[u_%d, u_{%d}) = [%g, %g)", i, i + p + 1, a, b),
          { place = "ne", offset = 2 })
  if double then
    f:line({ 1, 0 }, { 1, 1.06 }, { dash = "dotted", color = "grey" })
  end
  f:basis(U, i, p)
  f:label(label_point(i, p), string.format("N_%d^%d(u)", i, p),
          { place = "ne" })
  if double then
    local note
    if p == 1 then
      -- the jump: value 1 at u = 1 (filled), limit 0 from the left (open)
      f:points({ 1, 1 }, { marker = "dot" })
      f:points({ 1, 0 }, { marker = "circle", fill = "white",
                           marker_color = "#14306e" })
      note = "$u_1 = u_2 = 1$: $C^{-1}$ (skok)"
    else
      f:points({ 1, basis(U, i, p, 1) }, { marker = "dot" })
      note = string.format("$u_1 = u_2 = 1$: $C^%d$", p - 2)
    end
    -- right of the shading; above it where its edge u_{i+p+1} = 6 would
    -- cut the note
    f:label({ 9.9, b == 6 and 1.15 or 0.92 }, note,
            { place = "w", font_size = 8.5 })
  end
end
