robot Bad
pose x in [3, 1]
command q in [0, 1]
equation x + q = 1
