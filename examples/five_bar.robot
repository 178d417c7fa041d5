# An asymmetric five-bar of our own (examples/five_bar.py builds the same from Python).
# Lengths in one unit of our choice (here cm), angles in radians.
# Base joints at (0, 0) and (6, 0); proximal links 4 and 3; distal links 5 and 5.
# Pose: the end point (x, y). Commands: the two actuated base angles.
robot five-bar-4-3
pose    x  in [-12, 12]
pose    y  in [-12, 12]
command q1 in [-pi, pi] periodic
command q2 in [-pi, pi] periodic
equation (x - 4*cos(q1))^2 + (y - 4*sin(q1))^2 = 25
equation (x - 6 - 3*cos(q2))^2 + (y - 3*sin(q2))^2 = 25
