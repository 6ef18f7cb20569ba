-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- pcall and xpcall catch the limit's error and loop on
-- args: --max-instructions 1000000
while true do
  pcall(function() while true do end end)
  xpcall(function() while true do end end, function(e) return e end)
end
