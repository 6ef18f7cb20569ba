-- expect: 1 "figure: a figure named "same" is already defined"
-- two figures with the same name
figure{ name = 'same' }
figure{ name = 'same' }
