"""Independent oracles shared by several test areas (brute-force path checkers)."""
