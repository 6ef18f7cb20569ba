-- pairs in one order (render/lua/lpairs.c), one number a line: the seeds
-- of degenerate values (gen-degenerate.py) put 0, 1, -1, 1e300 and NaN
-- into each alone.  Keys of every rank in one table (integers, floats
-- round 2^53 and 2^63, strings, booleans, a table), a key removed and a
-- value changed during the loop, points drawn and labelled in the order
-- pairs gives, and a table whose options the schema checks.
local n =
  40
local x =
  9007199254740992
local w =
  0.5
local t = { [true] = 1, [false] = 2, [{}] = 3, s = 4, [""] = 5 }
for i = 1, n do
  t[i] = i
  t[i + w] = -i
  t["k" .. i] = i * w
end
t[x] = 1
t[x + 2] = 2
t[2.0 ^ 63] = 3
t[-2.0 ^ 63] = 4
local f = figure{ name = "p", width = "5cm", height = "4cm",
                  window = { -1, n + 1, -n - 1, n + 1 } }
local pts, names, last = {}, {}, nil
for k, v in pairs(t) do
  if type(k) == "string" and type(v) == "number" and #pts < n then
    pts[#pts + 1] = { #pts, v }
    names[#names + 1] = k
  end
  if k == "k1" then t.k2 = nil; t.k3 = w end
  last = k
end
assert(last ~= nil)
f:points(pts, { labels = function(i) return names[i + 1] end })
local opts = {}
for k, v in pairs({ color = "red", width = w, dash = "dashed" }) do
  opts[k] = v
end
f:polyline(pts, opts)
