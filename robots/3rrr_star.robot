# 3-RRR*, paper Section 5.2, parameters of [28], with the platform orientation fixed
# (x3 = 0) as in the paper. x3 stays a pose variable, hence a column of Fx.
robot 3-RRR*
pose    x1 in [-50, 50]
pose    x2 in [-50, 50]
pose    x3 in [0, 0]
command q1 in [-pi, pi] periodic
command q2 in [-pi, pi] periodic
command q3 in [-pi, pi] periodic
equation (x1 - 10 - 10*cos(q1))^2 + (x2 - 10 - 10*sin(q1))^2 - 100 = 0
equation (x1 + 10*cos(x3) - 10 - 10*cos(q2))^2 + (x2 + 10*sin(x3) - 10 - 10*sin(q2))^2 - 100 = 0
equation (x1 + 10*sqrt(2)*cos(x3 + pi/4) - 10*cos(q3))^2 + (x2 + 10*sqrt(2)*sin(x3 + pi/4) - 10 - 10*sin(q3))^2 - 100 = 0
