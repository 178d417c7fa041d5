# Issue 50, item 2: the bounds are exactly -pi and pi (the period check accepts them), but
# k16 = 1.1^65536 is about 1e2712: the enclosures reach beyond the doubles.
robot Overflow
constant k0 = 1.1
constant k1 = k0 * k0
constant k2 = k1 * k1
constant k3 = k2 * k2
constant k4 = k3 * k3
constant k5 = k4 * k4
constant k6 = k5 * k5
constant k7 = k6 * k6
constant k8 = k7 * k7
constant k9 = k8 * k8
constant k10 = k9 * k9
constant k11 = k10 * k10
constant k12 = k11 * k11
constant k13 = k12 * k12
constant k14 = k13 * k13
constant k15 = k14 * k14
constant k16 = k15 * k15
pose x in [-1, 1]
command q in [-pi + k16 - k16, pi + k16 - k16] periodic
equation x - sin(q) = 0
