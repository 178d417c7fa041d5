# A user factor: aspects count refuses it (its classes need not be the aspects' classes).
robot userfactor
pose x in [-2, 2]
command q in [-2, 2]
equation x^2 + q^2 = 1
factor x - 0.5
