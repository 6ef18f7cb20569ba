-- expect: 1 "load: binary (bytecode) chunks are not allowed in figure scripts"
-- load of a bytecode chunk
local f = assert(load('\27LuaT\0\25\147\13\10\26\10\4\8\8xV\0\0\0\0\0\0\0\0\0\0\0(w@', 'evil', 'b'))
f()
