-- expect: 1 "'coroutine' is not available to figure scripts"
-- coroutines
local co = coroutine.create(function() end)
