# Issue 50, item 2: the bounds are exactly -pi and pi (the period check accepts them), but
# k12 = 1.1^4096 is about 1e169: the domain evaluates to about 1e158 wide, not one period.
robot Wide
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
pose x in [-1, 1]
command q in [-pi + k12 - k12, pi + k12 - k12] periodic
equation x - sin(q) = 0
