# A periodic pose whose nonsingular arc crosses the +-pi seam: det Fx = sin(t) + cos(t)/2
# vanishes at -atan(1/2) and pi - atan(1/2), so one aspect holds t = +-pi (query/path tests).
robot Seam
pose    t in [-pi, pi] periodic
command q in [0, 4]
equation q - 2 - cos(t) + sin(t)/2 = 0
