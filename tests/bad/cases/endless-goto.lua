-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- an endless goto loop
-- args: --max-instructions 1000000
::top:: goto top
