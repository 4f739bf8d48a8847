"""fem: an axisymmetric (r, z) elastic-plastic plate pressed by a sphere, in scikit-fem (SI units)."""
