# 3-RRR, the full planar robot of paper Section 5.2 with the parameters of [28]: the
# platform orientation x3 is free over one period. The paper computes only the slice
# x3 = 0 (3rrr_star.robot) and leaves the number of aspects of this robot open.
# Leg i: base joint at A_i, proximal link 10 at angle q_i, distal link 10 to the platform
# point P_i(x): A1 = (10, 10), A2 = (10, 10), A3 = (0, 10); P1 = (x1, x2),
# P2 = (x1, x2) + 10 (cos x3, sin x3), P3 = (x1, x2) + 10 sqrt(2) (cos(x3 + pi/4), sin(x3 + pi/4)).
# Fq is diagonal, so det Fq factors into the three legs' serial singularities.
robot 3-RRR
pose    x1 in [-50, 50]
pose    x2 in [-50, 50]
pose    x3 in [-pi, pi] periodic
command q1 in [-pi, pi] periodic
command q2 in [-pi, pi] periodic
command q3 in [-pi, pi] periodic
equation (x1 - 10 - 10*cos(q1))^2 + (x2 - 10 - 10*sin(q1))^2 - 100 = 0
equation (x1 + 10*cos(x3) - 10 - 10*cos(q2))^2 + (x2 + 10*sin(x3) - 10 - 10*sin(q2))^2 - 100 = 0
equation (x1 + 10*sqrt(2)*cos(x3 + pi/4) - 10*cos(q3))^2 + (x2 + 10*sqrt(2)*sin(x3 + pi/4) - 10 - 10*sin(q3))^2 - 100 = 0
