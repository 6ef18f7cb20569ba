-- surfaces/tangent-plane: the tangent plane of a bicubic patch at a
-- hyperbolic point S(u0, v0): a square of the plane spanned by S_u and
-- S_v, filled and translucent, with the normal.  The surface passes through
-- its tangent plane there (the curvature changes sign across the point),
-- so parts of the plane lie behind the surface: they are faded (hidden =
-- "dashed", the default of a fill in space), found against the exact
-- surface, not by sorting facets.

local P = {}
for i = 0, 3 do
  P[i + 1] = {}
  for j = 0, 3 do
    local x, y = i - 1.5, j - 1.5
    P[i + 1][j + 1] = { x, y, 0.35 * (x * x - y * y) + 0.15 * x }
  end
end
local s = bezier_surface{ points = P }

local u0, v0 = 0.45, 0.55
local D = s:derivs(u0, v0, 1)
local S, Su, Sv = D[1][1], D[2][1], D[1][2]

-- a square of side 2a in the plane: orthonormal axes e1 = Su/|Su|, e2 in
-- the plane perpendicular to it
local function unit(a)
  local l = math.sqrt(a[1] ^ 2 + a[2] ^ 2 + a[3] ^ 2)
  return { a[1] / l, a[2] / l, a[3] / l }
end
local e1 = unit(Su)
local dot = Sv[1] * e1[1] + Sv[2] * e1[2] + Sv[3] * e1[3]
local e2 = unit{ Sv[1] - dot * e1[1], Sv[2] - dot * e1[2],
                 Sv[3] - dot * e1[3] }
local a = 1.3
local function corner(p, q)
  return { S[1] + a * (p * e1[1] + q * e2[1]),
           S[2] + a * (p * e1[2] + q * e2[2]),
           S[3] + a * (p * e1[3] + q * e2[3]) }
end

local f = figure{
  name = "surfaces-tangent-plane",
  caption = "A bicubic patch and its tangent plane at a hyperbolic point",
  width = "8cm", height = "6cm",
  view = { -55, 32 },
}
f:surface(s, { isolines = { 5, 5 }, hidden = "dashed" })
f:fill({ corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1) },
       { fill = "orange", opacity = 0.55, color = "#a05000", width = 0.6 })
local n = s:normal(u0, v0)
f:arrow(S, { 0.8 * n[1], 0.8 * n[2], 0.8 * n[3] }, { label = "n" })
f:points({ S })
