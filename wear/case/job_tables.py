"""The tables of the jobs beyond one impact: a particle stream eroding a plate patch (``[erosion]``), repeated
impacts at one site (``[repeat]``), a calibration of the wear law (``[calibration]``) and the erosion of a
component's wall from CFD or DEM impact records (``[wall]``). SI units; angles in degrees.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

from contact.impact import SPEED_MAX
from wear.case.schema import Table, key

__all__ = ["ErosionSpec", "RepeatSpec", "CalibrationSpec", "WallSpec"]

#: Particle mass concentration of a stream whose case gives neither concentration nor mass flux (kg/m³).
DEFAULT_CONCENTRATION = 0.464


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
        apart (:func:`wear.wall.per_record.table_axes_of`); a record of speed up to :math:`V_{max}` at angle θ is
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
