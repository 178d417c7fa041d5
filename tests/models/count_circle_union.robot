# x^2 + q^2 = 1 with x >= 0.6 or 2*x - q >= 0.4: both boundaries cross the first quarter at
# (0.6, 0.8), on the same side: the union is star-shaped there; 3 aspects
# (tests/test_exact_count.cpp).
robot circle_union
pose x in [-2, 2]
command q in [-2, 2]
equation x^2 + q^2 = 1
constraint x >= 0.6 or 2*x - q >= 0.4
