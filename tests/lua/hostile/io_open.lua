-- must stop: io is not in the sandbox
local f = io.open("hostile-was-here", "w")
f:write("x")
