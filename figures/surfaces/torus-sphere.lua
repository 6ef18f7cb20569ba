-- surfaces/torus-sphere: a NURBS torus and a NURBS sphere (rational
-- biquadratic, exact) with iso-lines; the silhouettes are the exact
-- contours, hidden lines dashed, the sphere partly hidden by the torus.

local torus = nurbs_torus{ center = { 0, 0, 0 }, R = 2, r = 0.7 }
local sphere = nurbs_sphere{ center = { 2.6, 2.2, 0.4 }, r = 1 }

local f = figure{
  name = "surfaces-torus-sphere",
  caption = "A NURBS torus and sphere with iso-lines; hidden lines dashed",
  width = "10cm", height = "7cm",
  view = { -70, 30 },
}
f:surface(torus, { boundary = false, isolines = { 11, 7 },
                   hidden = "dashed" })
f:surface(sphere, { boundary = false, isolines = { 7, 5 },
                    hidden = "dashed", color = "#1f5fbf" })
