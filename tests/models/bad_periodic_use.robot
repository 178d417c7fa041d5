# A periodic command used outside sin() and cos(): reported at the use (line 6), not at
# the declaration (line 4).
robot BadPeriodicUse
pose    x in [-2, 2]
command q in [-pi, pi] periodic
equation x + q^2 = 1
