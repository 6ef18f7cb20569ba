-- lecture5-smooth-edit (seed 001, lecture 5, "Условия сохранения
-- гладкости сопряжения при делении кривой Безье": "Если мы хотим, чтобы
-- эта гладкость была не менее C^k, то мы можем добиться этого, оставив
-- на месте точки p_n^a, ..., p_{n−k}^a, p_0^b, ..., p_k^b").
-- One figure, three panels side by side, k = 0, 1, 2: a quartic is split
-- at t* = 1/2 into the arcs r^a (blue) and r^b; then r^b is edited by
-- moving its free inner points p_{k+1}^b ... p_{n−1}^b by the same vector
-- (arrows), keeping the k + 1 points of each part at the join (square
-- markers) and the end point p_n^b.  Dashed grey: r^b and its polygon
-- before the edit; red: after.  The join stays C^k: for k = 0 the curve
-- keeps only its position at r(t*) (a corner appears), for k = 1 also
-- the tangent, for k = 2 also the curvature.
-- Data chosen (the seed gives none): n = 4, p_0 ... p_4 = (0,0) (0.8,2.6)
-- (3,3.4) (5.2,2.6) (6,0), t* = 1/2, the edit vector (0.5, 1.6).

local c = bezier{ {0, 0}, {0.8, 2.6}, {3, 3.4}, {5.2, 2.6}, {6, 0} }
local ts = 0.5
local n = c:degree()
local v = { 0.5, 1.6 }
local blue, red = "#1f5fbf", "#c0392b"

local f = figure{
  name = "lecture5-smooth-edit",
  caption = "After splitting at t* = 1/2, the arc r^b is edited keeping the "
    .. "k + 1 end points of each part at the join (squares) fixed: the join "
    .. "stays C^k (k = 0, 1, 2 from left to right); dashed: r^b before",
  width = "16cm", height = "5.2cm",
}

local function shifted(pts, dx)
  local out = {}
  for i, p in ipairs(pts) do out[i] = { p[1] + dx, p[2] } end
  return out
end

for k = 0, 2 do
  local dx = 7.6 * k
  local ra, rb = c:split(ts)
  local A = shifted(ra:points(), dx)
  local B = shifted(rb:points(), dx)
  local B2 = {}
  for i, p in ipairs(B) do
    local j = i - 1                -- index of p_j^b
    if j > k and j < n then B2[i] = { p[1] + v[1], p[2] + v[2] }
    else B2[i] = p end
  end
  local a, b_old, b_new = bezier(A), bezier(B), bezier(B2)
  -- check: the derivatives of orders 0 ... k agree at the join (both arcs
  -- have parameter length t* = 1 - t* = 1/2, so no rescaling), order k + 1
  -- does not
  local da, db = a:derivs(1, k + 1), b_new:derivs(0, k + 1)
  for j = 0, k + 1 do
    local gap = math.abs(da[j + 1][1] - db[j + 1][1]) + math.abs(da[j + 1][2] - db[j + 1][2])
    if (j <= k) ~= (gap < 1e-9 * (1 + math.abs(da[j + 1][1]) + math.abs(da[j + 1][2]))) then
      error(string.format("k = %d: derivative %d differs by %g at the join (expected C^%d exactly)", k, j, gap, k))
    end
  end
  -- before the edit
  f:polygon(b_old, { color = "grey", dash = "dashed", marker = "none", width = 0.6 })
  f:curve(b_old, { color = "grey", dash = "dashed", width = 1.2 })
  -- the edit: arrows old -> new
  for i = 1, #B do
    if B2[i] ~= B[i] then
      f:arrow_to(B[i], B2[i], { color = red, width = 0.6 })
    end
  end
  f:polygon(a, { color = blue, marker_color = blue, width = 0.8 })
  f:polygon(b_new, { color = red, marker_color = red, width = 0.8 })
  f:curve(a, { color = blue, width = 2 })
  f:curve(b_new, { color = red, width = 2 })
  -- the fixed points: p_{n-k}^a ... p_n^a and p_0^b ... p_k^b
  local fixed = {}
  for j = n - k, n do fixed[#fixed + 1] = A[j + 1] end
  for j = 0, k do fixed[#fixed + 1] = B[j + 1] end
  f:points(fixed, { marker = "square", marker_size = 6, color = "black",
                    marker_color = "black" })
  f:label({ dx + 3, 4.9 }, string.format("k = %d: C^%d", k, k), { place = "center" })
  f:label(A[1], "r^a", { place = "e", color = blue, offset = 8 })
  f:label(B2[n + 1], "r^b", { place = "w", color = red, offset = 8 })
end
