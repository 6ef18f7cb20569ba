-- expect: 1 "exceeded the instruction limit"
-- a misspelt global read in a loop that catches its error: each suggestion compares the name with every global, work in C no instruction paid for (5e8 instructions took over 120 s, ended only by the wall clock; 5e7 here would take 27 s, past this case's 15 s); now charged to the budget: 0.7 s, as a plain pcall loop
-- args: --max-instructions 50000000 --timeout 15
while true do pcall(function() return truk end) end
