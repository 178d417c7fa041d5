# x = 1.5 sin q, q on the circle: the aspects cos q > 0 and cos q < 0, the second across the
# seam q = pi (its pieces joined through a 2*pi shift): two aspects.
robot seam
pose x in [-1, 1]
command q in [-pi, pi] periodic
equation x - 1.5*sin(q) = 0
