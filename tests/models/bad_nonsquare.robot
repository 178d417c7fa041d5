robot Bad
pose x in [0, 1]
command q in [0, 1]
equation x + q = 1
equation x - q = 0
