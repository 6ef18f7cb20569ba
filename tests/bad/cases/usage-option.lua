-- expect: 2 "unknown option '--frobnicate'"
-- an unknown option
-- args: --frobnicate
figure{ name = 'z' }
