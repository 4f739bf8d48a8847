r"""The wear laws of :mod:`wear.laws` applied to each impact record of a wall: :func:`wall_law` turns a case into a
law object whose :meth:`volume` gives the eroded volume (m³) of every record from its angle θ (deg from the wall
normal), speed V (m/s), particle diameter d (m) and density ρ_p (kg/m³) and the particles N it stands for. A
record delivers the mass N m, :math:`m = \rho_p \pi d^3 / 6`.

A law with a closed form evaluates its formula on whole arrays, by its own module's
:attr:`~wear.laws.declaration.Law.per_record` (one copy):

- ``finnie``: :math:`W = N\,\mathrm{finnie}(m, V, \theta)` (:class:`wear.laws.finnie.FinnieLaw`; the plate's flow
  pressure ``plate.hardness``, else 3 Y, and ``wear.cutting_fraction``, ``wear.force_ratio``, ``wear.depth_ratio``);
- ``oka``: :math:`W = N m\,E_{\mathrm{Oka}}(V, \theta, d) / \rho_w` (:class:`wear.laws.oka.OkaLaw`, at each
  record's own diameter: not proportional to the mass, as :math:`E \propto d^{0.19}`);
- ``dnv``: :math:`W = N m\,K V^n F(\alpha) / \rho_w` (:class:`wear.laws.dnv.DnvLaw`).

The FE-informed laws (those without a closed form: ``local``, ``deformation``, ``combined``; they need the impact
itself: its pressure, sliding and plastic work) go through the erosion's response table
(:func:`wear.erosion.table.build_response_table` of the case's :func:`wear.erosion.run.impact_response`), built once per
law over normal speed × angle (:class:`TableLaw`), and looked up per record by :func:`wear.erosion.table.table_entries`
(power law in the normal speed along a line of constant speed, linear in the angle). Beyond the table's last angle θ_top
the volume goes linearly to 0 at 90°, where it vanishes for every law (no normal speed: no pressure, no plastic work). A
calibrated case (``calibrated.toml`` of ``impactwear calibrate``) is a case like any other: its fitted constants are the
``[wear]`` keys the law reads.

**Size scaling.** The table holds the volume per unit particle mass, :math:`w(V, \theta) = W / m`, at the case's
particle (``ball.radius``, ``ball.density``, ``ball.E``, ``ball.nu``); a record of diameter d erodes
:math:`W = N\,m(d)\,w(V, \theta)`. This is exact for the impact models the table runs on: the Hertz and Thornton
normal laws, the tangential laws and the closed-form pressures have no length of their own, so at fixed materials,
speed and angle an impact of a sphere of radius R is self-similar in R (lengths ∝ R, times ∝ R — the time step is
a fraction of the contact time and the wear grid a number of points across the contact —, pressures and speeds
independent of R): Eq. 15's :math:`K\int v^\beta \int p^\alpha\,dA\,dt \propto R^3` and Bitter's plastic work
:math:`\propto m`. Measured: a direct impact at three times the diameter gives the scaled volume to 1.3e-14
(tests/test_wall_laws.py). The particle's material is the table's: a record of another density is refused.

**Cost and accuracy of the table.** Only the entries a record in [``wall.table_speed_min``,
``wall.table_speed_max``] can reach are computed (within one speed step of its normal speeds). The default
``[wall]`` table, 24 normal speeds x 37 angles (2.5° apart) over 0.1-100 m/s, is 603 impacts: 15 s for the local law
of silica sand on steel (Thornton's pressure), 32 s for the combined law, on one core of a busy 2-core machine, and a
lookup runs at ~5e6 records/s (the closed forms 1.6e7-2.4e7). Against the impact computed directly at 40 random
(speed, angle) it measured median 0.14 %, at most 13 % of a small volume (2° from the normal, where the sticking of
slow oblique impacts bends the local law's curve) and 1.7 % of the largest volume at that speed; the coarse table of
the tests is checked in tests/test_wall_laws.py.
"""

from __future__ import annotations

import functools
import math
import time
from collections.abc import Callable
from dataclasses import dataclass

import numba
import numpy as np

from contact.checks import check_instance
from wear.case import Case
from wear.case.progress import progress_bar
from wear.erosion.response import Footprint, ImpactResponse
from wear.erosion.run import impact_response
from wear.erosion.table import build_response_table, table_entries
from wear.laws.records import RecordLaw, particle_mass, record_arrays
from wear.laws.registry import law_named

__all__ = [
    "TableLaw",
    "WallLaw",
    "records_refusal",
    "table_axes_of",
    "table_refusal",
    "wall_law",
]

#: Impacts of the response table run at a time (the progress bar moves between batches).
TABLE_BATCH = 32
#: Relative tolerance of a record's particle density against the table's (a CSV prints ~15 digits).
DENSITY_TOLERANCE = 1e-9


@numba.njit(cache=True)
def _table_volumes(normal_speeds, angles, per_kg, speed, angle, mass, count):
    """N m w(V, θ) per record from the table ``per_kg`` (m³/kg) over ``normal_speeds`` × ``angles``; linear to 0
    at 90° beyond the last angle."""
    top = angles[-1]
    out = np.empty(speed.size)
    for i in range(speed.size):
        theta = min(angle[i], top)
        _, w, _ = table_entries(normal_speeds, angles, per_kg, speed[i], theta)
        if angle[i] > top:
            w *= (90.0 - angle[i]) / (90.0 - top)
        out[i] = count[i] * (mass[i] * w)
    return out


@dataclass(frozen=True, eq=False)
class TableLaw:
    """An FE-informed law through the response table, per unit particle mass (see the module docstring):
    ``normal_speed`` (ns,) m/s and ``angle`` (na,) deg, the table's axes; ``volume_per_kg`` (ns, na) m³ per kg of
    particles; the speeds it covers, ``speed_min`` to ``speed_max`` (m/s); the table's particle ``density``
    (kg/m³) and ``diameter`` (m); ``seconds``: the time the table took to build."""

    normal_speed: np.ndarray
    angle: np.ndarray
    volume_per_kg: np.ndarray
    speed_min: float
    speed_max: float
    density: float
    diameter: float
    seconds: float
    name: str
    description: str

    def refused(self, speed_m_s, density_kg_m3) -> tuple[int, str, str] | None:
        """The first record the table cannot take, as (its index, the record field: ``"velocity"`` or
        ``"density"``, what is wrong with it), or None: :func:`table_refusal`."""
        return table_refusal(speed_m_s, density_kg_m3, self.speed_min, self.speed_max, self.density, self.name)

    def volume(self, angle_deg, speed_m_s, diameter_m, density_kg_m3, count) -> np.ndarray:
        """Eroded volume (m³) of each record: N m w(V, θ). A record the table cannot take (:meth:`refused`) is a
        one-line ``ValueError`` naming its index."""
        theta, speed, d, rho, n = record_arrays(angle_deg, speed_m_s, diameter_m, density_kg_m3, count)
        bad = self.refused(speed, rho)
        if bad is not None:
            i, field_name, why = bad
            name = "speed_m_s" if field_name == "velocity" else "density_kg_m3"
            raise ValueError(f"{name}[{i}]: {why}")
        return _table_volumes(self.normal_speed, self.angle, self.volume_per_kg, speed, theta, particle_mass(d, rho), n)


def table_refusal(
    speed_m_s, density_kg_m3, speed_min: float, speed_max: float, density: float, name: str
) -> tuple[int, str, str] | None:
    """The first record a response table of the law ``name`` for speeds ``speed_min`` to ``speed_max`` (m/s) and
    particles of ``density`` (kg/m³) cannot take, as (its index, the record field: ``"velocity"`` or ``"density"``,
    what is wrong with it), or None: a speed outside the table, a particle density other than the table's."""
    speed, rho = np.asarray(speed_m_s, float).reshape(-1), np.asarray(density_kg_m3, float).reshape(-1)
    outside = np.flatnonzero((speed < speed_min) | (speed > speed_max))
    if len(outside):
        i = int(outside[0])
        return (
            i,
            "velocity",
            (
                f"the speed {speed[i]:.6g} m/s is outside the response table's speeds [{speed_min:g}, "
                f"{speed_max:g}] m/s: widen wall.table_speed_min / wall.table_speed_max"
            ),
        )
    other = np.flatnonzero(np.abs(rho - density) > DENSITY_TOLERANCE * density)
    if len(other):
        i = int(other[0])
        return (
            i,
            "density",
            (
                f"{rho[i]:.6g} kg/m^3 is not the response table's particle density ball.density={density:g} "
                f"kg/m^3: the {name} law's table is for one particle material"
            ),
        )
    return None


#: The law of a wall: a closed form's per record (:attr:`wear.laws.declaration.Law.per_record`) or an FE-informed
#: law's response table (:class:`TableLaw`).
WallLaw = RecordLaw


def table_axes_of(case: Case) -> tuple[np.ndarray, np.ndarray]:
    r"""The wall's response-table axes (normal speeds m/s, angles deg): ``wall.table_angles`` angles from 0 to
    ``wall.table_angle_max`` evenly, ``wall.table_speeds`` normal speeds in geometric progression from
    :math:`V_{min}\cos\theta_{top}` to :math:`V_{max}` (the normal speeds of every speed of
    [``wall.table_speed_min``, ``wall.table_speed_max``] at every angle of the table)."""
    w = case.wall
    angles = np.linspace(0.0, w.table_angle_max, w.table_angles)
    return np.geomspace(w.table_normal_speed_min(), w.table_speed_max, w.table_speeds), angles


@dataclass(frozen=True)
class _Band:
    """The ``response`` run only where a record of speed ``low`` to ``high`` (m/s) is looked up: within one grid
    step ``ratio`` of the normal speeds V cos θ of that range; elsewhere a footprint of NaN volume, which no lookup
    reaches (a corner of the rectangular table: a normal speed of 100 m/s at 89° is a speed of 5730 m/s). The
    impacts run in batches of :data:`TABLE_BATCH`, with a progress bar unless ``quiet``."""

    response: ImpactResponse
    low: float
    high: float
    ratio: float
    quiet: bool = True

    def many(self, normal_speeds, angles) -> list[Footprint]:
        """The footprints at ``normal_speeds`` (m/s) and ``angles`` (deg), batched runs of those used."""
        cosine = np.cos(np.radians(angles))
        used = (normal_speeds <= self.high * cosine * self.ratio) & (normal_speeds >= self.low * cosine / self.ratio)
        speeds, thetas = normal_speeds[used], angles[used]
        computed: list[Footprint] = []
        with progress_bar(len(speeds), "impactwear wall: response table", "impact", self.quiet) as update:
            for start in range(0, len(speeds), TABLE_BATCH):
                part = slice(start, start + TABLE_BATCH)
                computed += self.response.many(speeds[part], thetas[part])
                update(len(computed))
        found = iter(computed)
        unit = np.array([-1.0, 0.0, 1.0])
        unused = Footprint(unit, unit, np.zeros((3, 3)), 1.0, cutting_volume_m3=math.nan)
        return [next(found) if u else unused for u in used]


def _table_law(case: Case, progress: bool) -> TableLaw:
    """The case's FE-informed law through its response table (built now; ``progress``: a bar on stderr)."""
    response = impact_response(case)
    speeds, angles = table_axes_of(case)
    w = case.wall
    band = _Band(response, w.table_speed_min, w.table_speed_max, (1.0 + 1e-9) * speeds[1] / speeds[0], not progress)
    # one impact first: a law that cannot run on this case (no plastic work on an elastic normal law) fails in one
    # impact rather than after the whole table's
    response.many(speeds[-1:], angles[:1])
    t0 = time.perf_counter()
    # the footprints' resampling grid is not used (only the volumes): the coarsest one
    table = build_response_table(
        band,
        speeds,
        angles,
        points_per_length=4,
        particle_radius=response.radius,
        particle_mass=response.particle_mass,
        plate_density=response.plate.density,
    )
    seconds = time.perf_counter() - t0
    impacts = int(np.isfinite(table.volume_m3).sum())
    cutting = f" (cutting: {case.wear.cutting})" if law_named(case.wear.law).parts is not None else ""
    description = (
        f"{law_named(case.wear.law).description}{cutting}, through the response table per unit particle mass: "
        f"{speeds.size} normal speeds x {angles.size} angles ({impacts} impacts) for {w.table_speed_min:g} to "
        f"{w.table_speed_max:g} m/s at 0 to {w.table_angle_max:g} deg, built in {seconds:.3g} s; "
        f"ImpactResponse(pressure={response.pressure!r}, normal_model={response.normal_model!r}, law: {response.law})"
    )
    return TableLaw(
        normal_speed=table.normal_speed,
        angle=table.angle,
        volume_per_kg=table.volume_m3 / table.particle_mass,
        speed_min=w.table_speed_min,
        speed_max=w.table_speed_max,
        density=case.ball.density,
        diameter=2.0 * case.ball.radius,
        seconds=seconds,
        name=case.wear.law,
        description=description,
    )


def wall_law(case: Case, progress: bool = False) -> WallLaw:
    """The case's wear law (``wear.law``) per record of a wall (see the module docstring): a closed form, or the
    response table of an FE-informed law (built now: :attr:`TableLaw.seconds`; ``progress``: a bar on stderr)."""
    check_instance("case", case, Case, "a wear.Case: wear.case.default_case('wall') or wear.case.load_case(path)")
    law, plate = law_named(case.wear.law), case.plate
    constants = {**case.wear.values(), "hardness": plate.hardness}
    material = plate.material()
    if law.per_record is None:
        return _table_law(case, progress)
    if plate.rigid:
        raise ValueError(f"plate.rigid=true: wear.law={law.name!r} erodes the plate, which needs its density (kg/m^3)")
    return law.per_record(constants, material)


def records_refusal(case: Case) -> Callable[[np.ndarray, np.ndarray], tuple[int, str, str] | None] | None:
    """The check of :meth:`TableLaw.refused` the case's law will make on each record, before its table is built
    (the records that table cannot take are found in seconds rather than after it): None for a closed form, which
    takes every record."""
    if law_named(case.wear.law).per_record is not None:
        return None
    w = case.wall
    return functools.partial(
        table_refusal,
        speed_min=w.table_speed_min,
        speed_max=w.table_speed_max,
        density=case.ball.density,
        name=case.wear.law,
    )
