"""The Fanuc dialect: Custom Macro B, calls, system variables, transforms, cycles, the corpus."""
