"""What the machine is asked to do besides the program: homing as configured and
the tool-break recovery plan (machine-file sections ``[homing]`` and ``[tool_change]``)."""
