-- surfaces/bezier-patch: a bicubic Bézier patch, two figures.
-- surfaces-bezier-patch: the 4 x 4 net P_ij (thin grey, dots), the
-- patch's boundary and silhouette (thick), iso-lines u, v = 1/4, 1/2, 3/4
-- (thin); what the patch hides is dashed.
-- surfaces-decasteljau: de Casteljau's algorithm on the patch at (u, v) =
-- (0.4, 0.6): the nets of levels 1, 2, 3 of the scheme in u (one colour
-- each), the scheme in v on the four points reached (the control polygon
-- of the iso-curve u = 0.4, and its levels), S(u, v) (star) and its
-- tangent plane, a small translucent square spanned by S_u and S_v (the
-- last level's two segments lie in it).

local P = {
  { {0, 0, 0},   {0, 1, 0.6}, {0, 2, 0.6}, {0, 3, 0} },
  { {1, 0, 0.7}, {1, 1, 1.8}, {1, 2, 1.6}, {1, 3, 0.4} },
  { {2, 0, 0.6}, {2, 1, 1.5}, {2, 2, 2.0}, {2, 3, 0.7} },
  { {3, 0, 0},   {3, 1, 0.5}, {3, 2, 0.8}, {3, 3, 0.2} },
}
local s = bezier_surface{ points = P }

local f = figure{
  name = "surfaces-bezier-patch",
  caption = "A bicubic Bézier patch with its control net; hidden lines dashed",
  width = "9cm", height = "7cm",
  view = { -55, 28 },
}
f:surface(s, { isolines = { 3, 3 }, hidden = "dashed",
               net = { color = "grey" }, labels = "P_{%d%d}",
               label_style = { font_size = 7 } })

local g = figure{
  name = "surfaces-decasteljau",
  caption = "de Casteljau's algorithm on a bicubic patch at (u, v) = "
    .. "(0.4, 0.6): the nets of the levels in u, then the scheme in v, "
    .. "the point S(u, v) and its tangent plane",
  width = "9cm", height = "7cm",
  view = { -55, 28 },
}
g:surface(s, { hidden = "remove", silhouette = false, width = 0.8,
               color = "#9aa5b5", net = { color = "grey" },
               isolines = { u = { 0.4 }, v = { 0.6 } },
               iso_style = { color = "#9aa5b5", dash = "dashed" } })
g:decasteljau_surface(s, 0.4, 0.6, { width = 0.6 })
-- the tangent plane at S(0.4, 0.6): a square of side 2a on orthonormal
-- axes e1 = S_u / |S_u| and e2, S_v made perpendicular to e1
local D = s:derivs(0.4, 0.6, 1)
local S, Su, Sv = D[1][1], D[2][1], D[1][2]
local function unit(x)
  local l = math.sqrt(x[1] ^ 2 + x[2] ^ 2 + x[3] ^ 2)
  return { x[1] / l, x[2] / l, x[3] / l }
end
local e1 = unit(Su)
local d = Sv[1] * e1[1] + Sv[2] * e1[2] + Sv[3] * e1[3]
local e2 = unit{ Sv[1] - d * e1[1], Sv[2] - d * e1[2], Sv[3] - d * e1[3] }
local a = 0.35
local function corner(p, q)
  return { S[1] + a * (p * e1[1] + q * e2[1]),
           S[2] + a * (p * e1[2] + q * e2[2]),
           S[3] + a * (p * e1[3] + q * e2[3]) }
end
g:fill({ corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1) },
       { fill = "#6a8fd0", opacity = 0.35, color = "#3a5a9a", width = 0.5 })
