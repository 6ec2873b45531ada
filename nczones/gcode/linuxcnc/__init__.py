"""What only the LinuxCNC dialect has: its state parameters, x87 trigonometry, splines,
cutter compensation, lathe cycles G70-G72 and the double pass (the shared front end is in
``nczones.gcode``; the Fanuc dialect in ``nczones.gcode.fanuc``)."""
