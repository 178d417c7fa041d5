# A spatial tripod of our own: three prismatic legs, from base points (0, 0, 0), (6, 0, 0)
# and (2, 5, 0), meet at the platform point (x, y, z); the commands are the leg lengths.
# Lengths in one unit of our choice (here dm). det Fx vanishes where z = 0 (the point in the
# base plane): the configurations above and below it lie in different aspects.
robot tripod
pose    x  in [-10, 10]
pose    y  in [-10, 10]
pose    z  in [-10, 10]
command q1 in [3, 9]
command q2 in [3, 9]
command q3 in [3, 9]
equation x^2 + y^2 + z^2 = q1^2
equation (x - 6)^2 + y^2 + z^2 = q2^2
equation (x - 2)^2 + (y - 5)^2 + z^2 = q3^2
