$ same sheet, small-field fixed format
BEGIN BULK
PSHELL         1      10     1.0
PSHELL         2      10     1.5
MAT1          10 210000.             0.3
GRID          11              0.      0.      0.
GRID          12             10.      0.      0.
GRID          13             20.      0.      0.
GRID          21              0.     10.      0.
GRID          22             10.     10.      0.
GRID          23             20.     10.      0.
GRID          31             30.      0.      5.
GRID          32             30.     10.      5.
CQUAD4       101       1      11      12      22      21
CQUAD4       102       1      12      13      23      22
CTRIA3       201       2      13      31      32
CTRIA3       202       2      13      32      23
ENDDATA
