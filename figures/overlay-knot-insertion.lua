-- overlay-knot-insertion (seed 002, "B-spline křivky", chapter 3, section
-- 3.1 "Vložení uzlu", Obr. 3.1 "Původní křivka" and Obr. 3.2 "Nový uzel
-- t = 0.6"; the insertion of markova-3.1/3.2 continued knot by knot, as
-- overlay steps for slides).
--
-- The thesis' sample curve (p = 2, P_0..P_7,
-- U = {0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1}).  Each step
-- inserts one more knot (Boehm's algorithm, s:insert_knot): the thesis'
-- t = 0.6, then t = 0.25 and t = 0.9, which lie in other spans (the
-- last two are this project's choice):
--   step 1  the curve, its control polygon and knot points;
--   step k  (k = 2, 3, 4) the polygon after k - 1 insertions; the polygon
--           it replaces dashed grey, its p = 2 new points blue, the new
--           knot point C(t) a green dot labelled with t.
-- The curve is the same on every step (checked below to 1e-12).
-- Window and size those of markova-3.1.

local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local U = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 }
local s = bspline{ degree = 2, knots = U, points = P }
local ts = { 0.6, 0.25, 0.9 }
local tplace = { "n", "w", "e" }   -- away from the curve

local f = figure{
  name = "overlay-knot-insertion",
  caption = "Knot insertion step by step on the sample curve (p = 2): " ..
            "t = 0.6, 0.25, 0.9, one per overlay step; each new polygon " ..
            "cuts a corner of the one before (dashed), the curve stays",
  width = "10cm", height = "7.8cm", window = { 0.6, 5.4, 0.7, 4.45 },
}
local curves = { s }
for i, t in ipairs(ts) do
  local n, info = curves[i]:insert_knot(t)
  for j = 0, 100 do
    local a, b = s:eval(j / 100), n:eval(j / 100)
    assert(math.abs(a[1] - b[1]) < 1e-12 and math.abs(a[2] - b[2]) < 1e-12)
  end
  assert(info.new_count == 2)
  curves[i + 1] = n
end
f:curve(s)
for step, c in ipairs(curves) do
  local only = tostring(step)
  if step > 1 then
    -- the polygon this step replaces, dashed
    f:polyline(curves[step - 1]:points(),
               { color = "grey", dash = "dashed", width = 0.8,
                 visible = only })
  end
  f:polygon(c, { visible = only })
  f:knots(c, { visible = only })
  if step > 1 then
    local t = ts[step - 1]
    local _, info = curves[step - 1]:insert_knot(t)
    local Q = c:points()
    local new = {}
    for j = info.new_first, info.new_first + info.new_count - 1 do
      new[#new + 1] = Q[j + 1]
    end
    f:points(new, { marker = "dot", color = "blue", marker_color = "blue",
                    marker_size = 5, visible = only })
    f:points({ c:eval(t) }, { marker = "dot", color = "darkgreen",
                              marker_color = "darkgreen", marker_size = 4,
                              labels = { string.format("t = %g", t) },
                              label_place = { tplace[step - 1] },
                              label_style = { color = "darkgreen",
                                              offset = 8 },
                              visible = only })
  end
end
