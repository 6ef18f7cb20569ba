-- expect: 1 "basis: N_0^3 needs knots u_0..u_4, 3 given"
-- basis function on a knot list that is too short
print(basis({0, 1, 2}, 0, 3, 0.5))
