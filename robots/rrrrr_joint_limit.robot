# RRRRR five-bar with a joint limit on the passive joint P, paper Section 5.4.2.
robot RRRRR-joint-limit
pose    x1 in [-20, 20]
pose    x2 in [-20, 20]
command q1 in [-pi, pi] periodic
command q2 in [-pi, pi] periodic
# Joint positions: A = (0, 0), A' = (a1x, a1y), P = (x1, x2), B = (9, 0), B' = (b1x, b1y).
let a1x = 8*cos(q1)
let a1y = 8*sin(q1)
let b1x = 9 + 5*cos(q2)
let b1y = 5*sin(q2)
equation (x1 - a1x)^2 + (x2 - a1y)^2 - 25 = 0
equation (x1 - b1x)^2 + (x2 - b1y)^2 - 64 = 0
# The angle of the passive joint P, between the links PA' and PB', stays in
# [-pi/2, pi/2]: (A' - P) . (B' - P) >= 0.
constraint (a1x - x1)*(b1x - x1) + (a1y - x2)*(b1y - x2) >= 0
