# RPRPR (bipod), paper Section 5.2, parameters of [28]: anchors (0, 0) and (9, 0),
# commands are the two arm lengths.
robot RPRPR
pose    x1 in [-20, 20]
pose    x2 in [-20, 20]
command q1 in [2, 6]
command q2 in [4, 9]
equation x1^2 + x2^2 - q1^2 = 0
equation (x1 - 9)^2 + x2^2 - q2^2 = 0
