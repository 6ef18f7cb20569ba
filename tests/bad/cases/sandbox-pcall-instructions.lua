-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- pcall catching the instruction limit
-- args: --max-instructions 1000000
while true do pcall(function() while true do end end) end
