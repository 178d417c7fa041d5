# 3-RPR (robots/3rpr.robot) on a window of the workspace, x1, x2 in [5, 13]: a quick
# benchmark case for the regularity tests (the full domain at eps 1 takes 220 s per run).
robot 3-RPR
pose    x1 in [5, 13]
pose    x2 in [5, 13]
pose    x3 in [-pi, pi] periodic
command q1 in [10, 32]
command q2 in [10, 32]
command q3 in [10, 32]
equation x1^2 + x2^2 - q1^2 = 0
equation (x1 + 17*cos(x3) - 15.9)^2 + (x2 + 17*sin(x3))^2 - q2^2 = 0
equation (x1 + 20.8*cos(x3 + 0.8822))^2 + (x2 + 20.8*sin(x3 + 0.8822) - 10)^2 - q3^2 = 0
