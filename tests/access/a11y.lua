-- The figures of tests/access/test_access.py: a cubic with de Casteljau's
-- construction at t = 3/4 and its two halves (a subdivision), a B-spline
-- and the same curve after a knot insertion, in Czech and in English.
local P = { {0, 5}, {2, 7}, {5, 7}, {6, 2} }
local c = bezier(P)
local t = 3 / 4

local f = figure{ name = "a11y-cs", lang = "cs", width = "6cm",
                  height = "4cm", caption = "Konstrukce",
                  alt = "Kubická Bézierova křivka a její konstrukce" }
f:curve(c)
f:polygon(P, { labels = "P_%d" })
f:decasteljau(c, t)
local left, right = c:split(1 / 2)
f:curve(left, { color = "grey" })
f:curve(right, { color = "grey" })

local U = { 0, 0, 0, 1 / 3, 2 / 3, 1, 1, 1 }
local Q = { {0, 0}, {1, 2}, {3, 3}, {5, 2}, {6, 0} }
local s = bspline{ degree = 2, knots = U, points = Q }
local g = figure{ name = "a11y-en", width = "6cm", height = "4cm",
                  alt = "A quadratic B-spline & its refinement <u = 1/2>" }
g:curve(s)
g:polygon(Q, { labels = "Q_%d" })
g:curve(s:insert_knot(1 / 2), { color = "grey", dash = "dashed" })
