-- expect: 1 "load: binary (bytecode) chunks are not allowed in figure scripts"
-- load of a bytecode chunk in mode bt
local f = assert(load('\27Lua' .. string.rep('\0', 40), 'evil', 'bt'))
f()
