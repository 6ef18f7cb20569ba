-- expect: 1 "xxxx\frob{y}yyyyyyyyyyyyyyyy...": unknown command \frob (`curvefig help labels` lists the commands) at byte 300
-- a label's error 300 bytes in: the message quotes the text around the byte, not the whole label
local f = figure{ name = "l" }
f:label({0, 0}, string.rep("x", 300) .. "\\frob{y}" .. string.rep("y", 300))
