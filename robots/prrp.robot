# PRRP, paper Section 2, equation (1): (x - a)^2 + (q - b)^2 = l^2.
# The paper gives no parameters; we use a = 0, b = 0, l = 1 and x, q in [-2, 2].
robot PRRP
constant a = 0
constant b = 0
constant l = 1
pose    x in [-2, 2]
command q in [-2, 2]
equation (x - a)^2 + (q - b)^2 = l^2
