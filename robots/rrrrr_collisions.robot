# RRRRR five-bar with link-collision avoidance, paper Section 5.4.1.
robot RRRRR-collisions
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
# No two non-adjacent moving links intersect. Segments [T,U] and [V,W] are disjoint
# when V and W lie strictly on the same side of line TU, or T and U strictly on the same
# side of line VW. o_TUV = (U - T) x (V - T) gives the side of V w.r.t. line TU.
# links AA' and BB'
let o_AApB = -a1y*9
let o_AApBp = a1x*b1y - a1y*b1x
let o_BBpA = -b1y*(-9)
let o_BBpAp = (b1x - 9)*a1y - b1y*(a1x - 9)
constraint o_AApB*o_AApBp > 0 or o_BBpA*o_BBpAp > 0
# links AA' and B'P
let o_AApP = a1x*x2 - a1y*x1
let o_BpPA = (x1 - b1x)*(-b1y) - (x2 - b1y)*(-b1x)
let o_BpPAp = (x1 - b1x)*(a1y - b1y) - (x2 - b1y)*(a1x - b1x)
constraint o_AApBp*o_AApP > 0 or o_BpPA*o_BpPAp > 0
# links A'P and BB'
let o_ApPB = (x1 - a1x)*(-a1y) - (x2 - a1y)*(9 - a1x)
let o_ApPBp = (x1 - a1x)*(b1y - a1y) - (x2 - a1y)*(b1x - a1x)
let o_BBpP = (b1x - 9)*x2 - b1y*(x1 - 9)
constraint o_ApPB*o_ApPBp > 0 or o_BBpAp*o_BBpP > 0
