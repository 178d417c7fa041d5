# The bow tie pinched at x1 = 0: its halves are two aspects of one class, three in all
# (tests/test_exact_count.cpp).
robot bow_tie
pose x1 in [-1, 1]
pose x2 in [-1, 1]
command q1 in [-1, 1]
command q2 in [-5, 5]
equation q1 - x1 = 0
equation q2 - (x2^3/3 - (x1^2 - 0.0001)*x2) = 0
