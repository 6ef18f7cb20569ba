-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- table.move of 10^12 empty entries loops in C
-- args: --max-instructions 1000000
table.move({}, 1, 1e12, 1, {})
