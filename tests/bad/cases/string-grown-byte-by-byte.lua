-- expect: 1 "string-grown-byte-by-byte.lua:6: script exceeded the instruction limit of 500000000 instructions"
-- a string grown one byte at a time: each step copies the whole string, so
-- n steps copy n^2/2 bytes within a small memory budget.  Allocated bytes
-- count against the instruction budget (one per 16), which stops it in
-- about a second instead of at the 60 s watchdog (a fuzzer finding).
local s = 'x'; while true do s = s .. 3 end
