# x^2 + q^2 = 1 with x > 0.5 or q > 0.5: the first quarter, q in (0.5, 1) of the second,
# x in (0.5, 1) of the fourth: 3 aspects (tests/test_exact_count.cpp).
robot circle_or
pose x in [-2, 2]
command q in [-2, 2]
equation x^2 + q^2 = 1
constraint x > 0.5 or q > 0.5
