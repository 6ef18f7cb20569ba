-- lecture5-rational (seed 001, lecture 5, "Рациональные кривые Безье",
-- Пример 5.4.1: "Рациональная кривая Безье, построенная по восьми опорным
-- точкам и их весам ... Для сравнения на том же графике изображена также
-- и обычная кривая Безье, построенная по тем же самым опорным точкам ...
-- Первоначально все веса сделаны одинаковыми, поэтому после запуска
-- программы обе кривые совпадают. При изменении весов они будут
-- расходиться").
-- The example's eight points p_0 ... p_7 = (−10,0) (−3,7) (1.1,−7.2)
-- (4.3,−8.5) (−16,12) (−2.1,1.7) (−8.2,1.4) (12.2,5.4) (given), degree 7.
-- Four panels (one figure, 2 × 2, each panel the same window): the
-- ordinary Bézier curve (blue, dashed) and the rational one (red) for
--   (a) all weights ω_i = 1: the two curves coincide;
--   (b) ω_4 = 10, the others 1 (the example's sliders reach 100);
--   (c) ω_2 = ω_3 = 3, the others 1;
--   (d) ω_1 = 8, ω_6 = 8, the others 1.
-- The weight settings (b)-(d) are chosen (the example leaves them to the
-- sliders); each shows the rational curve pulled towards the points of
-- larger weight (ringed) while it keeps its end points p_0, p_7.  A
-- legend (in Russian, as the lecture) names the two curves.

local P = { {-10, 0}, {-3, 7}, {1.1, -7.2}, {4.3, -8.5}, {-16, 12},
            {-2.1, 1.7}, {-8.2, 1.4}, {12.2, 5.4} }
local blue, red = "#1f5fbf", "#c0392b"

local settings = {
  { name = "(a)\\quad ω_i = 1", w = { 1, 1, 1, 1, 1, 1, 1, 1 } },
  { name = "(b)\\quad ω_4 = 10", w = { 1, 1, 1, 1, 10, 1, 1, 1 } },
  { name = "(c)\\quad ω_2 = ω_3 = 3", w = { 1, 1, 3, 3, 1, 1, 1, 1 } },
  { name = "(d)\\quad ω_1 = ω_6 = 8", w = { 1, 8, 1, 1, 1, 1, 8, 1 } },
}
local place = { "w", "n", "w", "s", "w", "auto", "auto", "e" }

local f = figure{
  name = "lecture5-rational",
  caption = "Rational (red) and ordinary (blue, dashed) Bézier curve on the "
    .. "eight points of Example 5.4.1: (a) equal weights, the curves coincide; "
    .. "(b) ω_4 = 10; (c) ω_2 = ω_3 = 3; (d) ω_1 = ω_6 = 8 (other weights 1)",
  width = "16cm", height = "13cm",
}
for k, s in ipairs(settings) do
  local dx = ((k - 1) % 2) * 36
  local dy = -math.floor((k - 1) / 2) * 27
  local Q = {}
  for i, p in ipairs(P) do Q[i] = { p[1] + dx, p[2] + dy } end
  local plain = bezier(Q)
  local rat = bezier{ points = Q, weights = s.w }
  if k == 1 then   -- equal weights: the rational curve is the ordinary one
    for j = 0, 20 do
      local a, b = plain:eval(j / 20), rat:eval(j / 20)
      if math.abs(a[1] - b[1]) + math.abs(a[2] - b[2]) > 1e-9 then
        error("equal weights: the curves differ at t = " .. j / 20)
      end
    end
  end
  for i, q in ipairs(Q) do
    if s.w[i] ~= 1 then   -- a point of raised weight: a red ring
      f:points(q, { marker = "circle", marker_size = 9, color = red, width = 1.2 })
    end
  end
  f:polygon(plain)
  -- one legend for the four panels (the entries of the first)
  f:curve(rat, { color = red, width = 2,
                 legend = k == 1 and "\\text{рациональная кривая Безье}" or nil })
  f:curve(plain, { color = blue, dash = "dashed", width = 1.4,
                   legend = k == 1 and "\\text{обычная кривая Безье}" or nil })
  -- the control points again, over the curves (p_6 lies under them)
  f:points(Q, { color = "#3c3c3c", marker_color = "#3c3c3c" })
  for i, q in ipairs(Q) do
    f:label(q, string.format("p_%d", i - 1),
            { place = place[i], font_size = 9,
              offset = s.w[i] ~= 1 and 6 or (i == 6 and 1.5 or nil) })
  end
  f:label({ dx - 2, dy + 14.5 }, s.name, { place = "center" })
end
