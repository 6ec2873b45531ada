"""Lathes: diameter programming, lathe tool offsets, the Fanuc lathe dialect and the turning cycles."""
