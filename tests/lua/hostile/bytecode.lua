-- must stop: binary chunks are refused even when built by hand
local chunk = "\27LuaT\0\25\147\13\10\26\10\4\8\8xV\0\0\0\0\0\0\0\0\0\0\0(w@"
local f = load(chunk, "=evil", "b")
f()
