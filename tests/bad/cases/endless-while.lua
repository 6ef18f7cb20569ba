-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- while true do end
-- args: --max-instructions 1000000
while true do end
