-- expect: 1 "knots.uniform: interval [1, 0] is empty"
-- knots.uniform with a > b
print(knots.uniform(2, 5, 1, 0))
