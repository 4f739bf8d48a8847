"""The worn volume of one impact by the case's wear law (:data:`wear.laws.registry.LAWS`): by mechanism
(:func:`impact_wear`), from the particle's kinematics alone for a closed form (:func:`closed_form_volume`), and laid
out as a depth map on the surface grid (:func:`wear_of_impact`). SI units; angles in degrees from the plate normal.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from contact import ImpactResult, Material
from wear.integrate import WearMap, integrate_wear, surface_grid, wear_map
from wear.law import WearLaw
from wear.laws.declaration import Constants
from wear.laws.local import LAW as LOCAL_LAW
from wear.laws.registry import closed_form_laws, law_named, parts_of
from wear.pressure import PressureHistory
from wear.slip import SlidingSpeed

__all__ = ["ImpactWear", "closed_form_volume", "impact_wear", "wear_of_impact"]


@dataclass(frozen=True)
class ImpactWear:
    """The worn volume of one impact by mechanism: ``parts`` (name → m³: ``cutting`` and ``deformation``, or the
    correlation's name), ``law``; :attr:`volume_m3` their sum, :meth:`share` each one's fraction."""

    law: str
    parts: dict[str, float] = field(default_factory=dict)

    @property
    def volume_m3(self) -> float:
        return float(sum(self.parts.values()))

    def share(self, part: str) -> float:
        """Fraction of the volume worn by ``part`` (0 when nothing is worn)."""
        total = self.volume_m3
        return self.parts.get(part, 0.0) / total if total > 0.0 else 0.0


def impact_wear(
    law: str,
    constants: Constants,
    impact: ImpactResult,
    *,
    local: float | None = None,
    plate_work: float | None = None,
) -> ImpactWear:
    """The worn volume of ``impact`` by the wear ``law`` (one of :data:`wear.laws.registry.LAWS`) with ``constants``
    (the ``[wear]`` table's keys plus the plate's ``hardness``). ``local``: the Eq. 15 volume (m³,
    :func:`wear.laws.local.local_volume`) where the law uses it; ``plate_work``: the FE plate's plastic dissipation
    (J), if the plate is the FE."""
    volumes = law_named(law).volumes(constants, impact, local=local, plate_work=plate_work)
    return ImpactWear(law, volumes)


def closed_form_volume(
    law: str,
    constants: Constants,
    radius: float,
    ball_density: float,
    plate: Material,
    speed,
    angle,
) -> np.ndarray:
    """The worn volume (m³) of one impact of a ball of ``radius`` (m) and ``ball_density`` (kg/m³) on ``plate`` at
    each ``speed`` (m/s) and ``angle`` (deg from the normal) by a law with a closed form
    (:func:`wear.laws.registry.closed_form_laws`) with ``constants`` (as :func:`impact_wear`): a formula of the
    particle's kinematics alone, so that no impact need be simulated."""
    form = law_named(law).closed_form
    if form is None:
        raise ValueError(f"wear.law={law!r} has no closed form: one of {', '.join(map(repr, closed_form_laws()))} has")
    return form(constants, radius, ball_density, plate, speed, angle)


#: The unit-K local laws whose maps give each mechanism's footprint: cutting follows the sliding (α = β = 1: where
#: the friction works), the rest where the plate is pressed (α = 1, β = 0: the time-integrated pressure).
_SHAPES = {"cutting": WearLaw(K=1.0, alpha=1.0, beta=1.0), "pressed": WearLaw(K=1.0, alpha=1.0, beta=0.0)}


def wear_of_impact(
    law: str,
    constants: Constants,
    local_law: WearLaw,
    impact: ImpactResult,
    pressure: PressureHistory,
    speed: SlidingSpeed,
    *,
    density: float,
    points_across: int,
    plate_work: float | None = None,
) -> tuple[WearMap, ImpactWear]:
    """The depth map (m) and the volumes of ``impact`` worn by ``law`` (:func:`impact_wear`). The local law's map is
    Eq. 15 integrated over the moving patch (:func:`wear.integrate_wear` with ``local_law``); every other
    mechanism's volume is laid out like a unit local law: cutting along the sliding (α = β = 1), deformation and the
    correlations where the plate is pressed (α = 1, β = 0; the pressure shape if nothing slides)."""
    parts = parts_of(law, constants)
    local_map = None
    if any(part.uses_local for part in parts):
        local_map = integrate_wear(pressure, speed, local_law, density=density, points_across=points_across)
    wear = impact_wear(
        law, constants, impact, local=None if local_map is None else local_map.volume_m3, plate_work=plate_work
    )
    if parts == (LOCAL_LAW,):
        return local_map, wear
    if local_map is not None:
        grid = local_map
    else:
        x, y = surface_grid(pressure, points_across)
        grid = wear_map(x, y, np.zeros((y.size, x.size)), density)
    depth = np.zeros_like(grid.depth)
    for part, volume in wear.parts.items():
        if part == "cutting" and local_map is not None:
            depth += local_map.depth
            continue
        if volume <= 0.0:
            continue
        shape = integrate_wear(
            pressure, speed, _SHAPES["cutting" if part == "cutting" else "pressed"], density=density, on=grid
        )
        if shape.volume_m3 <= 0.0:  # no sliding: the pressure shape
            shape = integrate_wear(pressure, speed, _SHAPES["pressed"], density=density, on=grid)
        depth += volume / shape.volume_m3 * shape.depth
    return wear_map(grid.x, grid.y, depth, density), wear
