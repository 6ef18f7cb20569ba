-- three figures from one script (a series), each must be written
local c = bezier{ {0, 0}, {1, 2}, {3, 2}, {4, 0} }
for k = 1, 3 do
  local f = figure{ name = "multi-" .. k, caption = "part " .. k .. " <of> 3",
                    width = "4cm", height = "3cm" }
  f:polygon(c, { labels = "P_%d" })
  f:curve(c:elevate(k - 1))
end
print("defined 3 figures")
