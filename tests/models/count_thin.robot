# det Fx = -(x - 0.3)(x - 0.31): an aspect 0.01 wide, three in all (tests/test_exact_count.cpp).
robot thin
pose x in [-1, 1]
command q in [-5, 5]
equation q - (x^3/3 - 0.61*x^2/2 + 0.093*x) = 0
