-- pairs visits the keys of a table in one order at every run
-- (render/lua/lpairs.c): numbers ascending, strings in byte order, false,
-- true, then other keys.  Each order is checked against table.sort of the
-- same keys, an order found independently; run by tests/lua/test_tool.c.

local function keys(t)
  local r = {}
  for k in pairs(t) do r[#r + 1] = k end
  return r
end

local function same(got, want, what)
  assert(#got == #want, what .. ": " .. #got .. " keys, " .. #want .. " wanted")
  for i = 1, #want do
    assert(got[i] == want[i], what .. ": key " .. i .. " is " ..
           tostring(got[i]) .. ", " .. tostring(want[i]) .. " wanted")
  end
end

-- strings: 300 of them, of different lengths, some prefixes of others,
-- some beyond ASCII
local t, want = {}, {}
for i = 1, 300 do
  local s = string.format("k%03d", (i * 37) % 300) .. string.rep("x", i % 3)
  if i % 50 == 0 then s = s .. "\u{17E}" end
  t[s] = i
  want[#want + 1] = s
end
t.k = 0
want[#want + 1] = "k"
table.sort(want)
same(keys(t), want, "strings")

-- numbers: integers and floats, negative, around 2^53 and 2^63
local nums = { -3, -0.5, 0, 1, 1.5, 2, 7, 1e300, -1e300, 2^53, 2^53 + 2,
               math.mininteger, math.maxinteger, 2.0^63, -2.0^63 * 2,
               math.huge, -math.huge, 0.1, 1 / 3 }
local n = {}
for _, x in ipairs(nums) do n[x] = true end
local wn = {}
for k in next, n do wn[#wn + 1] = k end
table.sort(wn)
same(keys(n), wn, "numbers")

-- the array part and the hash part together
local a = { 10, 20, 30, [5] = 50, [-1] = -10, [2.5] = 25 }
same(keys(a), { -1, 1, 2, 2.5, 3, 5 }, "array and hash")

-- the ranks: numbers, strings, false, true, then tables
local tab = {}
local m = { [tab] = 1, [true] = 2, [false] = 3, b = 4, a = 5, [2] = 6, [1] = 7 }
local got = keys(m)
same({ got[1], got[2], got[3], got[4], got[5], got[6], got[7] },
     { 1, 2, "a", "b", false, true, tab }, "ranks")

-- a key set to nil during the loop is passed over; values are current
local r = { a = 1, b = 2, c = 3, d = 4 }
local seen = {}
for k, v in pairs(r) do
  seen[#seen + 1] = k .. "=" .. v
  if k == "a" then r.c = nil; r.d = 40 end
end
same(seen, { "a=1", "b=2", "d=40" }, "changed during the loop")

-- __pairs is honoured
local proxy = setmetatable({}, { __pairs = function(self)
  return function(_, i) if (i or 0) < 3 then return (i or 0) + 1, "x" end end,
         self, nil
end })
same(keys(proxy), { 1, 2, 3 }, "__pairs")

-- an empty table; a table of one key
same(keys({}), {}, "empty")
same(keys({ z = 1 }), { "z" }, "one key")

-- not a table: named at once
local ok, err = pcall(pairs, 42)
assert(not ok and err:find("bad argument #1 to 'pairs' %(table expected, got number%)"),
       tostring(err))
ok, err = pcall(pairs)
assert(not ok and err:find("bad argument #1 to 'pairs'"), tostring(err))

print("pairs_order: ok")
