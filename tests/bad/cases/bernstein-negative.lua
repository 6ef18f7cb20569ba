-- expect: 1 "bernstein: n is -2; it must be in [0, 1024]"
-- Bernstein polynomial of degree -2
print(bernstein(-2, 0, 0.5))
