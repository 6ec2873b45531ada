# frontend.py runs under LinuxCNC's system Python with its `linuxcnc` module (tests/cli/test_linuxcnc_filter.py
# starts it through the linuxcnc launcher); it is not a module of the test suite.
collect_ignore = ["frontend.py"]
