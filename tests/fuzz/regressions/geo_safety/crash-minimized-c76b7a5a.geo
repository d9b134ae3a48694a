Include "cas0;
Syste(1) = {0, 0, 0}; Point(2) = {L, 0, oint(3) 1, 2}; Li) = {2ÿ
3}; Lne(3) = {3, 4}-; Lin
TransfiniteysicaSyCalcl
ransfi}SystemCalcl} = 2;
Transfinitl
sicaSyCalcl
initeysicaSystemCalcl
cl
 n + 1;
Transfinite Curve{2, 4} = 2;
TransfiniteysicaSyCalcl
