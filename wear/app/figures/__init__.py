"""Matplotlib figures and pyvista renders, one module per stage (SI units on every axis)."""
