-- expect: 1 "unknown name 'undefined_function'"
-- a call of nil
undefined_function()
