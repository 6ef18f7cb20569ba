-- label_place as a function(i, x, y): the same figure as with the table of
-- places that function gives (test_tool.c compares the two SVGs byte for
-- byte), and a bad return value named with its label.
local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local function place(i, x, y)
  assert(math.type(i) == "integer" and P[i + 1][1] == x and P[i + 1][2] == y)
  if i == 2 then return nil end          -- the default place
  return x < 3 and "w" or (y > 2.5 and "ne" or "se")
end
local places = {}
for i, q in ipairs(P) do places[i] = place(i - 1, q[1], q[2]) end
local t = figure{ name = "place-table", width = "6cm", height = "5cm" }
t:polygon(P, { labels = "P_%d", label_start = 0, label_place = places })
local f = figure{ name = "place-fn", width = "6cm", height = "5cm" }
f:polygon(P, { labels = "P_%d", label_start = 0, label_place = place })
local ok, err = pcall(function()
  figure{ name = "bad" }:polygon(P, { labels = "P_%d", label_start = 0,
    label_place = function(i) return i == 4 and 17 or "n" end })
end)
assert(not ok and err:find('the label "P_4" got a number', 1, true), err)
print("label_place function: ok")
