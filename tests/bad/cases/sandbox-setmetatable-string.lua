-- expect: 1 "bad argument #1 to 'setmetatable' (table expected, got string)"
-- setmetatable on a string
setmetatable('', {})
