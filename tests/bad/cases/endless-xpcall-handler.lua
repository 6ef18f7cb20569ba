-- expect: 1 "script exceeded the instruction limit of 1000000 instructions"
-- xpcall's message handler loops (it ran with the hooks off inside the limit's error)
-- args: --max-instructions 1000000
xpcall(error, function() while true do end end)
