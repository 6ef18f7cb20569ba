-- expect: 1 "attempt to call a nil value (global 'undefined_function')"
-- a call of nil
undefined_function()
