-- expect: 1 "message-figure-twice.lua:3); the names name the files, so they must differ"
-- two figures with one name: the message says where the first one is
local f = figure{ name = 'z' }
local g = figure{ name = 'z' }
