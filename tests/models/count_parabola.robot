# x = q^2 - 1: the branches q > 0 and q < 0, two aspects (tests/test_exact_count.cpp).
robot parabola
pose x in [-2, 2]
command q in [-2, 2]
equation x - q^2 + 1 = 0
