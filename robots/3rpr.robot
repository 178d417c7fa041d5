# 3-RPR, paper Section 5.2, parameters of [29]. (x1, x2): a platform vertex,
# x3: platform orientation; commands are the three arm lengths.
robot 3-RPR
# Each pose has one command (the arm lengths), so the commands need no bisection: cutting
# the pose first proves boxes whose commands stay as wide as their image. At eps 0.3: 9.3 M
# boxes and 319 s instead of 15.7 M and 629 s with round robin (bench/RESULTS.md).
bisect pose-first
pose    x1 in [-50, 50]
pose    x2 in [-50, 50]
pose    x3 in [-pi, pi] periodic
command q1 in [10, 32]
command q2 in [10, 32]
command q3 in [10, 32]
equation x1^2 + x2^2 - q1^2 = 0
equation (x1 + 17*cos(x3) - 15.9)^2 + (x2 + 17*sin(x3))^2 - q2^2 = 0
equation (x1 + 20.8*cos(x3 + 0.8822))^2 + (x2 + 20.8*sin(x3 + 0.8822) - 10)^2 - q3^2 = 0
