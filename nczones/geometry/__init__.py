"""Exact curve geometry the front end and both witnesses share: the developed
cylinder (G07.1), the polar plane (G12.1) and rational NURBS."""
