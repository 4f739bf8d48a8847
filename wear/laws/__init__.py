"""The wear laws of one impact, one module each (angles in degrees from the plate normal, θ; the erosion
literature's α from the surface is 90° − θ; SI units):

- :mod:`wear.laws.local`: errata Eq. 15, dw/dt = K p^α v^β over the moving contact patch (Archard's law is
  α = β = 1);
- :mod:`wear.laws.finnie`: Finnie's (1960) micro-cutting;
- :mod:`wear.laws.deformation`: Bitter's (1963) deformation wear, the impact's plastic work / ε;
- :mod:`wear.laws.combined`: a cutting law (``"local"`` or ``"finnie"``) plus ``"deformation"``, each share reported;
- :mod:`wear.laws.oka`: Oka et al.'s (2005) erosion ratio correlation;
- :mod:`wear.laws.dnv`: DNV-RP-O501's (2015) erosion ratio correlation.

Each module declares its law as a :class:`wear.laws.declaration.Law` (name, case keys, per-impact form, closed form
per record where it has one, calibration scale); :data:`wear.laws.registry.LAWS` lists them, and whatever takes a
law by name (the case schema, the impact's wear, the calibration, the wall) reads that registry. The worn volume of
one impact by the case's law is :mod:`wear.laws.impact`'s. The correlations give a mass ratio; the volume per impact
is E m_p / ρ_plate.
"""
