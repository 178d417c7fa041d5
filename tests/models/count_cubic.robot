# q = x^3/3 - x: three aspects, the outer two of one sign class (tests/test_exact_count.cpp).
robot cubic
pose x in [-2, 2]
command q in [-5, 5]
equation q - x^3/3 + x = 0
