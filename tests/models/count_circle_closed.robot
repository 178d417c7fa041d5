# x^2 + q^2 = 1 with x >= 0.5: the arcs x in [0.5, 1) of the quarters x > 0, 2 aspects
# (tests/test_exact_count.cpp; certificates/checker/tests/count_certs.py).
robot circle_closed
pose x in [-2, 2]
command q in [-2, 2]
equation x^2 + q^2 = 1
constraint x >= 0.5
