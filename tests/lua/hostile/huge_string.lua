-- must stop: a string doubled without end
local s = "x"
while true do s = s .. s end
