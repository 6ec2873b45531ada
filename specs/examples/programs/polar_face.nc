(A flat-sided profile milled on the face in polar coordinate interpolation)
G21 G98 G54
G00 X40. Z2. C0.
G01 Z-1. F200.
G12.1
G01 X40. C10. F100.
G03 X20. C20. R10.
G01 X-40.
C-10.
G03 X-20. C-20. I10. J0
G01 X40.
C0
G13.1
G00 Z10.
M30
