-- lecture5-conics (seed 001, lecture 5, Замечание 5.4.1, item 4: "В
-- отличие от обычных кривых Безье, рациональные кривые Безье способны
-- точно (а не приблизительно) представлять дуги кривых второго порядка
-- ... эллипса, параболы или гиперболы").
-- Four conic arcs, each one quadratic rational Bézier curve (made by the
-- library's exact conic constructions), with its control polygon
-- P_0 P_1 P_2 and its weights (ω_0, ω_1, ω_2); the whole conic is drawn
-- thin and dashed behind the arc:
--   circle x² + y² = 4, the arc from 45° to 135°: ω_1 = cos 45° ≈ 0.707;
--   ellipse x²/9 + y²/2.25 = 1, parameters −45° ... 45°: ω_1 ≈ 0.707;
--   parabola y = x²/2, x in [−2, 2]: ω_1 = 1 (an ordinary Bézier curve);
--   hyperbola x² − y² = 1.96, 1.4 (cosh s, sinh s) for s in [−1, 1]:
--   ω_1 = cosh 1 ≈ 1.543 (asymptotes dotted).
-- ω_1 < 1 ellipse (circle), = 1 parabola, > 1 hyperbola.
-- Data chosen (the seed gives no example): the conics and arcs above.

local pi = math.pi
local blue = "#1f5fbf"

local f = figure{
  name = "lecture5-conics",
  caption = "Exact conic arcs as quadratic rational Bézier curves with their "
    .. "control polygons and weights: circle arc and ellipse arc (ω_1 < 1), "
    .. "parabola (ω_1 = 1), hyperbola (ω_1 > 1)",
  width = "14cm", height = "11cm",
}

local function moved(list, dx, dy)
  local out = {}
  for i, b in ipairs(list) do out[i] = b:transform({ {1, 0}, {0, 1} }, { dx, dy }) end
  return out
end

-- one panel: the whole conic (dashed), the arc, its polygon, labels
local function panel(title, whole, arc, dx, dy, places, title_at)
  f:curve(moved(whole, dx, dy), { color = "grey", dash = "dashed", width = 0.7 })
  local b = moved(arc, dx, dy)[1]
  f:polygon(b)
  f:curve(b, { color = blue, width = 2.2 })
  local w = b:is_rational() and b:weights() or { 1, 1, 1 }
  for i, p in ipairs(b:points()) do
    f:label(p, string.format("P_%d", i - 1), { place = places[i] })
  end
  f:label({ title_at[1] + dx, title_at[2] + dy }, "\\text{" .. title .. "}", { place = "center" })
  local w1 = string.format("%.3f", w[2]):gsub("%.?0+$", "")
  f:label({ title_at[1] + dx, title_at[2] + dy - 0.55 },
          string.format("ω = (%g, %s, %g)", w[1], w1, w[3]),
          { place = "center", font_size = 9 })
end

-- circle
panel("дуга окружности", conic.circle(0, 0, 2), conic.arc(0, 0, 2, pi / 4, 3 * pi / 4),
      0, 0, { "e", "n", "w" }, { 0, -2.9 })
-- ellipse
panel("дуга эллипса", conic.ellipse(0, 0, 3, 1.5, 0, 0, 2 * pi),
      conic.ellipse(0, 0, 3, 1.5, 0, -pi / 4, pi / 4),
      8.5, 0.3, { "s", "e", "n" }, { 0, -2.6 })
-- parabola
panel("парабола", conic.parabola(0, 0, 0.5, pi / 2, -2.6, 2.6),
      conic.parabola(0, 0, 0.5, pi / 2, -2, 2),
      0, -7.6, { "w", "e", "e" }, { 0, -3.0 })
-- hyperbola, with its asymptotes
local hx, hy = 6.6, -7.6
f:line({ hx - 0.6, hy - 0.6 }, { hx + 3.4, hy + 3.4 }, { color = "grey", dash = "dotted", width = 0.6 })
f:line({ hx - 0.6, hy + 0.6 }, { hx + 3.4, hy - 3.4 }, { color = "grey", dash = "dotted", width = 0.6 })
panel("гипербола", conic.hyperbola(0, 0, 1.4, 1.4, 0, -1.5, 1.5),
      conic.hyperbola(0, 0, 1.4, 1.4, 0, -1, 1),
      hx, hy, { "e", "s", "e" }, { 1.9, -3.6 })
