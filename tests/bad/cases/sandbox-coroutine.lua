-- expect: 1 "attempt to index a nil value (global 'coroutine')"
-- coroutines
local co = coroutine.create(function() end)
