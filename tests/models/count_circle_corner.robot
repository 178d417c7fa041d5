# x^2 + q^2 = 1 with x > 0.6 or q > 0.8: both disjuncts' boundaries cross on the circle at
# (0.6, 0.8); 4 aspects, of which the count proves at least 3 and no upper bound
# (tests/test_exact_count.cpp).
robot circle_corner
pose x in [-2, 2]
command q in [-2, 2]
equation x^2 + q^2 = 1
constraint x > 0.6 or q > 0.8
