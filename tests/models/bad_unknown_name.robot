# unknown name on line 5
robot Bad
pose x in [0, 1]
command q in [0, 1]
equation x + r = 1
