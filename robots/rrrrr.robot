# RRRRR five-bar, paper Section 5.2 (architecture parameters of [5]).
# Anchors A = (0, 0) and B = (9, 0); proximal links 8 and 5, distal links 5 and 8.
robot RRRRR
# Cut the pose where it blocked the proof, else round robin: at eps 0.1, 89,134 boxes
# instead of 107,510, the same 10 filtered CSNCs and bound 10 (bench/RESULTS.md).
bisect verdict
pose    x1 in [-20, 20]
pose    x2 in [-20, 20]
command q1 in [-pi, pi] periodic
command q2 in [-pi, pi] periodic
equation (x1 - 8*cos(q1))^2 + (x2 - 8*sin(q1))^2 - 25 = 0
equation (x1 - 9 - 5*cos(q2))^2 + (x2 - 5*sin(q2))^2 - 64 = 0
