"""The case: every table and key, defined once (type, units, default, valid range, one-line doc).

A :class:`wear.case.Case` holds tables ``[ball]``, ``[plate]``, ``[impact]``, ``[wear]``, ``[fem]``, ``[output]``,
``[erosion]``, ``[repeat]``, ``[calibration]`` and ``[wall]``; each job reads the tables it needs
(:mod:`wear.case.jobs`). The defaults below are those of the main job, ``impactwear run``: a hard alumina ball
(R 2.5 mm) hitting a Ti-6Al-4V plate at 3 m/s, 30° from the normal, μ 0.3 — about 12 times Thornton's yield speed in
the normal direction, so first yield is far exceeded and the plastic zone reaches the surface — on the FE plate's own
force law (two-way coupling), with the paper's wear law (Eq. 15, α = 1, β = 0.3, K = 1e-11 m^0.7 s^-0.7 Pa^-1). SI
units; angles in degrees from the plate normal.

One module past 400 lines on purpose: the schema is one concept, every key of every table in one place, so that a
key's meaning, units and range are read (and changed) where the others are.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from typing import ClassVar

from contact import Material
from contact.impact import SPEED_MAX
from contact.impact import TANGENTIAL_MODELS as ENGINE_TANGENTIAL_MODELS
from wear.case.schema import Table, key
from wear.law import WearLaw
from wear.laws import CUTTING_LAWS, LAWS
from wear.pressure import PRESSURE_SOURCES
from wear.slip import SPEED_MODELS

__all__ = [
    "BallSpec",
    "PlateSpec",
    "ImpactSpec",
    "WearSpec",
    "FemSpec",
    "OutputSpec",
    "ErosionSpec",
    "RepeatSpec",
    "CalibrationSpec",
    "WallSpec",
    "COUPLINGS",
    "FEM_MODELS",
    "NORMAL_MODELS",
    "TANGENTIAL_MODELS",
    "SCHEMES",
]

#: The impact–plate couplings: the impact on the FE plate's own force law, the FE plate along the closed-form
#: impact, or no FE plate.
COUPLINGS = ("two-way", "one-way", "none")
#: The FE plate models: the axisymmetric (r, z) frictionless plate, or the 3-D half plate with Coulomb friction.
FEM_MODELS = ("axisymmetric", "3d")
NORMAL_MODELS = ("hertz", "thornton")
#: The impact engine's tangential laws (:data:`contact.impact.TANGENTIAL_MODELS`).
TANGENTIAL_MODELS = tuple(ENGINE_TANGENTIAL_MODELS)
SCHEMES = ("verlet", "paper")

#: Particle mass concentration of a stream whose case gives neither concentration nor mass flux (kg/m³).
DEFAULT_CONCENTRATION = 0.464

_E = dict(low=1e5, high=1e13, allow_inf=True)
_NU = dict(low=0.0, high=0.5, high_open=True)
_DENSITY = dict(low=0.0, low_open=True, high=1e5)
_YIELD = dict(low=1e3, high=1e11, optional=True, inf_is_absent=True, absent="never yields")


class _MaterialTable(Table):
    """A table that describes a material (E, nu, density, yield_strength, name)."""

    def check(self) -> None:
        self.material()

    def material(self) -> Material:
        """The table's :class:`contact.Material` (errors name ``table.key``)."""
        try:
            return Material(self.E, self.nu, self.density, self.yield_strength, self.name)  # type: ignore[attr-defined]
        except ValueError as exc:
            raise ValueError(f"{self.table}.{exc}") from None


@dataclass(frozen=True)
class BallSpec(_MaterialTable):
    """The ball (or particle): ``radius`` (m), ``E`` (Pa; inf = rigid), ``nu``, ``density`` (kg/m³),
    ``yield_strength`` (Pa; None = never yields), ``name`` (a label)."""

    table: ClassVar[str] = "ball"
    radius: float = key(float, 2.5e-3, "ball radius", "m", low=0.0, low_open=True, high=10.0)
    E: float = key(float, 3.8e11, "Young's modulus (inf: rigid)", "Pa", **_E)
    nu: float = key(float, 0.23, "Poisson's ratio", **_NU)
    density: float = key(float, 3950.0, "density", "kg/m^3", **_DENSITY)
    yield_strength: float | None = key(float, None, "yield strength", "Pa", **_YIELD)
    name: str = key(str, "alumina", "label of the ball material")


@dataclass(frozen=True)
class PlateSpec(_MaterialTable):
    """The plate: ``rigid`` (E, nu, density ignored), ``E`` (Pa), ``nu``, ``density`` (kg/m³), ``yield_strength``
    (Pa; None = never yields), ``name`` (a label)."""

    table: ClassVar[str] = "plate"
    rigid: bool = key(bool, False, "rigid plate (E, nu, density ignored)")
    E: float = key(float, 1.14e11, "Young's modulus", "Pa", **_E)
    nu: float = key(float, 0.34, "Poisson's ratio", **_NU)
    density: float = key(float, 4430.0, "density", "kg/m^3", **_DENSITY)
    yield_strength: float | None = key(float, 8.8e8, "yield strength", "Pa", **_YIELD)
    hardness: float | None = key(
        float,
        None,
        "hardness: plastic flow pressure (Finnie) and Vickers hardness (Oka)",
        "Pa",
        low=1e6,
        high=1e11,
        optional=True,
        absent="3 x yield strength",
    )
    name: str = key(str, "Ti-6Al-4V", "label of the plate material")

    def material(self) -> Material:
        """The plate's :class:`contact.Material` (``Material.rigid`` if ``rigid``)."""
        return Material.rigid(name=self.name) if self.rigid else super().material()


@dataclass(frozen=True)
class ImpactSpec(Table):
    """The impact (or the stream's particles): ``speed`` (m/s), ``angle`` (deg from the normal), ``friction`` μ,
    ``restitution`` (Hertz dashpot), ``normal_model`` (the impact model without FE coupling, and the first estimate
    of a coupled run), ``tangential_model``, ``limiting_pressure`` (Pa), ``scheme``, ``time_step`` (s)."""

    table: ClassVar[str] = "impact"
    speed: float = key(float, 3.0, "impact speed", "m/s", low=0.0, low_open=True, high=SPEED_MAX)
    angle: float = key(float, 30.0, "impact angle from the plate normal", "deg", low=0.0, high=90.0, high_open=True)
    friction: float = key(float, 0.3, "Coulomb friction coefficient", low=0.0, high=10.0)
    restitution: float = key(
        float, 1.0, "normal restitution setting the Hertz dashpot", low=0.0, low_open=True, high=1.0
    )
    normal_model: str = key(
        str, "thornton", "normal force law (without FE coupling; else the first estimate)", choices=NORMAL_MODELS
    )
    tangential_model: str = key(str, "hdd", "tangential force law", choices=TANGENTIAL_MODELS)
    limiting_pressure: float | None = key(
        float,
        None,
        "Thornton limiting pressure",
        "Pa",
        low=1e3,
        high=1e12,
        optional=True,
        absent="C(nu)*Y of the body that yields first",
    )
    scheme: str = key(str, "verlet", "time integration scheme", choices=SCHEMES)
    time_step: float | None = key(
        float, None, "time step", "s", low=0.0, low_open=True, optional=True, absent="Hertz contact time / 2000"
    )


@dataclass(frozen=True)
class WearSpec(Table):
    """The wear law (:mod:`wear.laws`): ``law`` by name; the local law (errata equation 15, dw/dt = K p^α v^β): ``K``
    (m^(1−β) s^(β−1) Pa^(−α)), ``alpha``, ``beta``, the ``pressure`` source along the impact, the sliding ``speed``
    model, ``points_across`` grid points across the largest contact diameter; Finnie's cutting: ``cutting_fraction``,
    ``force_ratio``, ``depth_ratio`` (and the plate's ``hardness``); Bitter's deformation wear:
    ``deformation_factor`` ε (J/m³); ``combined``: the ``cutting`` law plus deformation; the correlations: ``oka_e90``,
    ``oka_k2``, ``dnv_K``, ``dnv_n``."""

    table: ClassVar[str] = "wear"
    law: str = key(str, "local", "wear law (wear.laws)", choices=tuple(LAWS))
    K: float = key(float, 1e-11, "wear coefficient of Eq. 15", "m^(1-beta) s^(beta-1) Pa^(-alpha)", low=0.0, high=1e-3)
    alpha: float = key(float, 1.0, "pressure exponent of Eq. 15", low=0.0, high=4.0)
    beta: float = key(float, 0.3, "sliding-speed exponent of Eq. 15", low=0.0, high=4.0)
    pressure: str = key(str, "fe", "contact pressure source", choices=PRESSURE_SOURCES)
    speed: str = key(
        str, "local", "sliding speed: the FE surface's local slip, or the contact point's", choices=SPEED_MODELS
    )
    points_across: int = key(int, 64, "wear grid points across the largest contact diameter", low=40, high=2000)
    cutting: str = key(str, "local", "the cutting law of the combined law", choices=CUTTING_LAWS)
    cutting_fraction: float = key(
        float, 0.5, "Finnie's fraction of particles cutting ideally, c", low=0.0, low_open=True, high=10.0
    )
    force_ratio: float = key(
        float, 2.0, "Finnie's ratio of vertical to horizontal force on the particle, K", low=0.1, high=20.0
    )
    depth_ratio: float = key(float, 2.0, "Finnie's ratio of contact depth to cut depth, psi", low=0.1, high=20.0)
    deformation_factor: float | None = key(
        float,
        None,
        "Bitter's deformation wear factor epsilon",
        "J/m^3",
        low=1e3,
        high=1e15,
        optional=True,
        absent="none: the deformation and combined laws need it",
    )
    oka_e90: float | None = key(
        float,
        None,
        "Oka's erosion ratio at normal incidence, 104 m/s, 326 um",
        "kg/kg",
        low=0.0,
        low_open=True,
        high=1.0,
        optional=True,
        absent="65e-9 m^3/kg x (Hv/GPa)^-0.12 x plate density (Oka & Yoshida 2005)",
    )
    oka_k2: float | None = key(
        float, None, "Oka's speed exponent", low=0.5, high=5.0, optional=True, absent="2.3 Hv^0.038"
    )
    dnv_K: float = key(
        float, 2e-9, "DNV-RP-O501 material constant K", "(kg/kg) (m/s)^-n", low=0.0, low_open=True, high=1.0
    )
    dnv_n: float = key(float, 2.6, "DNV-RP-O501 speed exponent n", low=0.5, high=5.0)

    def check(self) -> None:
        self.wear_law()
        if self.speed == "local" and self.pressure != "fe":
            raise ValueError(
                f"wear.speed='local' is the FE plate surface's slip, read with the plate's pressure: it needs "
                f"wear.pressure='fe' (got {self.pressure!r}); with a closed-form pressure set wear.speed='sliding' "
                "(the impact's contact-point slip, the paper's) or 'kinematic'"
            )

    def check_deformation_factor(self, fitted: bool) -> None:
        """A one-line ``ValueError`` if the law needs Bitter's ε and the case gives none, unless a calibration
        ``fitted`` it (it then starts from the data)."""
        if self.law in ("deformation", "combined") and self.deformation_factor is None and not fitted:
            raise ValueError(
                f"wear.deformation_factor=None: wear.law={self.law!r} needs Bitter's deformation wear "
                "factor epsilon (J/m^3)"
            )

    def wear_law(self) -> WearLaw:
        """The local law's :class:`wear.WearLaw` (Eq. 15) of this table."""
        try:
            return WearLaw(K=self.K, alpha=self.alpha, beta=self.beta)
        except ValueError as exc:
            raise ValueError(f"wear.{exc}") from None


@dataclass(frozen=True)
class FemSpec(Table):
    """The FE plate: ``model`` ("axisymmetric": the (r, z) frictionless plate; "3d": the half block with Coulomb
    friction, coupled after the axisymmetric one), ``coupling`` ("two-way": the impact runs on the FE plate's own
    force law; "one-way": the FE plate follows the impact's overlap; "none"), its ``tolerance`` and
    ``max_iterations``, the FE increments ``load_steps`` and ``unload_steps``, the ``overshoot`` of the single FE
    loading past the estimated maximum overlap, ``mesh_scale`` (multiplies the FE element sizes; > 1 coarser; the
    3-D plate has 8/mesh_scale elements across the contact radius), and the 3-D plate's ``solid_iterations``,
    ``solid_load_steps`` and ``solid_unload_steps``."""

    table: ClassVar[str] = "fem"
    coupling: str = key(str, "two-way", "impact-FE coupling (two-way = the FE normal law)", choices=COUPLINGS)
    tolerance: float = key(float, 0.005, "coupling tolerance on the max overlap change (relative)", low=1e-6, high=0.2)
    max_iterations: int = key(int, 8, "most impact runs of the coupling", low=2, high=50)
    load_steps: int = key(int, 16, "FE increments of the loading", low=2, high=2000)
    unload_steps: int = key(int, 8, "FE increments of the unloading", low=1, high=2000)
    overshoot: float = key(float, 0.1, "FE loading past the estimated max overlap (relative)", low=0.02, high=2.0)
    mesh_scale: float = key(float, 2.0, "FE element size factor (> 1 coarser)", low=0.25, high=8.0)
    model: str = key(
        str,
        "axisymmetric",
        "FE plate: axisymmetric (r, z), or 3d (impactwear run and repeat: half block, "
        "Coulomb friction; its impact runs on the plate's tangential law, mindlin_deresiewicz)",
        choices=FEM_MODELS,
    )
    solid_iterations: int = key(int, 3, "most 3-D plate cycles of the 3-D coupling", low=1, high=20)
    solid_load_steps: int = key(int, 10, "3-D plate increments of the loading", low=2, high=200)
    solid_unload_steps: int = key(int, 6, "3-D plate increments of the unloading", low=1, high=200)


@dataclass(frozen=True)
class OutputSpec(Table):
    """Outputs: ``figures`` (PNG), ``render`` (3-D view), ``plate_mesh`` (a user's meshio plate block to deform
    instead of the generated one; "" = generate), ``block_thickness`` (m) of the generated block."""

    table: ClassVar[str] = "output"
    figures: bool = key(bool, True, "write the PNG figures")
    render: bool = key(bool, True, "write the rendered 3-D view (needs EGL or OSMesa)")
    plate_mesh: str = key(str, "", 'meshio plate block to deform instead of the generated one ("": generate)')
    block_thickness: float = key(
        float, 2e-3, "thickness of the generated plate block", "m", low=0.0, low_open=True, high=1.0
    )

    def check(self) -> None:
        if self.plate_mesh and not os.path.isfile(self.plate_mesh):
            raise ValueError(f"output.plate_mesh={self.plate_mesh!r} is not a file: give a meshio-readable plate mesh")


@dataclass(frozen=True)
class ErosionSpec(Table):
    """A particle stream eroding a periodic plate patch (the particle is ``[ball]``, its speed, angle and contact
    models ``[impact]``, the wear law ``[wear]``): concentration or mass flux, exposure, azimuth, the patch, the
    response table's resolution, the seed and the outputs' sampling."""

    table: ClassVar[str] = "erosion"
    concentration: float | None = key(
        float,
        None,
        "particle mass concentration of the stream (or give mass_flux)",
        "kg/m^3",
        low=0.0,
        low_open=True,
        optional=True,
        absent=f"{DEFAULT_CONCENTRATION:g} kg/m^3 unless mass_flux is given",
    )
    mass_flux: float | None = key(
        float,
        None,
        "mass flux through a plane normal to the stream (or give concentration)",
        "kg/(m^2 s)",
        low=0.0,
        low_open=True,
        optional=True,
        absent="from concentration",
    )
    exposure_time: float = key(float, 3120.0, "exposure time", "s", low=0.0, low_open=True, high=1e10)
    azimuth: float = key(
        float, 0.0, "stream direction in the patch, from the grid x axis", "deg", low=-360.0, high=360.0
    )
    # 2048 at most: the default erode case on 2048² nodes runs in 2.4 min (1.4 GB, 1.4 GB of outputs); on 4096² it
    # did not finish in 25 min (4.9 GB, ~6 GB of outputs written), on 8192² it reached 4.7 GB and did not finish
    grid: int = key(int, 512, "grid nodes per side of the patch", low=16, high=2048)
    patch_size: float | None = key(
        float,
        None,
        "side of the periodic patch",
        "m",
        low=0.0,
        low_open=True,
        high=10.0,
        optional=True,
        absent="grid x contact radius / 4",
    )
    seed: int = key(int, 0, "random seed of the impact points", low=0, high=2**63 - 1)
    frames: int = key(int, 10, "surfaces saved in the .pvd series", low=1, high=1000)
    samples: int = key(int, 100, "rows of the mass-loss time series", low=1, high=100000)
    angle_margin: float = key(
        float, 20.0, "response table: local angles covered around the stream angle", "deg", low=0.0, high=45.0
    )
    angle_step: float = key(float, 2.5, "response table: local angle step", "deg", low=0.1, high=15.0)
    table_speeds: int = key(int, 5, "response table: number of normal speeds", low=2, high=50)
    points_per_length: int = key(int, 12, "response table: footprint points per contact radius", low=4, high=64)

    def check(self) -> None:
        if self.concentration is not None and self.mass_flux is not None:
            raise ValueError(
                f"erosion.concentration={self.concentration:g} and erosion.mass_flux={self.mass_flux:g} "
                "are both given: the stream's supply is one of them (kg/m^3 or kg/(m^2 s))"
            )

    def supply(self) -> dict[str, float]:
        """The stream's supply: ``{"mass_flux": q}`` (kg m⁻² s⁻¹) or ``{"concentration": c}`` (kg/m³)."""
        if self.mass_flux is not None:
            return {"mass_flux": self.mass_flux}
        return {"concentration": DEFAULT_CONCENTRATION if self.concentration is None else self.concentration}


@dataclass(frozen=True)
class RepeatSpec(Table):
    """Repeated impacts at one site (:mod:`wear.chain.repeated_impacts`): ``impacts``; ``geometry_update`` (the wear
    moves the FE surface nodes); ``shakedown_tolerance`` (an impact whose largest plastic strain increment is below this
    × Y/E is shaken down); ``surface_fraction`` (a cycle-jump block moves the surface by at most this × the last
    computed impact's approach, its max overlap from first contact); ``max_plastic_impacts`` (computed one by one before
    blocks go on without shakedown); ``save_every`` (FE mesh of every k-th computed impact; 0 = none);
    ``wear_smoothing`` (width of the Gaussian filter of the wear profile the FE surface takes, × the contact radius;
    0 = off, which lets a node-scale ripple grow); ``elastic_after_shakedown`` (after a shaken-down impact the next
    one is solved on the plate's elastic response, :func:`fem.elastic_reload`, unless its elastic field yields)."""

    table: ClassVar[str] = "repeat"
    impacts: int = key(int, 100, "number of impacts at the site", low=1, high=1e9)
    geometry_update: bool = key(bool, True, "the wear of each impact moves the FE surface nodes")
    shakedown_tolerance: float = key(
        float,
        1e-3,
        "largest plastic strain increment of a shaken-down impact, over Y/E",
        low=0.0,
        low_open=True,
        high=1.0,
    )
    surface_fraction: float = key(
        float,
        0.1,
        "surface change per cycle-jump block, fraction of the impact's approach (max overlap from first contact)",
        low=0.0,
        low_open=True,
        high=1.0,
    )
    max_plastic_impacts: int = key(
        int, 20, "impacts computed one by one before blocks go on without shakedown", low=1, high=100000
    )
    save_every: int = key(int, 1, "save the FE mesh of every k-th computed impact (0 = none)", low=0, high=1e9)
    wear_smoothing: float = key(
        float,
        0.1,
        "width of the filter of the wear profile on the FE surface, fraction of the contact radius (0 = off)",
        low=0.0,
        high=1.0,
    )
    elastic_after_shakedown: bool = key(
        bool,
        True,
        "after a shaken-down impact, solve the next on the plate's elastic response unless its elastic field yields",
    )


@dataclass(frozen=True)
class CalibrationSpec(Table):
    """A calibration of the wear law (:mod:`wear.chain.calibrate`): the ``data`` file (CSV of measurements) and the
    ``free`` constants (comma-separated; "" = the law's scale constant)."""

    table: ClassVar[str] = "calibration"
    data: str = key(str, "", "CSV of measured wear: angle_deg, speed_m_s, one measured quantity, optional case keys")
    free: str = key(str, "", 'the constants to fit, comma-separated ("": the law\'s scale constant)')

    def free_constants(self) -> tuple[str, ...]:
        """The free constants' names."""
        return tuple(n.strip() for n in self.free.split(",") if n.strip())

    def fits(self, name: str) -> bool:
        """Whether this calibration (a ``data`` file given) fits the constant ``name`` of a law that has it: named
        in ``free``, or ``free`` empty and ``name`` a law's scale (Bitter's ε is the deformation laws')."""
        free = self.free_constants()
        return bool(self.data) and (name in free or (not free and name == "deformation_factor"))


#: One Julian year (s): the service time of the worn wall unless given, and the year of the mm/year rates.
YEAR = 365.25 * 86400.0


@dataclass(frozen=True)
class WallSpec(Table):
    """Erosion of a component's wall from CFD or DEM impact records (:mod:`wear.wall`; the particles are the
    records', the wall material ``[plate]``, the wear law ``[wear]``): the ``records`` and the wall's ``surface``
    (paths; the command's arguments win), the wall ``thickness`` (m; a per-face field of the wall file replaces it),
    the ``exposure`` (s) the records stand for, the ``service_time`` (s) of the worn wall, the real flow's
    ``sand_rate`` against the ``cfd_sand_rate`` its run injected (kg/s: every volume is scaled by their ratio), the
    ``loss_budget`` (m) the wall may lose in the service time (for the allowable sand rate), and the response table
    of an FE-informed law over speed and angle (``table_*``; the closed forms read none of them)."""

    table: ClassVar[str] = "wall"
    records: str | None = key(
        str,
        None,
        "impact records: a file or folder (OpenFOAM, Fluent, CSV, Parquet), relative to the current folder",
        optional=True,
        absent="the command's RECORDS (a sweep needs it)",
    )
    surface: str | None = key(
        str,
        None,
        "the wall: a surface file, a folder of them or an OpenFOAM case, relative to the current folder",
        optional=True,
        absent="the command's WALL (a sweep needs it)",
    )
    thickness: float | None = key(
        float,
        None,
        "wall thickness for the remaining life",
        "m",
        low=0.0,
        low_open=True,
        high=10.0,
        optional=True,
        absent="no remaining life unless the wall file has a thickness field",
    )
    exposure: float | None = key(
        float,
        None,
        "time the records stand for, turning eroded volumes into rates",
        "s",
        low=0.0,
        low_open=True,
        high=1e10,
        optional=True,
        absent="the records' time span, last minus first hit time",
    )
    service_time: float = key(
        float,
        YEAR,
        "service time after which the worn wall is written (default: a year of 365.25 days)",
        "s",
        low=0.0,
        low_open=True,
        high=1e11,
    )
    sand_rate: float | None = key(
        float,
        None,
        "particle mass rate of the real flow; volumes scale by sand_rate / cfd_sand_rate",
        "kg/s",
        low=0.0,
        low_open=True,
        high=1e6,
        optional=True,
        absent="no scaling: the records' own rate",
    )
    cfd_sand_rate: float | None = key(
        float,
        None,
        "particle mass rate the CFD or DEM run injected (with sand_rate)",
        "kg/s",
        low=0.0,
        low_open=True,
        high=1e6,
        optional=True,
        absent="none: sand_rate needs it",
    )
    loss_budget: float | None = key(
        float,
        None,
        "thickness the wall may lose in the service time, for the allowable sand rate",
        "m",
        low=0.0,
        low_open=True,
        high=10.0,
        optional=True,
        absent="no allowable sand rate",
    )
    table_speed_min: float = key(
        float,
        0.1,
        "response table (FE-informed laws): lowest impact speed",
        "m/s",
        low=0.0,
        low_open=True,
        high=SPEED_MAX,
    )
    table_speed_max: float = key(
        float,
        100.0,
        "response table (FE-informed laws): highest impact speed",
        "m/s",
        low=0.0,
        low_open=True,
        high=SPEED_MAX,
    )
    # at most 50 x 40 = 2000 impacts, wear.erosion.table.MAX_TABLE_ENTRIES
    table_speeds: int = key(int, 24, "response table (FE-informed laws): number of normal speeds", low=2, high=50)
    table_angles: int = key(
        int, 37, "response table (FE-informed laws): number of angles, 0 to table_angle_max", low=2, high=40
    )
    table_angle_max: float = key(
        float,
        89.0,
        "response table (FE-informed laws): last angle; the volume goes linearly to 0 at 90 deg",
        "deg",
        low=45.0,
        high=89.0,
    )

    def check(self) -> None:
        if (self.sand_rate is None) != (self.cfd_sand_rate is None):
            given, missing = (
                ("sand_rate", "cfd_sand_rate") if self.cfd_sand_rate is None else ("cfd_sand_rate", "sand_rate")
            )
            raise ValueError(
                f"wall.{given}={getattr(self, given):g} without wall.{missing}: the volumes scale by "
                "sand_rate / cfd_sand_rate (kg/s), give both or neither"
            )
        if self.table_speed_min >= self.table_speed_max:
            raise ValueError(
                f"wall.table_speed_min={self.table_speed_min:g} is not below wall.table_speed_max="
                f"{self.table_speed_max:g} m/s"
            )
        self._check_table_reach()

    def table_normal_speed_min(self) -> float:
        """The response table's lowest normal speed (m/s): the lowest speed at its last angle."""
        return self.table_speed_min * math.cos(math.radians(self.table_angle_max))

    def _check_table_reach(self) -> None:
        r"""Refuse a response table whose impacts would exceed the engine's :data:`contact.impact.SPEED_MAX`. Its
        normal speeds run geometrically, a ratio :math:`r = (V_{max} / (V_{min}\cos\theta_{top}))^{1/(n-1)}`
        apart (:func:`wear.wall.laws.table_axes_of`); a record of speed up to :math:`V_{max}` at angle θ is
        interpolated between the nodes around :math:`V\cos\theta`, the upper one up to :math:`r V_{max}\cos\theta`
        in normal speed, :math:`r V_{max}` in speed."""
        low = self.table_normal_speed_min()
        span = math.log(self.table_speed_max / low)
        step = span / (self.table_speeds - 1)
        if self.table_speed_max * math.exp(step) * (1.0 + 1e-9) <= SPEED_MAX:
            return
        n = self.table_speeds
        fits = math.exp(((n - 1) * math.log(SPEED_MAX) + math.log(low)) / n) / (1.0 + 1e-9)
        fewest = (
            f"wall.table_speeds >= {math.ceil(span / math.log(SPEED_MAX / self.table_speed_max) + 1.0)} or "
            if self.table_speed_max < SPEED_MAX
            else ""
        )
        raise ValueError(
            f"wall.table_speeds={n} is too coarse for wall.table_speed_min={self.table_speed_min:g} to "
            f"wall.table_speed_max={self.table_speed_max:g} m/s: its normal speeds lie x{math.exp(step):.4g} apart, "
            f"so a record near {self.table_speed_max:g} m/s is interpolated from impacts at up to "
            f"{self.table_speed_max * math.exp(step):.4g} m/s, above the impact's {SPEED_MAX:g} m/s; give "
            f"{fewest}wall.table_speed_max <= {fits:.4g} m/s"
        )

    def rate_scale(self) -> float:
        """The factor on every eroded volume: sand_rate / cfd_sand_rate, or 1."""
        return 1.0 if self.sand_rate is None else self.sand_rate / self.cfd_sand_rate


#: The case tables, in order: TOML name → table class.
TABLES: dict[str, type[Table]] = {
    t.table: t
    for t in (
        BallSpec,
        PlateSpec,
        ImpactSpec,
        WearSpec,
        FemSpec,
        OutputSpec,
        ErosionSpec,
        RepeatSpec,
        CalibrationSpec,
        WallSpec,
    )
}
