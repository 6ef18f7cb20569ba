-- expect: 1 "(error object is a nil value)"
-- error(nil)
error(nil)
