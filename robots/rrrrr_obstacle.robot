# RRRRR five-bar with a circular obstacle, paper Section 5.4.3.
robot RRRRR-obstacle
pose    x1 in [-20, 20]
pose    x2 in [-20, 20]
command q1 in [-pi, pi] periodic
command q2 in [-pi, pi] periodic
# Joint positions: A = (0, 0), A' = (a1x, a1y), P = (x1, x2), B = (9, 0), B' = (b1x, b1y).
let a1x = 8*cos(q1)
let a1y = 8*sin(q1)
let b1x = 9 + 5*cos(q2)
let b1y = 5*sin(q2)
equation (x1 - a1x)^2 + (x2 - a1y)^2 - 25 = 0
equation (x1 - b1x)^2 + (x2 - b1y)^2 - 64 = 0
# Obstacle: centre C = (cx, cy), radius r. No link may touch it: a segment [T,U] misses
# the disc when both ends are outside it and either the foot of the perpendicular from C
# falls outside the segment or the line TU passes farther than r from C:
#   |C-T|^2 > r^2 and |C-U|^2 > r^2 and
#   ((C-T).(U-T) <= 0 or (C-U).(T-U) <= 0 or ((U-T) x (C-T))^2 > r^2 |U-T|^2)
# The anchors A and B are 4.5 from C: their distance terms are constant and omitted.
constant cx = 4.5
constant cy = 0
constant r = 1
# link AA' (length 8)
constraint ((cx - a1x)^2 + (cy - a1y)^2 > r^2 and
  (cx*a1x + cy*a1y <= 0 or (cx - a1x)*(-a1x) + (cy - a1y)*(-a1y) <= 0 or (a1x*cy - a1y*cx)^2 > r^2*64))
# link A'P (length 5)
constraint ((cx - a1x)^2 + (cy - a1y)^2 > r^2 and (cx - x1)^2 + (cy - x2)^2 > r^2 and
  ((cx - a1x)*(x1 - a1x) + (cy - a1y)*(x2 - a1y) <= 0 or (cx - x1)*(a1x - x1) + (cy - x2)*(a1y - x2) <= 0 or ((x1 - a1x)*(cy - a1y) - (x2 - a1y)*(cx - a1x))^2 > r^2*25))
# link BB' (length 5)
constraint ((cx - b1x)^2 + (cy - b1y)^2 > r^2 and
  ((cx - 9)*(b1x - 9) + cy*b1y <= 0 or (cx - b1x)*(9 - b1x) + (cy - b1y)*(-b1y) <= 0 or ((b1x - 9)*cy - b1y*(cx - 9))^2 > r^2*25))
# link B'P (length 8)
constraint ((cx - b1x)^2 + (cy - b1y)^2 > r^2 and (cx - x1)^2 + (cy - x2)^2 > r^2 and
  ((cx - b1x)*(x1 - b1x) + (cy - b1y)*(x2 - b1y) <= 0 or (cx - x1)*(b1x - x1) + (cy - x2)*(b1y - x2) <= 0 or ((x1 - b1x)*(cy - b1y) - (x2 - b1y)*(cx - b1x))^2 > r^2*64))
